#include "output/scene_json.hpp"

#include <cstdio>

namespace openmss::output {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v == 0.0 ? 0.0 : v);  // no "-0"
  return buf;
}

std::string vec(const Eigen::Vector3d& v) {
  return "[" + num(v.x()) + "," + num(v.y()) + "," + num(v.z()) + "]";
}

// A rotation matrix row by row (9 numbers): the viewer never converts angles of its own.
std::string mat(const Eigen::Matrix3d& m) {
  std::string s = "[";
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) s += (r || c ? "," : "") + num(m(r, c));
  return s + "]";
}

long partId(const model::Model& model, int part) { return part >= 0 ? model.parts[part].id : 0; }

void writeGraphic(const model::Model& model, const model::Graphic& g, std::ostream& out) {
  using Kind = model::Graphic::Kind;
  out << "{\"id\":" << g.id << ",\"kind\":\"" << model::graphicKindName(g.kind)
      << "\",\"part\":" << partId(model, g.part);
  if (g.kind == Kind::Outline) {
    out << ",\"points\":[";
    for (std::size_t i = 0; i < g.outline.size(); ++i) {
      const model::Marker& m = model.markers[g.outline[i]];
      out << (i ? "," : "") << "{\"marker\":" << m.id << ",\"part\":" << partId(model, m.part)
          << ",\"position\":" << vec(m.position) << "}";
    }
    out << "]}";
    return;
  }
  out << ",\"marker\":" << model.markers[g.marker].id << ",\"position\":" << vec(g.position)
      << ",\"orientation\":" << mat(g.orientation);
  switch (g.kind) {
    case Kind::Cylinder:
      out << ",\"radius\":" << num(g.radius) << ",\"length\":" << num(g.length);
      break;
    case Kind::Frustum:
      out << ",\"top\":" << num(g.top) << ",\"bottom\":" << num(g.bottom)
          << ",\"length\":" << num(g.length);
      break;
    case Kind::Box:
      out << ",\"extents\":" << vec(g.extents);
      break;
    case Kind::Ellipsoid:
      out << ",\"diameters\":" << vec(g.extents);
      break;
    case Kind::Arc:
    case Kind::Circle:
      out << ",\"radius\":" << num(g.radius);
      break;
    case Kind::Outline:
      break;
  }
  if (g.kind != Kind::Box && g.kind != Kind::Ellipsoid)
    out << ",\"rangle\":" << num(g.rangle) << ",\"sides\":" << g.sides;
  out << "}";
}

}  // namespace

std::string jsonString(const std::string& text) {
  std::string s = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      s += '\\';
      s += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      s += buf;
    } else {
      s += c;
    }
  }
  return s + "\"";
}

void writeSceneJson(const model::Model& model, const std::vector<model::Graphic>& graphics,
                    std::ostream& out) {
  out << "{\"format\":\"openmss-scene\",\"version\":1,\"title\":" << jsonString(model.title)
      << ",\"units\":{\"length\":" << jsonString(model.units.length)
      << ",\"time\":" << jsonString(model.units.time) << "},\n\"parts\":[";
  for (std::size_t i = 0; i < model.parts.size(); ++i) {
    const model::Part& p = model.parts[i];
    out << (i ? ",\n" : "\n") << "{\"id\":" << p.id
        << ",\"ground\":" << (p.ground ? "true" : "false") << ",\"position\":" << vec(p.position)
        << ",\"orientation\":" << mat(p.orientation) << "}";
  }
  out << "],\n\"markers\":[";
  bool first = true;
  for (const model::Marker& m : model.markers) {
    if (m.floating) continue;  // no fixed pose on its part
    out << (first ? "\n" : ",\n") << "{\"id\":" << m.id << ",\"part\":" << partId(model, m.part)
        << ",\"position\":" << vec(m.position) << ",\"orientation\":" << mat(m.orientation) << "}";
    first = false;
  }
  out << "],\n\"graphics\":[";
  for (std::size_t i = 0; i < graphics.size(); ++i) {
    out << (i ? ",\n" : "\n");
    writeGraphic(model, graphics[i], out);
  }
  out << "]}\n";
}

}  // namespace openmss::output
