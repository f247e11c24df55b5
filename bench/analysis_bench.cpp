// Micro-benchmarks of the equations of motion and the integrator on small models: one residual,
// one Newton matrix (exact, forward-mode AD), and a 1 s dynamic run. Figures are printed by
// Google Benchmark; nothing here is asserted.

#include <benchmark/benchmark.h>

#include "analysis/multibody_dae.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"
#include "solvers/bdf_integrator.hpp"

namespace {

using namespace openmss;

// A three-link spatial chain on revolute joints with an SFORCE damper: 3 bodies, 15 equations.
const char* kChain =
    "three-link chain\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\n"
    "MARKER/20, PART=2, QP=0.5,0,0\n"
    "MARKER/21, PART=2, QP=0,0,0, REULER=0,90D,0\n"
    "MARKER/22, PART=2, QP=1,0,0\n"
    "PART/3, MASS=1, CM=30, IP=0.1,0.1,0.1\n"
    "MARKER/30, PART=3, QP=1.5,0,0\n"
    "MARKER/31, PART=3, QP=1,0,0\n"
    "MARKER/32, PART=3, QP=2,0,0\n"
    "PART/4, MASS=1, CM=40, IP=0.1,0.1,0.1\n"
    "MARKER/40, PART=4, QP=2.5,0,0\n"
    "MARKER/41, PART=4, QP=2,0,0\n"
    "MARKER/12, PART=1, QP=0,0,0, REULER=0,90D,0\n"
    "JOINT/1, REVOLUTE, I=21, J=12\n"
    "JOINT/2, SPHERICAL, I=31, J=22\n"
    "JOINT/3, SPHERICAL, I=41, J=32\n"
    "SFORCE/1, I=40, J=10, TRANSLATION, FUNCTION=-0.5*VR(40,10)\n"
    "ACCGRAV/ KGRAV=-9.81\n"
    "END\n";

struct Fixture {
  model::Model model;
  std::unique_ptr<mechanics::MultibodySystem> system;
  Eigen::VectorXd y, yp;
  Fixture() {
    language::Dataset ds;
    Diagnostics d;
    language::readDatasetText(kChain, "chain.adm", ds, d);
    model::buildModel(ds, model, d);
    system = std::make_unique<mechanics::MultibodySystem>(model);
    y = system->initialState();
    mechanics::removeRedundantConstraints(*system, y);
    mechanics::assemblePositions(*system, 0.0, y, 1e-12, 25);
    mechanics::solveVelocities(*system, 0.0, y);
    mechanics::solveAccelerations(*system, 0.0, y, yp);
  }
};

void BM_Residual(benchmark::State& state) {
  Fixture f;
  Eigen::VectorXd g(f.y.size());
  for (auto _ : state) {
    f.system->residual(0.0, f.y.data(), f.yp.data(), g.data());
    benchmark::DoNotOptimize(g.data());
  }
  state.counters["unknowns"] = static_cast<double>(f.y.size());
}
BENCHMARK(BM_Residual);

void BM_NewtonMatrix(benchmark::State& state) {
  Fixture f;
  Eigen::MatrixXd j;
  for (auto _ : state) {
    f.system->newtonMatrix(0.0, f.y, f.yp, 1e3, j);
    benchmark::DoNotOptimize(j.data());
  }
}
BENCHMARK(BM_NewtonMatrix);

void BM_DynamicRunOneSecond(benchmark::State& state) {
  Fixture f;
  long steps = 0;
  for (auto _ : state) {
    analysis::MultibodyDae dae(*f.system);
    solvers::MultistepSettings s;
    s.error = 1e-6;
    s.hmax = 1e-2;
    solvers::BdfIntegrator bdf(dae, s);
    bdf.start(0.0, f.y, f.yp);
    bdf.advanceTo(1.0);
    steps = bdf.statistics().steps;
  }
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(BM_DynamicRunOneSecond)->Unit(benchmark::kMillisecond);

}  // namespace
