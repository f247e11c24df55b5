#pragma once
// Kinematics of bodies and markers, templated on the scalar (double or Dual<>).

#include <Eigen/Dense>

#include "common/vec3.hpp"
#include "mechanics/state_layout.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

template <class T>
struct BodyPose {
  V3<T> r;      // CM position in ground
  M3<T> a;      // body axes in ground
  V3<T> v;      // CM velocity in ground axes
  V3<T> wg;     // angular velocity in ground axes
};

// A marker's origin, axes, velocity of its origin and angular velocity, all in ground.
template <class T>
struct MarkerState {
  V3<T> p;
  M3<T> a;
  V3<T> pdot;
  V3<T> w;
};

template <class T>
BodyPose<T> bodyPose(const StateLayout& layout, int b, const T* y) {
  const T* q = y + layout.body(b);
  BodyPose<T> pose;
  pose.r = {q[StateLayout::kR], q[StateLayout::kR + 1], q[StateLayout::kR + 2]};
  Quat<T> e{q[StateLayout::kE], q[StateLayout::kE + 1], q[StateLayout::kE + 2],
            q[StateLayout::kE + 3]};
  pose.a = rotationOf(e);
  pose.v = {q[StateLayout::kV], q[StateLayout::kV + 1], q[StateLayout::kV + 2]};
  V3<T> wb{q[StateLayout::kW], q[StateLayout::kW + 1], q[StateLayout::kW + 2]};
  pose.wg = pose.a * wb;
  return pose;
}

// The state of marker mk of a moving part whose body is at pose b (markerState's operations:
// the same value to the bit, so callers may compute b once and share it).
template <class T>
MarkerState<T> markerStateOnBody(const model::Marker& mk, const BodyPose<T>& b) {
  MarkerState<T> s;
  const V3<T> sb = V3<T>::from(mk.position);
  const M3<T> ab = M3<T>::from(mk.orientation);
  V3<T> sg = b.a * sb;
  s.p = b.r + sg;
  s.a = b.a * ab;
  s.pdot = b.v + cross(b.wg, sg);
  s.w = b.wg;
  return s;
}

// The state of marker mk on ground: its data-set frame, at rest.
template <class T>
MarkerState<T> groundMarkerState(const model::Marker& mk) {
  MarkerState<T> s;
  s.p = V3<T>::from(mk.position);
  s.a = M3<T>::from(mk.orientation);
  s.pdot = {T(0.0), T(0.0), T(0.0)};
  s.w = s.pdot;
  return s;
}

template <class T>
MarkerState<T> markerState(const model::Model& m, const StateLayout& layout, int marker,
                           const T* y) {
  const model::Marker& mk = m.markers[marker];
  const model::Part& part = m.parts[mk.part];
  if (part.body >= 0) return markerStateOnBody(mk, bodyPose(layout, part.body, y));
  return groundMarkerState<T>(mk);
}

}  // namespace openmss::mechanics
