#include "output/graphics_file.hpp"

#include <cerrno>
#include <cstring>
#include <set>

#include "common/rotation.hpp"

namespace openmss::output {
namespace {

std::string padded(std::string s, std::size_t width) {
  s.resize(width, ' ');
  return s;
}

// Up to five sizes of a graphic, in the order docs/output-files.md lists per kind.
std::vector<double> sizes(const model::Graphic& g) {
  using Kind = model::Graphic::Kind;
  switch (g.kind) {
    case Kind::Cylinder:
      return {g.length, g.radius, g.rangle, static_cast<double>(g.sides)};
    case Kind::Frustum:
      return {g.length, g.bottom, g.top, g.rangle, static_cast<double>(g.sides)};
    case Kind::Box:
    case Kind::Ellipsoid:
      return {g.extents.x(), g.extents.y(), g.extents.z()};
    case Kind::Arc:
    case Kind::Circle:
      return {g.radius, g.rangle, static_cast<double>(g.sides)};
    case Kind::Outline:
      return {static_cast<double>(g.outline.size())};
  }
  return {};
}

}  // namespace

int graphicsKindCode(model::Graphic::Kind kind) { return static_cast<int>(kind) + 1; }

GraphicsFileWriter::~GraphicsFileWriter() { close(); }

bool GraphicsFileWriter::open(const std::string& path, const RequestFileHeader& header,
                              const model::Model& model,
                              const std::vector<model::Graphic>& graphics, std::string* error) {
  close();
  // Binary mode: LF line ends everywhere, so runs compare byte for byte.
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) {
    if (error) *error = "cannot create graphics file " + path + ": " + std::strerror(errno);
    return false;
  }
  // The markers the graphics use (reference markers and OUTLINE points), in model order.
  std::set<int> markers;
  for (const model::Graphic& g : graphics) {
    if (g.marker >= 0) markers.insert(g.marker);
    markers.insert(g.outline.begin(), g.outline.end());
  }
  std::fprintf(file_, " A.G8    %s  %s %.15E\n", header.stamp.c_str(), header.unitsToken.c_str(),
               header.lengthScale);
  std::fprintf(file_, "%s\n", padded(header.title, 80).c_str());
  // Counts: parts, markers, 0, 0, graphics, 0, 0, 0, moving parts (docs/output-files.md).
  movingParts_ = 0;
  for (const model::Part& p : model.parts) movingParts_ += p.body >= 0 ? 1 : 0;
  std::fprintf(file_, "%6zu%5zu%5d%5d%5zu%5d%5d%5d%5zu\n", model.parts.size(), markers.size(), 0, 0,
               graphics.size(), 0, 0, 0, movingParts_);
  for (const model::Part& p : model.parts)
    std::fprintf(file_, "%11ld%10d\n", p.id, p.body >= 0 ? 1 : 0);
  for (const model::Graphic& g : graphics)
    std::fprintf(file_, "%11ld%10d%10ld\n", g.id, graphicsKindCode(g.kind),
                 g.marker >= 0 ? model.markers[g.marker].id : 0L);
  for (const int k : markers) {
    const model::Marker& m = model.markers[k];
    const Eigen::Vector3d a = euler313FromMatrix(m.orientation);
    std::fprintf(file_, "%11ld%10ld%13.5E%13.5E%13.5E%8d\n", m.id, model.parts[m.part].id,
                 m.position.x(), m.position.y(), m.position.z(), 0);
    std::fprintf(file_, "%14.5E%13.5E%13.5E\n", a.x(), a.y(), a.z());
  }
  // An OpenMSS record per graphic: its sizes (and, for an OUTLINE, its marker ids).
  for (const model::Graphic& g : graphics) {
    std::fprintf(file_, "%11ld", g.id);
    for (const double v : sizes(g)) std::fprintf(file_, "%13.5E", v);
    for (const int k : g.outline) std::fprintf(file_, "%11ld", model.markers[k].id);
    std::fprintf(file_, "\n");
  }
  if (std::fflush(file_) != 0) {
    if (error) *error = "cannot write graphics file " + path + ": " + std::strerror(errno);
    close();
    return false;
  }
  return true;
}

void GraphicsFileWriter::writeStep(double time, const std::vector<GraphicsPose>& poses) {
  if (!file_) return;
  if (poses.size() != movingParts_) {
    error_ = "a step with " + std::to_string(poses.size()) + " part poses for " +
             std::to_string(movingParts_) + " moving parts was not written";
    return;
  }
  std::fprintf(file_, "%13.5E\n", time);
  for (const GraphicsPose& p : poses)
    std::fprintf(file_, "%13.5E%13.5E%13.5E%13.5E%13.5E%13.5E\n", p.position.x(), p.position.y(),
                 p.position.z(), p.angles.x(), p.angles.y(), p.angles.z());
  if (std::fflush(file_) != 0 && error_.empty()) error_ = std::strerror(errno);
}

void GraphicsFileWriter::close() {
  if (file_) std::fclose(file_);
  file_ = nullptr;
}

}  // namespace openmss::output
