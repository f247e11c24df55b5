#pragma once
// The active constraint equations of a model evaluated together, as the index-1 form of the
// equations of motion needs them at every evaluation (docs/theory.md §9d): the rows of
// C = dPhi/d(delta r, delta pi) on a structure that depends on the model only, the
// acceleration right-hand side gamma (C u' = gamma) and the values Phi.
//
// Built for speed (docs/theory.md §9e): each body's pose and each marker's frame, with its
// velocity and zero-acceleration second derivative, is computed once per call and shared by
// every equation that reads it; the numbers themselves come from the one definition of each
// equation (MultibodySystem::sideGradient, ConstraintSet::geometry). Nothing is allocated per
// call: the scratch is sized at construction, so one ConstraintRows serves one thread at a time.

#include <cstddef>
#include <vector>

#include "common/dual.hpp"
#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

class ConstraintRows {
 public:
  // The equations `rows` (indices into system.constraints().equations(), in that order).
  ConstraintRows(const MultibodySystem& system, std::vector<int> rows);

  const std::vector<int>& rows() const { return rows_; }
  int count() const { return static_cast<int>(rows_.size()); }
  // Structure of C: the entries of row r are start()[r] .. start()[r + 1] - 1, with columns
  // columns()[i] (6 b + direction of moving body b, increasing within a row). Fixed for the
  // model: the same whatever the state.
  const std::vector<int>& start() const { return start_; }
  const std::vector<int>& columns() const { return columns_; }

  // values[i]: the entries of C at y, in the order of columns(); gamma[r]: f''(t) of a motion
  // minus the second derivative of Phi_r along the current velocities at zero acceleration.
  // Either may be null: C alone (it depends on positions only) skips the velocity jets, gamma
  // alone (after a change of velocities only) skips the side gradients.
  void evaluate(double t, const double* y, double* values, double* gamma) const;
  // phi[r] = Phi_r(q, t); nu[r] = f'(t) of a motion, else 0 (C u = nu on the manifold).
  void values(double t, const double* y, double* phi, double* nu) const;

 private:
  // Second-order jet along the path r + s v, A exp(s [w]): value, d/ds, d2/ds2 (as in
  // MultibodySystem::constraintRates).
  using Jet = Dual<Dual<double>>;
  // One equation's side (marker slot s of the equation): its moving body (index into bodies_,
  // -1 for ground) and where its six derivatives go in the row's values (-1 for ground).
  struct Side {
    int body = -1;
    int offset = -1;
  };
  // One marker as a group reads it: its body (index into bodies_, -1 for ground) and its place
  // in that body's frame.
  struct Slot {
    int body = -1;
    V3<double> position;
    M3<double> axes;
  };
  // Fills the pose cache of every body the rows read; with velocities when `jets`.
  void updateBodies(const double* y, bool jets) const;
  // Fills the frames (and the jets when `jets`) of group `group`'s slots on moving bodies.
  void updateSlots(size_t group, bool jets) const;

  const MultibodySystem& system_;
  std::vector<int> rows_;
  std::vector<int> start_, columns_;

  // Fixed at construction.
  std::vector<int> bodies_;     // moving bodies the rows read (state_layout indices)
  std::vector<int> sideStart_;  // per row: its sides are sides_[sideStart_[r] ..]
  std::vector<Side> sides_;
  // Consecutive rows reading the same markers in the same order (a revolute joint's five)
  // form a group; group g holds rows groupStart_[g] .. groupStart_[g + 1] - 1, and its
  // markers' frames are slots groupSlot_[g] .. (contiguous, as ConstraintSet::geometry reads
  // them). A marker read by several groups is computed once per group: cheaper than copying.
  std::vector<int> groupStart_, groupSlot_;
  std::vector<Slot> slots_;

  // Scratch, overwritten by every call (ground slots are set once, at construction).
  mutable std::vector<V3<double>> origin_, velocity_, omega_;  // omega_: see updateBodies
  mutable std::vector<M3<double>> axes_;
  mutable std::vector<Frame<double>> frames_;  // per slot
  mutable std::vector<Frame<Jet>> jets_;       // per slot
};

}  // namespace openmss::mechanics
