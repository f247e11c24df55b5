// Scaling of the dynamics core on planar revolute pendulum chains of N links
// (bench/model_generators.hpp): one residual, one sparse Newton matrix (structural pattern,
// element-local assembly, with its run-time pattern check; and by compressed forward AD of the
// whole residual), one KLU factorisation and solve, and the BDF and HHT step loops; the
// corrector's solve and the factorisation alone by KLU variant (ordering, BTF, positions
// eliminated first: BM_Solve, BM_Factor, with the L+U entry counts); the dense
// matrix and LU beside them for small N, which is where the
// integrator's sparse threshold (BdfIntegrator::kSparseThreshold) comes from. Figures only;
// nothing is asserted. Run: build/bench/jacobian_bench (OPENMSS_BUILD_BENCH=ON).

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "analysis/multibody_dae.hpp"
#include "language/reader.hpp"
#include "mechanics/constraint_rows.hpp"
#include "mechanics/index_one_dynamics.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"
#include "model_generators.hpp"
#include "solvers/bdf_integrator.hpp"
#include "solvers/dense_linear_solver.hpp"
#include "solvers/hht_integrator.hpp"
#include "solvers/klu_linear_solver.hpp"
#include "solvers/nonzero_pattern.hpp"

namespace {

using namespace openmss;

// One assembled chain per size, built once for all benchmarks (set-up is not timed).
struct Chain {
  model::Model model;
  std::unique_ptr<mechanics::MultibodySystem> system;
  std::unique_ptr<analysis::MultibodyDae> dae;
  Eigen::VectorXd y, yp;
  double cj = 1e3;
};

// bushing: the chain of free blocks joined by BUSHING and SPRINGDAMPER (bench::bushingChainAdm)
// instead of the revolute chain.
Chain& chain(int links, bool bushing = false) {
  static std::map<std::pair<int, bool>, std::unique_ptr<Chain>> chains;
  auto& c = chains[{links, bushing}];
  if (c) return *c;
  c = std::make_unique<Chain>();
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(
      bushing ? bench::bushingChainAdm(links) : bench::planarPendulumChainAdm(links), "chain.adm",
      ds, d);
  model::buildModel(ds, c->model, d);
  c->system = std::make_unique<mechanics::MultibodySystem>(c->model);
  c->y = c->system->initialState();
  mechanics::removeRedundantConstraints(*c->system, c->y);
  mechanics::assemblePositions(*c->system, 0.0, c->y, 1e-12, 25);
  mechanics::solveVelocities(*c->system, 0.0, c->y);
  mechanics::solveAccelerations(*c->system, 0.0, c->y, c->yp);
  c->dae = std::make_unique<analysis::MultibodyDae>(*c->system);
  return *c;
}

void count(benchmark::State& state, const Chain& c) {
  state.counters["unknowns"] = static_cast<double>(c.y.size());
}

// The integrator's row and unknown scaling, applied in place (as BdfIntegrator::refresh does).
void scale(const Chain& c, Eigen::SparseMatrix<double>& a) {
  for (int col = 0; col < a.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator e(a, col); e; ++e)
      e.valueRef() *= std::pow(c.cj, c.dae->rowScaleExponent(static_cast<int>(e.row()))) *
                      std::pow(c.cj, c.dae->unknownScaleExponent(col));
}

void BM_Residual(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  Eigen::VectorXd g(c.y.size());
  for (auto _ : state) {
    c.system->residual(0.0, c.y.data(), c.yp.data(), g.data());
    benchmark::DoNotOptimize(g.data());
  }
  count(state, c);
}
BENCHMARK(BM_Residual)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

void BM_SparseNewtonMatrix(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  Eigen::SparseMatrix<double> jac = *c.dae->pattern();
  for (auto _ : state) {
    c.dae->newtonMatrixSparse(0.0, c.y, c.yp, c.cj, jac);
    benchmark::DoNotOptimize(jac.valuePtr());
  }
  count(state, c);
  state.counters["colours"] = c.dae->jacobianPattern().colours();
  state.counters["nonzeros"] = static_cast<double>(jac.nonZeros());
}
BENCHMARK(BM_SparseNewtonMatrix)->Arg(1)->Arg(3)->Arg(5)->Arg(10)->Arg(100)->Arg(1000)
    ->Unit(benchmark::kMicrosecond);

// The same matrix by compressed forward AD of the whole residual (one dual pass per colour),
// the path before the element-local assembly and still the fallback for dense rows; no guard.
void BM_ColouredNewtonMatrix(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  const mechanics::JacobianPattern& pattern = c.dae->jacobianPattern();
  Eigen::SparseMatrix<double> jac = pattern.matrix();
  mechanics::SparseJacobianWork work;
  work.elementLocal = false;
  for (auto _ : state) {
    c.system->newtonMatrixSparse(0.0, c.y, c.yp, c.cj, pattern, jac, work);
    benchmark::DoNotOptimize(jac.valuePtr());
  }
  count(state, c);
}
BENCHMARK(BM_ColouredNewtonMatrix)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

// The force elements' entries on the bushing chain (N blocks, a BUSHING and a translational
// SPRINGDAMPER between neighbours, no constraints), the whole sparse Newton matrix without the
// run-time guard: range(1) = 0 element by element (mechanics/local_newton_forces.cpp), 1 the
// force elements on the element-local matrix's coloured passes (the path before), 2 the whole
// residual coloured.
void BM_ForceElementNewtonMatrix(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)), true);
  const mechanics::JacobianPattern& pattern = c.dae->jacobianPattern();
  Eigen::SparseMatrix<double> jac = pattern.matrix();
  mechanics::SparseJacobianWork work;
  work.forceElementsLocal = state.range(1) == 0;
  work.elementLocal = state.range(1) != 2;
  for (auto _ : state) {
    c.system->newtonMatrixSparse(0.0, c.y, c.yp, c.cj, pattern, jac, work);
    benchmark::DoNotOptimize(jac.valuePtr());
  }
  count(state, c);
  state.counters["colours"] = pattern.colours();
}
BENCHMARK(BM_ForceElementNewtonMatrix)
    ->ArgsProduct({{100, 1000}, {0, 1, 2}})
    ->Unit(benchmark::kMicrosecond);

void BM_DenseNewtonMatrix(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  Eigen::MatrixXd jac;
  for (auto _ : state) {
    c.system->newtonMatrix(0.0, c.y, c.yp, c.cj, jac);
    benchmark::DoNotOptimize(jac.data());
  }
  count(state, c);
}
BENCHMARK(BM_DenseNewtonMatrix)->Arg(1)->Arg(3)->Arg(5)->Arg(10)->Unit(benchmark::kMicrosecond);

void BM_KluFactorSolve(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  Eigen::SparseMatrix<double> jac = *c.dae->pattern();
  c.dae->newtonMatrixSparse(0.0, c.y, c.yp, c.cj, jac);
  scale(c, jac);
  solvers::KluLinearSolver klu;
  klu.analyze(jac);
  Eigen::VectorXd x(c.y.size());
  for (auto _ : state) {
    klu.factor(jac);
    x.setOnes();
    klu.solve(x);
    benchmark::DoNotOptimize(x.data());
  }
  count(state, c);
}
BENCHMARK(BM_KluFactorSolve)->Arg(1)->Arg(3)->Arg(5)->Arg(10)->Arg(100)->Arg(1000)
    ->Unit(benchmark::kMicrosecond);

// The corrector's linear solve, one per iteration (several per step; a factorisation only every
// ten steps or so), by KLU's choices: range(1) = 0 the default (BTF first, its maximum
// transversal limited to 30 entries' work per entry, then AMD), 1 COLAMD, 2 without BTF, 3 BTF
// without the work limit (the default before 2026-11-29). Counters: unknowns of the
// factorised matrix, entries of its L and U. Eliminating the positions before KLU was measured as
// well and not kept (docs/theory.md §9a).
solvers::KluLinearSolver::Options variantOptions(int variant) {
  solvers::KluLinearSolver::Options o;
  if (variant == 1) o.ordering = 1;
  if (variant == 2) o.btf = false;
  if (variant == 3) o.maxWork = 0.0;
  return o;
}

std::unique_ptr<solvers::LinearSolver> factorisedVariant(int variant,
                                                         const Eigen::SparseMatrix<double>& jac,
                                                         benchmark::State& state) {
  auto klu = std::make_unique<solvers::KluLinearSolver>();
  klu->setOptions(variantOptions(variant));
  klu->factor(jac);
  state.counters["factored_unknowns"] = static_cast<double>(jac.rows());
  state.counters["LU_nonzeros"] = static_cast<double>(klu->factorNonZeros());
  return klu;
}

Eigen::SparseMatrix<double> scaledMatrix(Chain& c) {
  Eigen::SparseMatrix<double> jac = *c.dae->pattern();
  c.dae->newtonMatrixSparse(0.0, c.y, c.yp, c.cj, jac);
  scale(c, jac);
  return jac;
}

void BM_Solve(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  const Eigen::SparseMatrix<double> jac = scaledMatrix(c);
  auto solver = factorisedVariant(static_cast<int>(state.range(1)), jac, state);
  Eigen::VectorXd x(c.y.size());
  for (auto _ : state) {
    x.setOnes();
    solver->solve(x);
    benchmark::DoNotOptimize(x.data());
  }
  count(state, c);
}
BENCHMARK(BM_Solve)->ArgsProduct({{10, 100, 1000}, {0, 1, 2}})
    ->Unit(benchmark::kMicrosecond);

void BM_Factor(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  const Eigen::SparseMatrix<double> jac = scaledMatrix(c);
  auto solver = factorisedVariant(static_cast<int>(state.range(1)), jac, state);
  for (auto _ : state) benchmark::DoNotOptimize(solver->factor(jac));
  count(state, c);
}
BENCHMARK(BM_Factor)->ArgsProduct({{10, 100, 1000}, {0}})->Unit(benchmark::kMicrosecond);

// The symbolic analysis of a new pattern (the integrator takes a few per run) by the variants
// above: without its work limit BTF's maximum transversal grows like N^2 on the planar chains'
// Newton matrices (docs/performance.md, "KLU's block triangular form, bounded").
void BM_Analyze(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  // The pattern the integrator analyses: the exact zeros of the planar chain left out.
  solvers::NonzeroPattern nonzero;
  const Eigen::SparseMatrix<double> jac = nonzero.select(scaledMatrix(c));
  solvers::KluLinearSolver klu;
  klu.setOptions(variantOptions(static_cast<int>(state.range(1))));
  for (auto _ : state) klu.analyze(jac);
  count(state, c);
}
BENCHMARK(BM_Analyze)->ArgsProduct({{100, 1000}, {0, 2, 3}})->Unit(benchmark::kMillisecond);

void BM_DenseLuFactorSolve(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  Eigen::SparseMatrix<double> jac = *c.dae->pattern();
  c.dae->newtonMatrixSparse(0.0, c.y, c.yp, c.cj, jac);
  scale(c, jac);
  const Eigen::MatrixXd dense(jac);
  solvers::DenseLinearSolver lu;
  lu.analyze(jac);
  Eigen::VectorXd x(c.y.size());
  for (auto _ : state) {
    lu.factor(dense);
    x.setOnes();
    lu.solve(x);
    benchmark::DoNotOptimize(x.data());
  }
  count(state, c);
}
BENCHMARK(BM_DenseLuFactorSolve)->Arg(1)->Arg(3)->Arg(5)->Arg(10)->Unit(benchmark::kMicrosecond);

// The BDF step loop over 0.2 s at ERROR 1e-6, HMAX 1e-3 (set-up excluded): time per step.
void BM_StepLoop(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  long steps = 0;
  const char* solver = "";
  for (auto _ : state) {
    analysis::MultibodyDae dae(*c.system);
    solvers::MultistepSettings s;
    s.error = 1e-6;
    s.hmax = 1e-3;
    s.hinit = 1e-4;
    solvers::BdfIntegrator bdf(dae, s);
    bdf.start(0.0, c.y, c.yp);
    bdf.advanceTo(0.2);
    steps = bdf.statistics().steps;
    solver = bdf.linearSolverName();
  }
  count(state, c);
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["s_per_step"] = benchmark::Counter(
      static_cast<double>(steps) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(solver);
}
BENCHMARK(BM_StepLoop)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)->Iterations(1);

// The HHT step loop over 0.2 s at ERROR 1e-6, HMAX 1e-3, as BM_StepLoop: since issue 21 HHT
// solves problems of BdfIntegrator::kSparseThreshold unknowns and more with the sparse Newton
// matrix and KLU (the label names the solver; the 5-link chain, 95 unknowns, is still dense).
void BM_HhtStepLoop(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  long steps = 0;
  const char* solver = "";
  for (auto _ : state) {
    analysis::MultibodyDae dae(*c.system);
    solvers::HhtSettings s = solvers::HhtSettings::hht(-0.3);
    s.error = 1e-6;
    s.hmax = 1e-3;
    s.hinit = 1e-4;
    solvers::HhtIntegrator hht(dae, s);
    hht.start(0.0, c.y, c.yp);
    hht.advanceTo(0.2);
    steps = hht.statistics().steps;
    solver = hht.linearSolverName();
  }
  count(state, c);
  state.counters["steps"] = static_cast<double>(steps);
  state.counters["s_per_step"] = benchmark::Counter(
      static_cast<double>(steps) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(solver);
}
BENCHMARK(BM_HhtStepLoop)->Arg(5)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// ConstraintRows (mechanics/constraint_rows.hpp): the rows of C and gamma of every equation in
// one pass (evaluate), and Phi with nu (values), as the index-1 dynamics needs them at each
// evaluation of an explicit integrator.
void BM_ConstraintRows(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  std::vector<int> rows;
  for (int k = 0; k < c.system->constraints().size(); ++k)
    if (c.system->constraints().equations()[static_cast<size_t>(k)].active) rows.push_back(k);
  const mechanics::ConstraintRows cr(*c.system, rows);
  std::vector<double> values(cr.columns().size()), gamma(rows.size()), phi(rows.size()),
      nu(rows.size());
  // 0: C and gamma; 1: Phi and nu; 2: C alone; 3: gamma alone (as projectAndEvaluate calls it).
  const auto mode = state.range(1);
  double* valuesOut = mode == 3 ? nullptr : values.data();
  double* gammaOut = mode == 2 ? nullptr : gamma.data();
  for (auto _ : state) {
    if (mode == 1) cr.values(0.0, c.y.data(), phi.data(), nu.data());
    else cr.evaluate(0.0, c.y.data(), valuesOut, gammaOut);
    benchmark::DoNotOptimize(values.data());
    benchmark::DoNotOptimize(gamma.data());
    benchmark::DoNotOptimize(phi.data());
  }
  count(state, c);
  state.counters["rows"] = static_cast<double>(rows.size());
  const char* labels[] = {"evaluate", "values", "rows only", "gamma only"};
  state.SetLabel(labels[static_cast<size_t>(mode)]);
}
BENCHMARK(BM_ConstraintRows)->ArgsProduct({{10, 100, 1000}, {0, 1, 2, 3}})
    ->Unit(benchmark::kMicrosecond);

// IndexOneDynamics (mechanics/index_one_dynamics.hpp): one evaluation of the index-1 equations
// of motion (C and gamma, Q, S = C M^-1 C^T, its block Cholesky factor, multipliers and
// accelerations), as an explicit integrator needs it at every stage.
void BM_IndexOneEvaluate(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  mechanics::IndexOneDynamics dynamics(*c.system);
  Eigen::VectorXd y = c.y, yp = c.yp;
  for (auto _ : state) {
    benchmark::DoNotOptimize(dynamics.evaluate(0.0, y, yp));
    benchmark::DoNotOptimize(yp.data());
  }
  count(state, c);
}
BENCHMARK(BM_IndexOneEvaluate)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

// The projection after a step: every body moved and turned by ~1e-6 (positions and velocities
// off their manifolds), the positions projected to 1e-10 with the factorisation of an
// evaluation at the unperturbed state (as after the last stage of a step), the velocities with
// S formed at the projected positions (one factorisation); the copy and perturbation are timed
// too (O(N), small).
void BM_IndexOneProject(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  mechanics::IndexOneDynamics dynamics(*c.system);
  Eigen::VectorXd y = c.y, yp = c.yp;
  dynamics.evaluate(0.0, y, yp);
  const mechanics::StateLayout& l = c.system->layout();
  Eigen::VectorXd delta(6 * l.bodies);
  for (Eigen::Index i = 0; i < delta.size(); ++i) delta(i) = 1e-6 * std::sin(1.7 * static_cast<double>(i));
  Eigen::VectorXd moved = c.y;
  mechanics::applyBodyCorrection(l, delta, moved);
  for (int b = 0; b < l.bodies; ++b) moved(l.body(b) + mechanics::StateLayout::kW + 2) += 1e-3;
  const long before = dynamics.factorizations();
  for (auto _ : state) {
    y = moved;
    benchmark::DoNotOptimize(dynamics.project(0.0, y, 1e-10));
    benchmark::DoNotOptimize(y.data());
  }
  count(state, c);
  state.counters["factorizations"] = benchmark::Counter(
      static_cast<double>(dynamics.factorizations() - before), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_IndexOneProject)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

// What an explicit integrator does after each accepted step: project the new state and
// evaluate there (the next step's first stage). Second argument 0: project() then evaluate();
// 1: the fused projectAndEvaluate(), which shares C and S between the two. The state is the
// one of BM_IndexOneProject, the position tolerance MERSON's at ERROR = 1e-4 (1e-8); each
// iteration starts from the factorisation the previous one left (at the projected state).
void BM_IndexOneProjectAndEvaluate(benchmark::State& state) {
  Chain& c = chain(static_cast<int>(state.range(0)));
  const bool fused = state.range(1) == 1;
  mechanics::IndexOneDynamics dynamics(*c.system);
  Eigen::VectorXd y = c.y, yp = c.yp;
  dynamics.evaluate(0.0, y, yp);
  const mechanics::StateLayout& l = c.system->layout();
  Eigen::VectorXd delta(6 * l.bodies);
  for (Eigen::Index i = 0; i < delta.size(); ++i)
    delta(i) = 1e-6 * std::sin(1.7 * static_cast<double>(i));
  Eigen::VectorXd moved = c.y;
  mechanics::applyBodyCorrection(l, delta, moved);
  for (int b = 0; b < l.bodies; ++b) moved(l.body(b) + mechanics::StateLayout::kW + 2) += 1e-3;
  const long before = dynamics.factorizations();
  for (auto _ : state) {
    y = moved;
    if (fused) {
      benchmark::DoNotOptimize(dynamics.projectAndEvaluate(0.0, y, yp, 1e-8));
    } else {
      benchmark::DoNotOptimize(dynamics.project(0.0, y, 1e-8));
      benchmark::DoNotOptimize(dynamics.evaluate(0.0, y, yp));
    }
    benchmark::DoNotOptimize(yp.data());
  }
  count(state, c);
  state.counters["factorizations"] = benchmark::Counter(
      static_cast<double>(dynamics.factorizations() - before), benchmark::Counter::kAvgIterations);
  state.SetLabel(fused ? "projectAndEvaluate" : "project+evaluate");
}
BENCHMARK(BM_IndexOneProjectAndEvaluate)->ArgsProduct({{10, 100, 1000}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
