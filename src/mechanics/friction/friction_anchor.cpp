#include "mechanics/friction/friction_anchor.hpp"

#include <cmath>

#include "mechanics/friction/joint_friction.hpp"

namespace openmss::mechanics::friction {

namespace {

// Rotation by the vector phi (Rodrigues).
Eigen::Matrix3d rotationOfVector(const Eigen::Vector3d& phi) {
  const double angle = phi.norm();
  if (angle == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, phi / angle).toRotationMatrix();
}

}  // namespace

void updateAnchor(const model::Model& m, const StateLayout& l, int friction, const double* y,
                  FrictionAnchor& anchor) {
  const model::Friction& f = m.frictions[friction];
  const model::Joint& joint = m.joints[f.joint];
  const MarkerState<double> mi = markerState(m, l, joint.iMarker, y);
  const MarkerState<double> mj = markerState(m, l, joint.jMarker, y);
  Eigen::Vector3d displacement;
  Eigen::Matrix3d rotation;
  relativePose(mi, mj, displacement, rotation);
  const FrictionKinematics<double> k = frictionKinematics(m, l, f, y, &anchor);
  double slip2 = 0.0, creep2 = 0.0;
  for (int c = 0; c < 6; ++c)
    if (k.channels.free[c]) {
      slip2 += k.slip[c] * k.slip[c];
      creep2 += k.creep[c] * k.creep[c];
    }
  const bool slipping = std::sqrt(slip2) >= f.stictionVelocity;
  if (!anchor.set || slipping || f.effect == model::Friction::Effect::Sliding) {
    anchor.set = true;
    anchor.displacement = displacement;
    anchor.rotation = rotation;
    return;
  }
  const double creep = std::sqrt(creep2), limit = f.maxStictionDeformation;
  if (creep <= limit) return;
  // Keep the creep at the limit along its direction: the anchor moves to current - limit * u
  // (translations), and the anchored rotation to exp(-limit/creep * theta) R for the
  // rotational creep theta (J axes).
  const double keep = limit / creep;
  for (int c = 0; c < 3; ++c)
    if (k.channels.free[c]) anchor.displacement(c) = displacement(c) - keep * k.creep[c];
  Eigen::Vector3d theta = Eigen::Vector3d::Zero();
  for (int c = 0; c < 3; ++c)
    if (k.channels.free[3 + c]) theta(c) = keep * k.creep[3 + c] / k.channels.radius;
  // creep = sin(angle) axis: the kept angle is asin of the kept length.
  const double s = theta.norm();
  if (s > 0.0) theta *= std::asin(std::min(1.0, s)) / s;
  anchor.rotation = rotationOfVector(-theta) * rotation;
}

}  // namespace openmss::mechanics::friction
