#pragma once
// The stiction anchor of one FRICTION (docs/theory.md, "Joint friction"): the relative pose of
// the joint's I marker in J axes where the current stiction began. The creep that the static
// regime resists is the displacement from it. It is run-time history, like the reference of a
// cumulative angle: the expression run state (mechanics/expression_run_state.hpp) holds one per
// FRICTION and moves it only after accepted steps, so corrector iterations and rejected steps
// see a fixed anchor (the residual stays a smooth function of the state) and a run repeated is
// bit-identical.

#include <Eigen/Dense>

#include "mechanics/state_layout.hpp"
#include "model/model.hpp"

namespace openmss::mechanics::friction {

struct FrictionAnchor {
  bool set = false;
  Eigen::Vector3d displacement = Eigen::Vector3d::Zero();  // A_J^T (p_I - p_J)
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // A_J^T A_I
};

// After an accepted state y: while the joint slips (|slip| >= STICTION_TRANSITION_VELOCITY) or
// before the first accepted state, the anchor follows the joint (creep zero); in stiction it
// stays, except that a creep longer than MAX_STICTION_DEFORMATION drags it along so that the
// creep keeps that length and its direction.
void updateAnchor(const model::Model& m, const StateLayout& l, int friction, const double* y,
                  FrictionAnchor& anchor);

}  // namespace openmss::mechanics::friction
