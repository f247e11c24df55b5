#include "model/graphics_builder.hpp"

#include <map>
#include <numbers>

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// Defaults where the GRAPHICS arguments are left out (docs/viewer.md, "Geometry": the ADAMS
// pages list the arguments, not these values; 20 facets and a full turn are our choice).
constexpr int kDefaultSides = 20;
constexpr double kFullTurn = 2.0 * std::numbers::pi;

int integerOr(const Statement& g, const char* name, int fallback) {
  const Argument* a = g.find(name);
  return a && !a->values.empty() ? static_cast<int>(a->values[0].number) : fallback;
}

// A size that must not be negative (RADIUS, XSCALE, ...); 0 is accepted, drawn flat or as a
// point, since real data sets carry such graphics (a CYLINDER of LENGTH 0 is a disc). False
// after an error.
bool size(const Statement& g, const char* name, bool required, double& out, Diagnostics& diags) {
  const Argument* a = g.find(name);
  if (!a || a->values.empty()) {
    if (!required) return true;
    diags.error(g.where, g.subject(), std::string("the ") + name + " of the graphic is missing",
                std::string("Add ") + name + "=<number >= 0>.");
    return false;
  }
  out = a->values[0].number;
  if (out >= 0.0) return true;
  diags.error(a->where, g.subject(), std::string(name) + " must not be negative",
              std::string("Give ") + name + " >= 0.");
  return false;
}

// CYLINDER and FRUSTUM: LENGTH (signed), the radii, RANGLE and SIDES.
bool readRound(const Statement& g, Graphic& out, Diagnostics& diags) {
  bool ok = true;
  if (!g.has("LENGTH")) {
    diags.error(g.where, g.subject(), "the LENGTH of the graphic is missing",
                "Add LENGTH=<number> (negative: along -z).");
    ok = false;
  }
  out.length = graphicsNumber(g, "LENGTH");
  if (out.kind == Graphic::Kind::Cylinder) {
    ok = size(g, "RADIUS", true, out.radius, diags) && ok;
  } else {  // a frustum may close to a cone at either end
    ok = size(g, "TOP", true, out.top, diags) && ok;
    ok = size(g, "BOTTOM", true, out.bottom, diags) && ok;
  }
  out.rangle = g.has("RANGLE") ? graphicsNumber(g, "RANGLE") : kFullTurn;
  out.sides = integerOr(g, "SIDES", kDefaultSides);
  return ok;
}

// One drawn GRAPHICS statement; false after an error.
bool readGraphic(const Statement& g, const std::string& kind, const Model& model, Graphic& out,
                 Diagnostics& diags) {
  out.id = g.id.value_or(0);
  out.where = g.where;
  const std::string subject = g.subject();
  if (kind == "OUTLINE") {
    out.kind = Graphic::Kind::Outline;
    for (const language::Value& v : g.find("OUTLINE")->values) {
      const auto it = model.markerIndex.find(static_cast<long>(v.number));
      if (it == model.markerIndex.end()) {
        diags.error(v.where, subject,
                    "OUTLINE names MARKER/" + std::to_string(static_cast<long>(v.number)) +
                        ", which does not exist",
                    "Use the ids of MARKER statements of this data set.");
        return false;
      }
      out.outline.push_back(it->second);
    }
    if (out.outline.size() < 2) {
      diags.error(g.where, subject, "an OUTLINE needs at least two markers",
                  "List two or more markers in OUTLINE.");
      return false;
    }
    out.part = model.markers[out.outline.front()].part;
    return true;
  }
  bool ok = true;
  if (kind == "BOX") {
    out.kind = Graphic::Kind::Box;
    out.marker = graphicsMarker(g, "CORNER", model, g.where, subject, diags);
    // Signed extents; a 0 extent draws a flat face.
    out.extents = {graphicsNumber(g, "X"), graphicsNumber(g, "Y"), graphicsNumber(g, "Z")};
  } else {
    out.marker = graphicsMarker(g, "CM", model, g.where, subject, diags);
    if (kind == "CYLINDER" || kind == "FRUSTUM") {
      out.kind = kind == "CYLINDER" ? Graphic::Kind::Cylinder : Graphic::Kind::Frustum;
      ok = readRound(g, out, diags);
    } else if (kind == "ELLIPSOID") {
      out.kind = Graphic::Kind::Ellipsoid;
      ok = size(g, "XSCALE", true, out.extents.x(), diags) &&
           size(g, "YSCALE", true, out.extents.y(), diags) &&
           size(g, "ZSCALE", true, out.extents.z(), diags);
    } else {  // ARC or CIRCLE
      out.kind = kind == "ARC" ? Graphic::Kind::Arc : Graphic::Kind::Circle;
      ok = size(g, "RADIUS", true, out.radius, diags);
      out.rangle = kind == "ARC" && g.has("RANGLE") ? graphicsNumber(g, "RANGLE") : kFullTurn;
      out.sides = integerOr(g, "SEG", kDefaultSides);
    }
  }
  if (out.marker < 0 || !ok) return false;
  const Marker& m = model.markers[out.marker];
  out.part = m.part;
  out.position = m.position;
  out.orientation = m.orientation;
  return true;
}

bool drawn(const std::string& kind) {
  for (const char* k : {"CYLINDER", "FRUSTUM", "BOX", "ELLIPSOID", "OUTLINE", "ARC", "CIRCLE"})
    if (kind == k) return true;
  return false;
}

}  // namespace

std::string graphicsKind(const Statement& g) {
  for (const char* kind : {"ELLIPSOID", "BOX", "CYLINDER", "FRUSTUM", "TORUS", "EXTERNAL", "PLANE",
                           "ARC", "CIRCLE", "CURVE", "POINT", "SPDP", "FORCE"})
    if (g.has(kind)) return kind;
  if (g.has("OUTLINE")) return "OUTLINE";
  return "";
}

double graphicsNumber(const Statement& g, const char* name) {
  const Argument* a = g.find(name);
  return a && !a->values.empty() ? a->values[0].number : 0.0;
}

std::string graphicsAt(const Statement& g) {
  return g.subject() + " (line " + std::to_string(g.where.line) + ")";
}

int graphicsMarker(const Statement& g, const char* name, const Model& model,
                   const SourceLocation& where, const std::string& subject, Diagnostics& diags) {
  const Argument* a = g.find(name);
  if (!a || a->values.empty()) {
    diags.error(where, subject, graphicsAt(g) + " has no " + name + "= marker to place it",
                std::string("Add ") + name + "=<marker id> to " + g.subject() + ".");
    return -1;
  }
  const long id = static_cast<long>(a->values[0].number);
  const auto it = model.markerIndex.find(id);
  if (it == model.markerIndex.end()) {
    diags.error(a->where, g.subject(),
                std::string(name) + "=" + std::to_string(id) + " names no marker",
                "Use the id of a MARKER statement of this data set.");
    return -1;
  }
  return it->second;
}

std::vector<Graphic> buildGraphics(const language::Dataset& dataset, const Model& model,
                                   Diagnostics& diags) {
  std::vector<Graphic> graphics;
  // The kinds not drawn: one warning per kind at its first statement, with the count, so a
  // data set with a hundred EXTERNAL shells gets one line, not a hundred.
  std::map<std::string, std::pair<const Statement*, int>> skipped;
  for (const Statement& g : dataset.statements) {
    if (g.name != "GRAPHICS") continue;
    const std::string kind = graphicsKind(g);
    if (!drawn(kind)) {
      auto& [first, count] = skipped[kind.empty() ? "no kind" : kind];
      if (!first) first = &g;
      ++count;
      continue;
    }
    Graphic graphic;
    if (readGraphic(g, kind, model, graphic, diags)) graphics.push_back(graphic);
  }
  for (const auto& [kind, entry] : skipped)
    diags.warning(entry.first->where, entry.first->subject(),
                  std::to_string(entry.second) + " GRAPHICS of kind " + kind +
                      " (this one first) are not drawn by the viewer nor written to the .gra "
                      "file; drawn kinds: CYLINDER, FRUSTUM, BOX, ELLIPSOID, OUTLINE, ARC, CIRCLE",
                  "Nothing to change for the analysis; the viewer shows the other graphics.");
  return graphics;
}

const char* graphicKindName(Graphic::Kind kind) {
  switch (kind) {
    case Graphic::Kind::Cylinder:
      return "CYLINDER";
    case Graphic::Kind::Frustum:
      return "FRUSTUM";
    case Graphic::Kind::Box:
      return "BOX";
    case Graphic::Kind::Ellipsoid:
      return "ELLIPSOID";
    case Graphic::Kind::Outline:
      return "OUTLINE";
    case Graphic::Kind::Arc:
      return "ARC";
    case Graphic::Kind::Circle:
      return "CIRCLE";
  }
  return "?";
}

}  // namespace openmss::model
