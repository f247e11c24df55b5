#pragma once
// Shared pieces of the CONTACT truth tests: a model built from data-set text, and a dynamic run
// from consistent initial conditions that hands every output sample to the test.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "analysis/multibody_dae.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/expression_run_state.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "solvers/bdf_integrator.hpp"

namespace openmss::contact_test {

using mechanics::StateLayout;

inline model::Model build(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "contact.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

// One output sample of body 0 (the first moving part): time, CM position and velocity, and
// the angular velocity in ground axes.
struct Sample {
  double t;
  Eigen::Vector3d r, v, w;
};

// Dynamic run (GSTIFF-style BDF, I3) to `end` with outputs every `step`.
inline std::vector<Sample> simulate(const model::Model& m, double end, double step, double error,
                                    double hmax) {
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
  solvers::BdfIntegrator bdf(dae, settings);
  bdf.start(0.0, y, yp);
  auto record = [&](double t, const Eigen::VectorXd& x) {
    const Quat<double> e{x(StateLayout::kE), x(StateLayout::kE + 1), x(StateLayout::kE + 2),
                         x(StateLayout::kE + 3)};
    const Eigen::Vector3d wBody = x.segment<3>(StateLayout::kW);
    out.push_back({t, x.segment<3>(StateLayout::kR), x.segment<3>(StateLayout::kV),
                   toEigen(rotationOf(e)) * wBody});
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
  return out;
}

}  // namespace openmss::contact_test
