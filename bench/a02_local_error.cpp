// openmss-a02-local-error: the BDF's local error estimate against the true local error, step by
// step, on IFToMM A02 (docs/validation.md, "IFToMM A02"; docs/integrators.md, "Local error audit
// on A02"). A measuring tool, not a test: nothing here is asserted.
//
// Usage: openmss-a02-local-error N END METHOD ERROR [STEPS_CSV [HMAX]]
//   METHOD: GSTIFF, WSTIFF, SI2_GSTIFF, SI2_WSTIFF, DSTIFF or MERSON. ERROR as on the INTEGRATOR
//   statement. 400 output steps per 20 s (the benchmark's), so HMAX and HINIT are those of
//   a02_table.py unless HMAX is given. MERSON's estimate column is its own error norm (its
//   ERROR weights), not the BDF's, so its true / estimated ratios compare unlike things; its
//   steps, energy errors and the fan are comparable. DSTIFF's is the norm IDA reports.
//
// The integrator is the one `openmss run` builds (analysis/integrator_factory.hpp) on the data
// set `openmss-generate fourbar N`, stepped to the same output times. After every accepted step
// from (t_n, y_n) to (t_n+1, y_n+1):
//  * phi_n, phi'_n are read from the first rocker (angle of its centre about its pivot);
//  * the exact one-degree-of-freedom motion A phi'' = -g B cos phi through (phi_n, phi'_n) is
//    integrated to t_n+1 (classical RK4, h <= 1e-4 s) and every body's exact position, Euler
//    parameters and velocities are built from it (rockers turn about their pivots, couplers
//    translate with the rocker tops);
//  * the true local error is y_n+1 minus that exact state, weighed as the BDF weighs its
//    estimate: max |e_i| / (ERRORLOCAL (1 + |y_n,i|)) over displacements (r, e), ERRORLOCAL =
//    0.1 ERROR (integrator_factory.cpp, kBdfLocalShare); the velocities' true error likewise
//    with the I3 velocity test's weights 2 h / (ERRORLOCAL (1 + |v_n,i|)). The estimate is the
//    step's errorNorm (solvers/integrator.hpp, StepInfo).
// The global error at END is split exactly over the steps (Lady Windermere's fan): with
// F(T, t, x) the exact flow, x_N - F(T, 0, x_0) = sum_n [F(T, t_n+1, x_n+1) - F(T, t_n, x_n)],
// and each term into its energy part (the step's energy error carried to T) and the rest.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "analysis/integrator_factory.hpp"
#include "analysis/multibody_dae.hpp"
#include "common/vec3.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"
#include "model_generators.hpp"

namespace {

using namespace openmss;
using mechanics::StateLayout;

constexpr double kLocalShare = 0.1;     // integrator_factory.cpp, kBdfLocalShare
constexpr double kVelocitySteps = 2.0;  // bdf_integrator.cpp, kVelocityTestSteps

struct Pendulum {
  double a, b, k;  // A phi'' = -g B cos phi, k = g B / A
  explicit Pendulum(int n) {
    a = (n + 1) / 3.0 + n;
    b = (n + 1) * 0.5 + n;
    k = 9.81 * b / a;
  }
  double energy(double p, double w) const { return 0.5 * a * w * w + 9.81 * b * std::sin(p); }
  // The exact flow from (p, w) over dt (RK4, steps <= hmax).
  void flow(double& p, double& w, double dt, double hmax) const {
    const int n = std::max(1, static_cast<int>(std::ceil(dt / hmax - 1e-9)));
    const double h = dt / n;
    for (int i = 0; i < n; ++i) {
      const double k1p = w, k1w = -k * std::cos(p);
      const double k2p = w + h / 2 * k1w, k2w = -k * std::cos(p + h / 2 * k1p);
      const double k3p = w + h / 2 * k2w, k3w = -k * std::cos(p + h / 2 * k2p);
      const double k4p = w + h * k3w, k4w = -k * std::cos(p + h * k3p);
      p += h / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
      w += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
    }
  }
};

// Every body's exact state for (phi, phi') from its initial state (phi = pi/2).
struct ExactState {
  const StateLayout& layout;
  Eigen::VectorXd y0;
  std::vector<bool> rocker;
  ExactState(const StateLayout& l, const Eigen::VectorXd& y) : layout(l), y0(y) {
    for (int b = 0; b < l.bodies; ++b) rocker.push_back(std::abs(y(l.body(b) + 1) - 0.5) < 1e-9);
  }
  void fill(double p, double w, Eigen::VectorXd& y) const {
    y = y0;
    const double d = p - M_PI / 2;
    const Quat<double> qz{std::cos(d / 2), 0, 0, std::sin(d / 2)};
    for (int b = 0; b < layout.bodies; ++b) {
      const int o = layout.body(b);
      const double x0 = y0(o);  // rocker: pivot x; coupler: CM x at phi = pi/2
      const double arm = rocker[b] ? 0.5 : 1.0;
      y(o) = x0 + arm * std::cos(p);
      y(o + 1) = arm * std::sin(p);
      y(o + 7) = -arm * w * std::sin(p);
      y(o + 8) = arm * w * std::cos(p);
      y(o + 9) = 0.0;
      Quat<double> e0{y0(o + 3), y0(o + 4), y0(o + 5), y0(o + 6)}, e;
      if (rocker[b]) {  // qz * e0 (Hamilton product): the turn about ground z
        e.e0 = qz.e0 * e0.e0 - qz.e3 * e0.e3;
        e.e1 = qz.e0 * e0.e1 - qz.e3 * e0.e2;
        e.e2 = qz.e0 * e0.e2 + qz.e3 * e0.e1;
        e.e3 = qz.e0 * e0.e3 + qz.e3 * e0.e0;
      } else {
        e = e0;
      }
      y(o + 3) = e.e0, y(o + 4) = e.e1, y(o + 5) = e.e2, y(o + 6) = e.e3;
      const M3<double> r = rotationOf(e);
      const double wz = rocker[b] ? w : 0.0;  // body axes: R^T (0, 0, wz)
      for (int j = 0; j < 3; ++j) y(o + 10 + j) = r.c[j].z * wz;
    }
  }
};

struct StepRecord {
  double t, h, hPrevious, phi, rate;  // at the start of the step
  int order;
  double estimate;      // errorNorm of the step (1 = the tolerance)
  double trueNorm;      // true local error, displacements, same weights
  double trueVelocity;  // true velocity error in the I3 velocity test's weights
  double dPhi, dRate;   // step result minus exact through the start, angle and rate
  double dEnergy;       // energy of the result minus energy at the start (J)
};

struct Observer {
  int order = 0;
  double estimate = 0.0;
  long rejected = 0;
  static void onStep(const solvers::StepInfo& info, void* self) {
    auto* me = static_cast<Observer*>(self);
    if (info.event == solvers::StepInfo::Event::Accepted) {
      me->order = info.order;
      me->estimate = info.errorNorm;
    } else if (info.event == solvers::StepInfo::Event::ErrorTestFailed) {
      ++me->rejected;
    }
  }
};

double weighted(const Eigen::VectorXd& e, const Eigen::VectorXd& yRef, const StateLayout& l,
                int from, int to, double scale) {
  double worst = 0.0;
  for (int b = 0; b < l.bodies; ++b)
    for (int i = l.body(b) + from; i < l.body(b) + to; ++i)
      worst = std::max(worst, std::abs(e(i)) * scale / (1.0 + std::abs(yRef(i))));
  return worst;
}

// Ratios true / estimated on the steps the test holds (estimate >= 0.25 of the tolerance: where
// the estimate is small its leading term passes through zero and the ratio says nothing), the
// steps whose true error exceeds 1.5 tolerances, and the signed sums of the local errors.
struct Summary {
  int count = 0, overTolerance = 0, velocityOver = 0;
  std::vector<double> ratios;
  double sumPhi = 0.0, sumEnergy = 0.0, sumAbsEnergy = 0.0;
  void add(const StepRecord& s) {
    ++count;
    if (s.estimate >= 0.25) ratios.push_back(s.trueNorm / s.estimate);
    if (s.trueNorm > 1.5) ++overTolerance;
    sumPhi += s.dPhi;
    sumEnergy += s.dEnergy;
    sumAbsEnergy += std::abs(s.dEnergy);
    if (s.trueVelocity > 1.5) ++velocityOver;
  }
  void print(const std::string& label) {
    if (count == 0) return;
    std::sort(ratios.begin(), ratios.end());
    const auto q = [&](double f) {
      return ratios.empty()
                 ? 0.0
                 : ratios[static_cast<size_t>(f * static_cast<double>(ratios.size() - 1))];
    };
    std::printf("| %s | %d | %zu | %.2f | %.2f | %.2f | %d | %+.2e | %+.2e | %.2e | %d |\n",
                label.c_str(), count, ratios.size(), q(0.5), q(0.9),
                ratios.empty() ? 0.0 : ratios.back(), overTolerance, sumPhi, sumEnergy,
                sumAbsEnergy, velocityOver);
  }
};

const char* phaseOf(double phi) {
  const double s = std::sin(phi);
  return s > 0.5    ? "top (sin phi > 0.5)"
         : s < -0.5 ? "bottom (sin phi < -0.5)"
                    : "flat (|sin phi| <= 0.5)";
}

// The global error at the end split exactly over the steps (Lady Windermere's fan with the
// exact flow), each term into the step's energy error carried to the end and the rest.
void printFan(const Pendulum& pendulum, const std::vector<StepRecord>& steps,
              const std::vector<double>& times, const std::vector<double>& phis,
              const std::vector<double>& rates, double sumLocalPhi) {
  const double hFlow = 5e-4;
  const double tEnd = times.back();
  auto carried = [&](double t, double p, double w, double& pT, double& wT) {
    pT = p, wT = w;
    pendulum.flow(pT, wT, tEnd - t, hFlow);
  };
  double pExact, wExact;
  carried(0.0, M_PI / 2, -1.0, pExact, wExact);
  double sumEnergyPart = 0.0, sumRest = 0.0;
  double pPrev, wPrev;
  carried(0.0, phis[0], rates[0], pPrev, wPrev);
  std::map<std::string, double> energyPartByPhase, restByPhase;
  for (size_t n = 0; n < steps.size(); ++n) {
    double pNext, wNext;
    carried(times[n + 1], phis[n + 1], rates[n + 1], pNext, wNext);
    // The exact step's end with the energy of the step's result: the step's energy error.
    double p = phis[n], w = rates[n];
    pendulum.flow(p, w, steps[n].h, 1e-4);
    const double e = pendulum.energy(phis[n + 1], rates[n + 1]);
    const double w2 = 2.0 * (e - 9.81 * pendulum.b * std::sin(p)) / pendulum.a;
    const double wE = std::copysign(std::sqrt(std::max(0.0, w2)), w);
    double pE, wEnd;
    carried(times[n + 1], p, wE, pE, wEnd);
    sumEnergyPart += pE - pPrev;
    sumRest += pNext - pE;
    energyPartByPhase[phaseOf(steps[n].phi)] += pE - pPrev;
    restByPhase[phaseOf(steps[n].phi)] += pNext - pE;
    pPrev = pNext;
  }
  const double global = phis.back() - pExact;
  const double e0 = pendulum.energy(M_PI / 2, -1.0);
  std::printf(
      "\nAt t = %g s: global phi error %+.3e rad (B0 %.3e m); sum of signed local dphi "
      "%+.3e rad; fan: energy errors carried to the end %+.3e rad, the rest (position "
      "and timing) %+.3e rad (sum %+.3e); energy error %+.3e J (%+.2e of E)\n",
      tEnd, global, 2 * std::abs(std::sin(0.5 * global)), sumLocalPhi, sumEnergyPart, sumRest,
      sumEnergyPart + sumRest, pendulum.energy(phis.back(), rates.back()) - e0,
      (pendulum.energy(phis.back(), rates.back()) - e0) / std::abs(e0));
  for (auto& [label, v] : energyPartByPhase)
    std::printf("  %s: energy part %+.3e rad, rest %+.3e rad\n", label.c_str(), v,
                restByPhase[label]);
}

void writeCsv(const char* path, const std::vector<StepRecord>& steps) {
  FILE* f = std::fopen(path, "w");
  if (!f) return;
  std::fprintf(f, "t,h,order,phi,rate,estimate,true,true_velocity,dphi,drate,denergy\n");
  for (const StepRecord& s : steps)
    std::fprintf(f, "%.12g,%.6g,%d,%.12g,%.12g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g\n", s.t, s.h, s.order,
                 s.phi, s.rate, s.estimate, s.trueNorm, s.trueVelocity, s.dPhi, s.dRate, s.dEnergy);
  std::fclose(f);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr,
                 "usage: %s N END GSTIFF|WSTIFF|SI2_GSTIFF|SI2_WSTIFF|DSTIFF|MERSON ERROR "
                 "[STEPS_CSV [HMAX]]\n",
                 argv[0]);
    return 2;
  }
  const int windows = std::atoi(argv[1]);
  const double end = std::atof(argv[2]);
  const std::string method = argv[3];
  const double error = std::atof(argv[4]);
  const long outputs = std::lround(20 * end);

  language::Dataset ds;
  Diagnostics diags;
  language::readDatasetText(bench::fourBarChainAdm(windows), "a02.adm", ds, diags);
  model::Model model;
  if (!model::buildModel(ds, model, diags)) {
    std::fprintf(stderr, "the generated data set does not build\n");
    return 1;
  }
  mechanics::MultibodySystem system(model);
  Eigen::VectorXd y = system.initialState(), yp;
  mechanics::removeRedundantConstraints(system, y);
  mechanics::AssemblyOptions assembly;
  assembly.honourExact = true;
  assembly.holdJointInitialConditions = true;
  mechanics::assemblePositions(system, 0.0, y, assembly);
  mechanics::solveVelocities(system, 0.0, y, true);
  mechanics::solveAccelerations(system, 0.0, y, yp);

  model::IntegratorSettings settings;
  settings.type = method.find("WSTIFF") != std::string::npos ? model::IntegratorType::Wstiff
                                                             : model::IntegratorType::Gstiff;
  if (method == "MERSON") settings.type = model::IntegratorType::Merson;
  if (method == "DSTIFF") settings.type = model::IntegratorType::Dstiff;
  if (method.rfind("SI2", 0) == 0) settings.formulation = model::IntegratorFormulation::Si2;
  settings.error = error;
  if (argc > 6) settings.hmax = std::atof(argv[6]);
  const double outStep = end / static_cast<double>(outputs);
  const analysis::IntegratorPlan plan = analysis::resolveIntegrator(settings, outStep);
  analysis::MultibodyDae dae(system);
  auto integrator = analysis::makeIntegrator(plan, system, dae, end);
  Observer observer;
  integrator->setStepObserver(&Observer::onStep, &observer);
  integrator->start(0.0, y, yp);

  const StateLayout& layout = system.layout();
  const ExactState exact(layout, y);
  const Pendulum pendulum(windows);
  const double local = kLocalShare * error;
  // phi from the first rocker's centre about its pivot, unwrapped along the run.
  const int r0 = layout.body(0);
  const double pivot = y(r0);
  double phiPrevious = M_PI / 2;
  auto angle = [&](const Eigen::VectorXd& s, double& phi, double& rate) {
    const double x = s(r0) - pivot, z = s(r0 + 1);
    double p = std::atan2(z, x);
    p += 2 * M_PI * std::round((phiPrevious - p) / (2 * M_PI));
    phi = p;
    rate = (x * s(r0 + 8) - z * s(r0 + 7)) / (x * x + z * z);
  };

  std::vector<StepRecord> steps;
  std::vector<double> times{0.0}, phis{M_PI / 2}, rates{-1.0};
  Eigen::VectorXd yStart = integrator->y(), yExact;
  double tStart = 0.0, hPrevious = 0.0, phiStart = M_PI / 2, rateStart = -1.0;
  bool ok = true;
  for (long i = 1; i <= outputs && ok; ++i) {
    const double tout = outStep * static_cast<double>(i);
    while (integrator->t() < tout - 1e-12 * std::max(1.0, tout)) {
      if (!integrator->step(tout)) {
        ok = false;
        break;
      }
      const Eigen::VectorXd& yNew = integrator->y();
      StepRecord s{tStart,
                   integrator->t() - tStart,
                   hPrevious,
                   phiStart,
                   rateStart,
                   observer.order,
                   observer.estimate,
                   0,
                   0,
                   0,
                   0,
                   0};
      double p = phiStart, w = rateStart;
      pendulum.flow(p, w, s.h, 1e-4);
      exact.fill(p, w, yExact);
      const Eigen::VectorXd e = yNew - yExact;
      s.trueNorm = weighted(e, yStart, layout, StateLayout::kR, StateLayout::kV, 1.0 / local);
      s.trueVelocity = weighted(e, yStart, layout, StateLayout::kV, StateLayout::kMu,
                                kVelocitySteps * s.h / local);
      double phiNew, rateNew;
      angle(yNew, phiNew, rateNew);
      phiPrevious = phiNew;
      s.dPhi = phiNew - p;
      s.dRate = rateNew - w;
      s.dEnergy = pendulum.energy(phiNew, rateNew) - pendulum.energy(phiStart, rateStart);
      steps.push_back(s);
      times.push_back(integrator->t());
      phis.push_back(phiNew);
      rates.push_back(rateNew);
      hPrevious = s.h;
      tStart = integrator->t();
      yStart = yNew;
      phiStart = phiNew;
      rateStart = rateNew;
    }
  }
  const double tEnd = times.back();
  std::printf(
      "A02 N = %d, %s, ERROR = %g: reached t = %g s, %zu steps, %ld error-test "
      "rejections\n\n",
      windows, method.c_str(), error, tEnd, steps.size(), observer.rejected);

  // Ratio true / estimated local error (displacement weights) by order, step change, phase.
  std::printf(
      "| class | steps | held | true/est median | p90 | max | true > 1.5 tol | "
      "sum of local dphi (rad) | sum of step energy errors (J) | sum of abs (J) | "
      "velocity true > 1.5 tol |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  Summary all;
  std::map<std::string, Summary> byOrder, byChange, byPhase;
  for (const StepRecord& s : steps) {
    all.add(s);
    byOrder["order " + std::to_string(s.order)].add(s);
    const double c = s.hPrevious > 0 ? s.h / s.hPrevious : 1.0;
    byChange[c > 1.0 + 1e-9 ? "h grew" : c < 1.0 - 1e-9 ? "h shrank" : "h unchanged"].add(s);
    byPhase[phaseOf(s.phi)].add(s);
  }
  all.print("all");
  for (auto* group : {&byOrder, &byChange, &byPhase})
    for (auto& [label, summary] : *group) summary.print(label);

  printFan(pendulum, steps, times, phis, rates, all.sumPhi);
  if (argc > 5) writeCsv(argv[5], steps);
  return ok ? 0 : 1;
}
