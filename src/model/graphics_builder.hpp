#pragma once
// Dataset -> Model for GRAPHICS (docs/viewer.md, "Geometry"): every drawn kind becomes a
// Graphic on the part of its reference marker; the kinds not drawn are named in one warning
// each. The readers of one GRAPHICS statement are shared with CONTACT (contact_builder.cpp),
// which takes its solids from the same statements.

#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/graphics.hpp"
#include "model/model.hpp"

namespace openmss::model {

// The drawn graphics of every GRAPHICS statement of `dataset`, on the parts and markers of
// `model` (built from that data set), with a located error for bad data and one warning per
// kind not drawn. The Model does not keep them: no analysis needs them; buildModel calls this
// to check the statements, the writers that draw (output/scene_json) call it for the geometry.
std::vector<Graphic> buildGraphics(const language::Dataset& dataset, const Model& model,
                                   Diagnostics& diags);

// The kind keyword of a GRAPHICS statement (CYLINDER, BOX, ..., OUTLINE), "" when none.
std::string graphicsKind(const language::Statement& g);
// The first value of the real argument `name`, 0 when absent.
double graphicsNumber(const language::Statement& g, const char* name);
// "GRAPHICS/5 (line 12)": how diagnostics of another statement name a GRAPHICS statement.
std::string graphicsAt(const language::Statement& g);
// The reference marker of a GRAPHICS statement (CM= or CORNER=) as an index; -1 after an error
// reported at `where` for `subject` (the GRAPHICS statement itself, or the CONTACT naming it).
int graphicsMarker(const language::Statement& g, const char* name, const Model& model,
                   const SourceLocation& where, const std::string& subject, Diagnostics& diags);

}  // namespace openmss::model
