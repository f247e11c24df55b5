#pragma once
// The kinematics the CONTACT elements of one residual evaluation read (docs/theory.md §6c,
// "Shared kinematics"): each body's pose and each marker's state computed once, when first
// asked, and shared by every pair that reads them. A pile of N spheres has N (N - 1) / 2 pair
// elements reading N parts; computed per element, the parts' dual states were 71 % of a
// Newton matrix (docs/performance.md, "Contact pile"). The cached values come from the same
// functions as the uncached ones (pose.hpp), so they are the same to the bit.
//
// Without slots (the read-backs ask for one element at a time) every call computes afresh, as
// before, and nothing is allocated.

#include <vector>

#include "mechanics/pose.hpp"
#include "mechanics/state_layout.hpp"
#include "model/model.hpp"

namespace openmss::mechanics::contact {

// Which bodies and markers the CONTACT elements read, numbered densely (built once per
// model), so that a cache holds those only, whatever the size of the rest of the model.
struct ContactSlots {
  std::vector<int> body, marker;  // per body / per marker of the model: slot, or -1
  int bodies = 0, markers = 0;

  ContactSlots() = default;
  ContactSlots(const model::Model& m, const StateLayout& layout) {
    body.assign(static_cast<size_t>(layout.bodies), -1);
    marker.assign(m.markers.size(), -1);
    auto take = [&](int k) {
      if (k < 0 || marker[k] >= 0) return;
      marker[k] = markers++;
      const int b = m.parts[m.markers[k].part].body;
      if (b >= 0 && body[b] < 0) body[b] = bodies++;
    };
    for (const model::Contact& c : m.contacts) {
      take(c.iMarker);
      take(c.jMarker);
      for (const model::ContactSolid& s : c.iSolids) take(s.marker);
      for (const model::ContactSolid& s : c.jSolids) take(s.marker);
    }
  }
};

template <class T>
class ContactKinematics {
 public:
  // `slots` null: nothing is cached (every call computes afresh).
  ContactKinematics(const model::Model& m, const StateLayout& layout, const T* y,
                    const ContactSlots* slots = nullptr)
      : m_(m), layout_(layout), y_(y), slots_(slots) {
    if (slots == nullptr) return;
    poses_.resize(static_cast<size_t>(slots->bodies));
    poseDone_.assign(static_cast<size_t>(slots->bodies), 0);
    markers_.resize(static_cast<size_t>(slots->markers));
    markerDone_.assign(static_cast<size_t>(slots->markers), 0);
  }

  const T* y() const { return y_; }

  // Pose of moving body b (bodyPose).
  BodyPose<T> pose(int b) {
    const int k = slots_ != nullptr ? slots_->body[b] : -1;
    if (k < 0) return bodyPose(layout_, b, y_);
    if (!poseDone_[k]) {
      poses_[k] = bodyPose(layout_, b, y_);
      poseDone_[k] = 1;
    }
    return poses_[k];
  }

  // State of a marker (markerState). By value: the uncached path has no storage.
  MarkerState<T> marker(int id) {
    const int k = slots_ != nullptr ? slots_->marker[id] : -1;
    if (k < 0) return markerState(m_, layout_, id, y_);
    if (!markerDone_[k]) {
      const model::Marker& mk = m_.markers[id];
      const int body = m_.parts[mk.part].body;
      markers_[k] = body < 0 ? markerState(m_, layout_, id, y_) : markerStateOnBody(mk, pose(body));
      markerDone_[k] = 1;
    }
    return markers_[k];
  }

 private:
  const model::Model& m_;
  const StateLayout& layout_;
  const T* y_;
  const ContactSlots* slots_;
  std::vector<BodyPose<T>> poses_;
  std::vector<char> poseDone_;
  std::vector<MarkerState<T>> markers_;
  std::vector<char> markerDone_;
};

}  // namespace openmss::mechanics::contact
