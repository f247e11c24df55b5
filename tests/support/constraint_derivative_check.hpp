#pragma once
// The checks every constraint equation is held to, besides its Newton matrix
// (newton_matrix_check.hpp): its row of C against central differences of its value under
// virtual displacements of each body (translations along ground axes, turns about body axes),
// and its rates against differences along the motion of every body (time held fixed, so the
// differences see the geometry only, as the rates do).

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "mechanics/multibody_system.hpp"
#include "model/model.hpp"
#include "support/random_state.hpp"

namespace openmss::testing {

inline void checkConstraintRows(const mechanics::MultibodySystem& s, const model::Model& m,
                                const Eigen::VectorXd& y, double t) {
  using L = mechanics::StateLayout;
  const int nb = s.layout().bodies;
  std::vector<double> row(6 * nb);
  for (int k = 0; k < s.constraints().size(); ++k) {
    s.constraintRow(k, y.data(), row.data());
    for (int b = 0; b < nb; ++b)
      for (int dir = 0; dir < 6; ++dir) {
        const int o = s.layout().body(b);
        auto displaced = [&](double h) {
          Eigen::VectorXd z = y;
          if (dir < 3) z(o + L::kR + dir) += h;
          else z = turned(y, o, Eigen::Vector3d::Unit(dir - 3), h);
          return s.constraintValue(k, t, z.data());
        };
        const double h = 1e-6;
        const double fd = (displaced(h) - displaced(-h)) / (2 * h);
        // Central differences with h = 1e-6 on O(1) quantities: error ~1e-10 (truncation h^2
        // and round-off 1e-16/h); 1e-7 leaves margin.
        EXPECT_NEAR(row[6 * b + dir], fd, 1e-7 * (1.0 + std::abs(fd)))
            << s.constraints().describe(k, m) << " body " << b << " direction " << dir;
      }
  }
}

// Motion equations are skipped when asked: their rates include the motion's own time
// derivatives, which differences at fixed time do not see.
enum class MotionRates { Check, Skip };

inline void checkConstraintRates(const mechanics::MultibodySystem& s, const model::Model& m,
                                 const Eigen::VectorXd& y, double t,
                                 MotionRates motions = MotionRates::Check) {
  using L = mechanics::StateLayout;
  auto moved = [&](double h) {
    Eigen::VectorXd z = y;
    for (int b = 0; b < s.layout().bodies; ++b) {
      const int o = s.layout().body(b);
      z.segment<3>(o + L::kR) += h * y.segment<3>(o + L::kV);
      const Eigen::Vector3d w = y.segment<3>(o + L::kW);
      z = turned(z, o, w / w.norm(), h * w.norm());
    }
    return z;
  };
  for (int k = 0; k < s.constraints().size(); ++k) {
    if (motions == MotionRates::Skip && s.constraints().equations()[k].motion >= 0) continue;
    double first = 0, second = 0;
    s.constraintRates(k, y.data(), &first, &second);
    const double h = 1e-4;
    const double p = s.constraintValue(k, t, moved(h).data());
    const double z = s.constraintValue(k, t, y.data());
    const double q = s.constraintValue(k, t, moved(-h).data());
    EXPECT_NEAR(first, (p - q) / (2 * h), 1e-7 * (1.0 + std::abs(first)))
        << s.constraints().describe(k, m);
    // Second differences: truncation ~h^2 = 1e-8, round-off ~1e-16/h^2 = 1e-8.
    EXPECT_NEAR(second, (p - 2 * z + q) / (h * h), 1e-5 * (1.0 + std::abs(second)))
        << s.constraints().describe(k, m);
  }
}

}  // namespace openmss::testing
