#pragma once
// The structural pattern of the stabilised index-2 (SI2) Newton matrix
// (analysis/multibody_dae_si2.hpp, docs/theory.md §9a): the index-3 pattern, plus for each
// constraint equation k one row (its velocity form C_k u) and one column (its multiplier
// eta_k). The velocity form reads the positions and velocities of the bodies the equation
// reads; eta_k enters the kinematic rows (r, e) of those bodies, whose terms C^T eta also vary
// with those bodies' positions. Which bodies an equation reads is taken from its value row in
// the index-3 pattern, so whatever rule made that row (markers, or an expression's measures)
// carries over; a dense index-3 row makes every body's kinematic rows read eta_k.

#include "mechanics/jacobian_pattern.hpp"

namespace openmss::mechanics {

class MultibodySystem;

// The SI2 pattern of size i3.size + constraintEquations, coloured. Its denseRows is that of
// the index-3 pattern (rows made dense there stay dense here), so that a plan refuses it too.
JacobianPattern stabilisedNewtonPattern(const MultibodySystem& system, const JacobianPattern& i3);

}  // namespace openmss::mechanics
