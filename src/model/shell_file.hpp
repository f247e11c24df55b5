#pragma once
// Readers of the external shells a CONTACT may use (docs/theory.md §6c, "Meshes"): the ADAMS
// shell (.shl) and STL (ASCII or binary). File formats stay in the model layer; the contact
// code sees a TriangleMesh only.

#include <optional>
#include <string>

#include "model/triangle_mesh.hpp"

namespace openmss::model {

// The mesh in `path`, or nullopt with `why` saying what is wrong (unreadable, malformed: the
// first fault found, with its line for text files). The kind is chosen by the extension
// (.shl, .stl; any case).
std::optional<TriangleMesh> readShellFile(const std::string& path, std::string& why);

}  // namespace openmss::model
