#include "api/model_info.hpp"

#include "analysis/model_summary.hpp"
#include "language/reader.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"

namespace openmss::api {
namespace {

const char* kindName(model::Request::Kind k) {
  switch (k) {
    case model::Request::Kind::Displacement:
      return "displacement";
    case model::Request::Kind::Velocity:
      return "velocity";
    case model::Request::Kind::Acceleration:
      return "acceleration";
    case model::Request::Kind::Force:
      return "force";
    case model::Request::Kind::Expressions:
      return "expressions";
  }
  return "expressions";
}

long markerId(const model::Model& m, int index) {
  return index >= 0 && index < static_cast<int>(m.markers.size()) ? m.markers[index].id : 0;
}

}  // namespace

ModelInfo loadModel(const std::string& path) {
  ModelInfo info;
  info.path = path;
  Diagnostics diags;
  language::Dataset ds;
  language::readDatasetFile(path, ds, diags);
  model::Model m;
  // Built even after reading errors, so that one pass reports the model-level errors too.
  const bool built = model::buildModel(ds, m, diags);
  info.diagnostics = toRecords(diags);
  info.title = ds.title;
  if (!built || diags.hasErrors()) return info;
  info.ok = true;
  for (const auto& p : m.parts)
    info.parts.push_back({p.id, "PART/" + std::to_string(p.id), p.ground, p.mass});
  for (const auto& r : m.requests)
    info.requests.push_back({r.id,
                             r.comment.empty() ? "REQUEST/" + std::to_string(r.id) : r.comment,
                             kindName(r.kind), markerId(m, r.iMarker), markerId(m, r.jMarker)});
  mechanics::MultibodySystem system(m);
  const Eigen::VectorXd y = system.initialState();
  const analysis::DegreeOfFreedomCount dof = analysis::countDegreesOfFreedom(system, y);
  info.degreesOfFreedom = dof.degreesOfFreedom;
  info.grueblerCount = dof.gruebler;
  return info;
}

}  // namespace openmss::api
