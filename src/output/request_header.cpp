#include "output/request_header.hpp"

namespace openmss::output {

RequestFileHeader requestFileHeader(const model::Model& m, bool* unitsKnown) {
  RequestFileHeader h;
  h.title = m.title;
  const auto u = requestFileUnits(m.units.length, m.units.mass, m.units.time, m.units.force);
  if (u) {
    h.unitsToken = u->token;
    h.lengthScale = u->lengthScale;
  }
  if (unitsKnown) *unitsKnown = u.has_value();
  return h;
}

std::vector<RequestEntry> requestEntries(const model::Model& m) {
  std::vector<RequestEntry> entries;
  for (const auto& r : m.requests) {
    RequestEntry e;
    e.id = r.id;
    using RK = model::Request::Kind;
    e.type = r.kind == RK::Displacement   ? kDisplacementRequest
             : r.kind == RK::Velocity     ? kVelocityRequest
             : r.kind == RK::Acceleration ? kAccelerationRequest
             : r.kind == RK::Force        ? kForceRequest
                                          : kExpressionRequest;
    if (r.kind != RK::Expressions) {
      e.iMarker = m.markers[r.iMarker].id;
      e.jMarker = r.jMarker >= 0 ? m.markers[r.jMarker].id : 0;
    }
    e.comment = r.comment;
    entries.push_back(e);
  }
  return entries;
}

}  // namespace openmss::output
