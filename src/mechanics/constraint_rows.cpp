#include "mechanics/constraint_rows.hpp"

#include <algorithm>
#include <utility>

namespace openmss::mechanics {

namespace {

// A jet whose derivatives are d1 and d2: (value, d1) with derivative (d1, d2).
Dual<Dual<double>> jetOf(double value, double d1, double d2) {
  return {Dual<double>(value, d1), Dual<double>(d1, d2)};
}

bool sameMarkers(const ConstraintEquation& a, const ConstraintEquation& b) {
  if (a.markerCount() != b.markerCount()) return false;
  for (int s = 0; s < a.markerCount(); ++s)
    if (a.marker(s) != b.marker(s)) return false;
  return true;
}

}  // namespace

ConstraintRows::ConstraintRows(const MultibodySystem& system, std::vector<int> rows)
    : system_(system), rows_(std::move(rows)) {
  const model::Model& model = system.model();
  const auto& eqs = system.constraints().equations();
  // The structure comes from one evaluation at the data set's configuration: the columns of a
  // row are the bodies its markers sit on, whatever their values.
  const Eigen::VectorXd y = system.initialState();
  std::vector<int> cols;
  std::vector<double> vals;
  start_.assign(1, 0);
  for (int k : rows_) {
    system.constraintRowEntries(k, y.data(), cols, vals);
    columns_.insert(columns_.end(), cols.begin(), cols.end());
    start_.push_back(static_cast<int>(columns_.size()));
  }

  std::vector<int> bodyIndex(static_cast<size_t>(system.layout().bodies), -1);
  auto bodyOf = [&](int marker) {
    const int body = model.parts[model.markers[marker].part].body;
    if (body < 0) return -1;
    int& index = bodyIndex[static_cast<size_t>(body)];
    if (index < 0) {
      index = static_cast<int>(bodies_.size());
      bodies_.push_back(body);
    }
    return index;
  };
  sideStart_.assign(1, 0);
  for (int r = 0; r < count(); ++r) {
    const ConstraintEquation& eq = eqs[static_cast<size_t>(rows_[static_cast<size_t>(r)])];
    if (r == 0 || !sameMarkers(eq, eqs[static_cast<size_t>(rows_[static_cast<size_t>(r - 1)])])) {
      groupStart_.push_back(r);
      groupSlot_.push_back(static_cast<int>(slots_.size()));
      for (int s = 0; s < eq.markerCount(); ++s) {
        const model::Marker& mk = model.markers[eq.marker(s)];
        slots_.push_back({bodyOf(eq.marker(s)), V3<double>::from(mk.position),
                          M3<double>::from(mk.orientation)});
      }
    }
    for (int s = 0; s < eq.markerCount(); ++s) {
      Side side;
      side.body = bodyOf(eq.marker(s));
      if (side.body >= 0) {
        // The row's entries for this body: its six columns, found in the row's structure.
        const int column = 6 * bodies_[static_cast<size_t>(side.body)];
        const auto first = columns_.begin() + start_[static_cast<size_t>(r)];
        const auto last = columns_.begin() + start_[static_cast<size_t>(r) + 1];
        side.offset = static_cast<int>(std::find(first, last, column) - columns_.begin());
      }
      sides_.push_back(side);
    }
    sideStart_.push_back(static_cast<int>(sides_.size()));
  }
  groupStart_.push_back(count());
  groupSlot_.push_back(static_cast<int>(slots_.size()));

  const size_t nb = bodies_.size();
  origin_.resize(nb);
  velocity_.resize(nb);
  omega_.resize(nb);
  axes_.resize(nb);
  frames_.resize(slots_.size());
  jets_.resize(slots_.size());
  // Markers on ground never move: their frames and (zero-derivative) jets are set once here.
  for (size_t i = 0; i < slots_.size(); ++i) {
    const Slot& slot = slots_[i];
    if (slot.body >= 0) continue;
    frames_[i] = {slot.position, slot.axes};
    for (int c = 0; c < 3; ++c) {
      jets_[i].p[c] = jetOf(slot.position[c], 0.0, 0.0);
      for (int a = 0; a < 3; ++a) jets_[i].a.c[a][c] = jetOf(slot.axes.c[a][c], 0.0, 0.0);
    }
  }
}

void ConstraintRows::updateBodies(const double* y, bool jets) const {
  const StateLayout& layout = system_.layout();
  for (size_t i = 0; i < bodies_.size(); ++i) {
    const double* q = y + layout.body(bodies_[i]);
    // As MultibodySystem::bodyPose, operation for operation, so that the rows are the same
    // numbers as constraintRowEntries'.
    origin_[i] = {q[StateLayout::kR], q[StateLayout::kR + 1], q[StateLayout::kR + 2]};
    const Quat<double> e{q[StateLayout::kE], q[StateLayout::kE + 1], q[StateLayout::kE + 2],
                         q[StateLayout::kE + 3]};
    axes_[i] = rotationOf(e);
    if (!jets) continue;
    velocity_[i] = {q[StateLayout::kV], q[StateLayout::kV + 1], q[StateLayout::kV + 2]};
    // Along A(s) = A exp(s [w]) a body vector x moves as A [w] x = omega x (A x) with
    // omega = A w / |e|^2: rotationOf(e) is |e|^2 times a rotation, so this holds exactly
    // whether or not e is normalised, and every derivative below is a cross product in
    // ground instead of a matrix product per marker axis.
    const V3<double> wb{q[StateLayout::kW], q[StateLayout::kW + 1], q[StateLayout::kW + 2]};
    const double scale = 1.0 / (e.e0 * e.e0 + e.e1 * e.e1 + e.e2 * e.e2 + e.e3 * e.e3);
    omega_[i] = scale * (axes_[i] * wb);
  }
}

void ConstraintRows::updateSlots(size_t group, bool jets) const {
  const auto last = static_cast<size_t>(groupSlot_[group + 1]);
  for (auto i = static_cast<size_t>(groupSlot_[group]); i < last; ++i) {
    const Slot& slot = slots_[i];
    if (slot.body < 0) continue;
    const auto b = static_cast<size_t>(slot.body);
    const M3<double>& a = axes_[b];
    // As MultibodySystem::frame (markerState), operation for operation.
    const V3<double> arm = a * slot.position;
    Frame<double>& f = frames_[i];
    f.p = origin_[b] + arm;
    f.a = a * slot.axes;
    if (!jets) continue;
    // Zero-acceleration path: p' = v + omega x arm, p'' = omega x (omega x arm); each axis
    // a' = omega x a, a'' = omega x a'.
    const V3<double>& w = omega_[b];
    const V3<double> dp = velocity_[b] + cross(w, arm);
    const V3<double> ddp = cross(w, cross(w, arm));
    Frame<Jet>& jf = jets_[i];
    for (int c = 0; c < 3; ++c) jf.p[c] = jetOf(f.p[c], dp[c], ddp[c]);
    for (int r = 0; r < 3; ++r) {
      const V3<double> da = cross(w, f.a.c[r]);
      const V3<double> dda = cross(w, da);
      for (int c = 0; c < 3; ++c) jf.a.c[r][c] = jetOf(f.a.c[r][c], da[c], dda[c]);
    }
  }
}

void ConstraintRows::evaluate(double t, const double* y, double* values, double* gamma) const {
  // The jets (velocities and their products) only when gamma is wanted: the rows alone need
  // the frames, gamma alone needs no side gradient.
  const bool jets = gamma != nullptr;
  updateBodies(y, jets);
  const auto& eqs = system_.constraints().equations();
  for (size_t g = 0; g + 1 < groupStart_.size(); ++g) {
    // The group's frames just before its rows read them (still in the first-level cache).
    updateSlots(g, jets);
    const Frame<double>* frames = frames_.data() + groupSlot_[g];
    const Frame<Jet>* groupJets = jets_.data() + groupSlot_[g];
    for (int r = groupStart_[g]; r < groupStart_[g + 1]; ++r) {
      const auto ru = static_cast<size_t>(r);
      const int k = rows_[ru];
      const ConstraintEquation& eq = eqs[static_cast<size_t>(k)];
      if (gamma) {
        const double second = ConstraintSet::geometry(eq, groupJets).d.d;
        const double f2 = eq.motion >= 0 ? system_.motionJet(k, t).d2 : 0.0;
        gamma[r] = f2 - second;
      }
      if (!values) continue;
      // The row: the sides' derivatives summed per body, in marker order (two markers of one
      // equation may share a body), as constraintRowEntries sums them.
      std::fill(values + start_[ru], values + start_[ru + 1], 0.0);
      for (int s = 0; s < eq.markerCount(); ++s) {
        const Side& side = sides_[static_cast<size_t>(sideStart_[ru] + s)];
        if (side.body < 0) continue;
        const auto b = static_cast<size_t>(side.body);
        double d[6];
        MultibodySystem::sideGradient(eq, frames, s, origin_[b], axes_[b], d);
        double* out = values + side.offset;
        for (int dir = 0; dir < 6; ++dir) out[dir] = out[dir] + d[dir];
      }
    }
  }
}

void ConstraintRows::values(double t, const double* y, double* phi, double* nu) const {
  updateBodies(y, false);
  const auto& eqs = system_.constraints().equations();
  for (size_t g = 0; g + 1 < groupStart_.size(); ++g) {
    updateSlots(g, false);
    const Frame<double>* frames = frames_.data() + groupSlot_[g];
    for (int r = groupStart_[g]; r < groupStart_[g + 1]; ++r) {
      const int k = rows_[static_cast<size_t>(r)];
      phi[r] = system_.constraintValue(k, t, frames);
      nu[r] = eqs[static_cast<size_t>(k)].motion >= 0 ? system_.motionJet(k, t).d1 : 0.0;
    }
  }
}

}  // namespace openmss::mechanics
