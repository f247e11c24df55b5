#pragma once
// Shared pieces of the CONTACT truth tests: a model built from data-set text, a dynamic run
// from consistent initial conditions that hands every output sample to the test, the check of
// a located refusal, and the CONTACT statements of a pile of spheres.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "analysis/contact_events.hpp"
#include "analysis/multibody_dae.hpp"
#include "language/reader.hpp"
#include "mechanics/expression_run_state.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "solvers/bdf_integrator.hpp"
#include "support/built_model.hpp"

namespace openmss::contact_test {

using mechanics::StateLayout;

// Reads `text` as contact.adm and builds it (the build must succeed), diagnostics into `d`.
inline model::Model readAndBuild(const std::string& text, Diagnostics& d) {
  language::Dataset ds;
  language::readDatasetText(text, "contact.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d));
  return m;
}

inline model::Model build(const std::string& text) {
  Diagnostics d;
  model::Model m = readAndBuild(text, d);
  // A PLANE's "not drawn by the viewer" warning is expected; any other diagnostic fails.
  for (const auto& x : d.all())
    if (format(x).find("are not drawn by the viewer") == std::string::npos)
      ADD_FAILURE() << format(x);
  return m;
}

// build(), failing on errors only: warnings (a PLANE or OUTLINE not drawn by the viewer, ...)
// are expected.
inline model::Model buildFailingOnErrors(const std::string& text) {
  Diagnostics d;
  model::Model m = readAndBuild(text, d);
  for (const auto& x : d.all())
    if (x.severity == Severity::Error) ADD_FAILURE() << format(x);
  return m;
}

// One output sample of body 0 (the first moving part): time, CM position and velocity, the
// angular velocity in ground axes and the body's axes in ground (columns).
struct Sample {
  double t;
  Eigen::Vector3d r, v, w;
  Eigen::Matrix3d a;
};

// Dynamic run (GSTIFF-style BDF, I3) to `end` with outputs every `step`. With `events`, the
// method runs under the contact event locator (analysis/contact_events.hpp), which restarts it
// at each onset and records the events there.
inline std::vector<Sample> simulate(const model::Model& m, double end, double step, double error,
                                    double hmax,
                                    std::vector<analysis::ContactEvent>* events = nullptr) {
  std::vector<Sample> out;
  mechanics::MultibodySystem s(m);
  // A dynamic analysis (DYNAMICS_ONLY friction acts): the mode is the run state's.
  mechanics::ExpressionRunState run(m);
  run.status().mode = model::AnalysisMode::Dynamics;
  s.setRunState(&run);
  Eigen::VectorXd y = s.initialState(), yp;
  mechanics::removeRedundantConstraints(s, y);
  EXPECT_TRUE(mechanics::assemblePositions(s, 0.0, y, 1e-12, 25).converged);
  mechanics::solveVelocities(s, 0.0, y);
  EXPECT_TRUE(mechanics::solveAccelerations(s, 0.0, y, yp));
  analysis::MultibodyDae dae(s);
  solvers::MultistepSettings settings;
  settings.error = error;
  settings.hmax = hmax;
  settings.hinit = hmax / 10;
  solvers::BdfIntegrator method(dae, settings);
  analysis::ContactEventIntegrator located(method, s);
  solvers::Integrator& bdf = events ? static_cast<solvers::Integrator&>(located) : method;
  bdf.start(0.0, y, yp);
  auto record = [&](double t, const Eigen::VectorXd& x) {
    const Quat<double> e{x(StateLayout::kE), x(StateLayout::kE + 1), x(StateLayout::kE + 2),
                         x(StateLayout::kE + 3)};
    const Eigen::Vector3d wBody = x.segment<3>(StateLayout::kW);
    const Eigen::Matrix3d a = toEigen(rotationOf(e));
    out.push_back({t, x.segment<3>(StateLayout::kR), x.segment<3>(StateLayout::kV), a * wBody, a});
  };
  record(0.0, y);
  const int n = static_cast<int>(std::lround(end / step));
  for (int k = 1; k <= n; ++k) {
    if (!bdf.advanceTo(k * step)) {
      ADD_FAILURE() << "integration failed at " << k * step << ": " << bdf.failure().reason;
      break;
    }
    record(bdf.t(), bdf.y());
  }
  if (events) *events = located.events();
  return out;
}

// The penetration d = R - z obeys d'' = g - F(d, d')/m with ADAMS's IMPACT force.
struct ImpactOde {
  double k, e, c, dmax, g;
  double force(double d, double u) const {
    if (d <= 0.0) return 0.0;
    double damp = c;
    if (d < dmax) {
      const double s = d / dmax;
      damp = c * s * s * (3.0 - 2.0 * s);
    }
    return std::max(0.0, k * std::pow(d, e) + damp * u);
  }
  void rate(const double x[2], double out[2]) const {
    out[0] = x[1];
    out[1] = g - force(x[0], x[1]);
  }
  void rk4(double x[2], double h) const {
    double k1[2], k2[2], k3[2], k4[2], t[2];
    rate(x, k1);
    for (int i = 0; i < 2; ++i) t[i] = x[i] + 0.5 * h * k1[i];
    rate(t, k2);
    for (int i = 0; i < 2; ++i) t[i] = x[i] + 0.5 * h * k2[i];
    rate(t, k3);
    for (int i = 0; i < 2; ++i) t[i] = x[i] + h * k3[i];
    rate(t, k4);
    for (int i = 0; i < 2; ++i) x[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
};

// Peak of samples y(t) at uniform spacing by the parabola through the three largest neighbours.
inline double peak(const std::vector<double>& y) {
  const size_t k = std::max_element(y.begin(), y.end()) - y.begin();
  if (k == 0 || k + 1 >= y.size()) return y[k];
  const double a = 0.5 * (y[k + 1] - 2 * y[k] + y[k - 1]), b = 0.5 * (y[k + 1] - y[k - 1]);
  return y[k] - b * b / (4 * a);
}

// First time after the peak where y falls back to 0 (linear interpolation between samples).
inline double returnTime(const std::vector<double>& t, const std::vector<double>& y) {
  const size_t top = std::max_element(y.begin(), y.end()) - y.begin();
  for (size_t k = top + 1; k < y.size(); ++k)
    if (y[k] <= 0.0) return t[k - 1] + (t[k] - t[k - 1]) * y[k - 1] / (y[k - 1] - y[k]);
  return -1.0;
}

// dG/dy of the residual: the Newton matrix with cj = 0 against central differences.
// The Newton matrix `exact` (cj = 0) against central differences of the residual with step h,
// every column: the largest difference and the largest entry.
struct ColumnMismatch {
  double worst = 0.0, scale = 0.0;
  int columns = 0;
};
inline ColumnMismatch centralDifferenceMismatch(const mechanics::MultibodySystem& s,
                                                const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                                                const Eigen::MatrixXd& exact, double h) {
  const int n = static_cast<int>(y.size());
  Eigen::VectorXd gp(n), gm(n);
  ColumnMismatch m;
  for (int c = 0; c < n; ++c) {
    Eigen::VectorXd a = y, b = y;
    a(c) += h;
    b(c) -= h;
    s.residual(0.0, a.data(), yp.data(), gp.data());
    s.residual(0.0, b.data(), yp.data(), gm.data());
    const Eigen::VectorXd fd = (gp - gm) / (2 * h);
    m.worst = std::max(m.worst, (fd - exact.col(c)).cwiseAbs().maxCoeff());
    m.scale = std::max(m.scale, exact.col(c).cwiseAbs().maxCoeff());
    ++m.columns;
  }
  return m;
}

// The Newton matrix of `m` in a dynamic analysis (DYNAMICS_ONLY friction acts: the mode is the
// run state's), at the data set's configuration with the first part moving at `velocity`
// (v, w), against central differences of step h.
inline ColumnMismatch newtonMatrixMismatch(const model::Model& m, const Eigen::VectorXd& velocity,
                                           double h) {
  mechanics::MultibodySystem s(m);
  mechanics::ExpressionRunState run(m);
  run.status().mode = model::AnalysisMode::Dynamics;
  s.setRunState(&run);
  Eigen::VectorXd y = s.initialState();
  y.segment<3>(StateLayout::kV) = velocity.head<3>();
  y.segment<3>(StateLayout::kW) = velocity.tail<3>();
  const Eigen::VectorXd yp = Eigen::VectorXd::Zero(y.size());
  Eigen::MatrixXd exact;
  s.newtonMatrix(0.0, y, yp, 0.0, exact);
  return centralDifferenceMismatch(s, y, yp, exact, h);
}

inline void checkJacobian(const std::string& text, const Eigen::VectorXd& velocity) {
  const model::Model m = build(text);
  const int n = static_cast<int>(mechanics::MultibodySystem(m).initialState().size());
  const ColumnMismatch d = newtonMatrixMismatch(m, velocity, 1e-7);
  std::printf(
      "contact Jacobian: max |exact - central difference| %.3e of max entry %.3e over "
      "%d columns\n",
      d.worst, d.scale, d.columns);
  EXPECT_EQ(d.columns, n);
  // Central differences with h = 1e-7 are good to ~1e-7 relative on these smooth branches.
  EXPECT_LT(d.worst, 1e-6 * d.scale);
}

// Exactly one error in the build `b`, located at `line`, whose text contains `text` and, when
// `subject` is given, the statement's subject (e.g. "CONTACT/1"): a refusal names the statement
// and says where and what to change.
inline void expectOneError(const testing::BuiltModel& b, int line, const std::string& text,
                           const char* subject = "CONTACT/1") {
  EXPECT_FALSE(b.ok);
  int errors = 0;
  for (const auto& d : b.diags.all()) {
    if (d.severity != Severity::Error) continue;
    ++errors;
    EXPECT_EQ(d.where.line, line) << format(d);
    EXPECT_NE(format(d).find(text), std::string::npos) << format(d);
    if (subject) {
      EXPECT_NE(format(d).find(subject), std::string::npos) << format(d);
    }
  }
  EXPECT_EQ(errors, 1) << ::testing::PrintToString(b.messages());
}

// The CONTACT statements of a pile of `spheres` spheres whose GRAPHICS are 10 * (firstPart + i):
// numbered from 1, each sphere against the GRAPHICS ids `walls` (a JGEOM list), then every pair
// of spheres; each ends with `law` (the normal law and the line's end).
inline std::string pileContacts(int spheres, int firstPart, const std::string& walls,
                                const std::string& law) {
  std::string d;
  int id = 1;
  for (int i = 0; i < spheres; ++i)
    d += "CONTACT/" + std::to_string(id++) + ", IGEOM=" + std::to_string(10 * (firstPart + i)) +
         ", JGEOM=" + walls + ", " + law;
  for (int i = 0; i < spheres; ++i)
    for (int j = i + 1; j < spheres; ++j)
      d += "CONTACT/" + std::to_string(id++) + ", IGEOM=" + std::to_string(10 * (firstPart + i)) +
           ", JGEOM=" + std::to_string(10 * (firstPart + j)) + ", " + law;
  return d;
}

}  // namespace openmss::contact_test
