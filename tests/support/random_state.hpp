#pragma once
// Random but valid states for the mechanics' derivative checks: positions near the data set's
// configuration, unit Euler parameters, velocities and multipliers of order one, and a body
// turned about one of its own axes (a virtual rotation, for constraint-row checks).

#include <random>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include "mechanics/multibody_system.hpp"

namespace openmss::testing {

// Whether the Euler-parameter multiplier mu gets a random value too (it draws one more number
// per body, so the two choices give different sequences from the same seed).
enum class RandomMu { No, Yes };

inline Eigen::VectorXd randomState(const mechanics::MultibodySystem& s, std::mt19937& rng,
                                   RandomMu mu = RandomMu::No) {
  using L = mechanics::StateLayout;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd y = s.initialState();
  for (int b = 0; b < s.layout().bodies; ++b) {
    const int o = s.layout().body(b);
    for (int c = 0; c < 3; ++c) y(o + L::kR + c) += 0.1 * u(rng);
    Eigen::Vector4d e = y.segment<4>(o + L::kE);
    for (int c = 0; c < 4; ++c) e(c) += 0.2 * u(rng);
    y.segment<4>(o + L::kE) = e.normalized();
    for (int c = 0; c < 3; ++c) {
      y(o + L::kV + c) = u(rng);
      y(o + L::kW + c) = u(rng);
    }
    if (mu == RandomMu::Yes) y(o + L::kMu) = 0.01 * u(rng);
  }
  for (int k = 0; k < s.layout().constraintEquations; ++k) y(s.layout().lambda(k)) = 10.0 * u(rng);
  return y;
}

// The body whose state starts at offset o turned by `angle` about its own axis `axis`.
inline Eigen::VectorXd turned(const Eigen::VectorXd& y, int o, const Eigen::Vector3d& axis,
                              double angle) {
  using L = mechanics::StateLayout;
  Eigen::VectorXd z = y;
  const Eigen::Vector4d e = z.segment<4>(o + L::kE);
  const Eigen::Quaterniond q(e(0), e(1), e(2), e(3));
  const Eigen::Quaterniond qr = q * Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
  z.segment<4>(o + L::kE) << qr.w(), qr.x(), qr.y(), qr.z();
  return z;
}

}  // namespace openmss::testing
