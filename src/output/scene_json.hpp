#pragma once
// The scene of a model for the browser viewer (docs/viewer.md, "scene.json"): the parts with
// their initial poses, every drawn GRAPHICS with its geometry in part coordinates, and every
// marker (the viewer's triads). A small fixed JSON layout written by hand: no JSON library.

#include <ostream>
#include <string>
#include <vector>

#include "model/graphics.hpp"
#include "model/model.hpp"

namespace openmss::output {

// Writes the scene of `model` as one JSON object. Numbers are printed with 17 significant
// digits, so the same model always gives the same bytes.
void writeSceneJson(const model::Model& model, const std::vector<model::Graphic>& graphics,
                    std::ostream& out);

// `text` as a JSON string literal (quotes, backslashes and control characters escaped).
std::string jsonString(const std::string& text);

}  // namespace openmss::output
