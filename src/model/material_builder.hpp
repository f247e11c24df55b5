#pragma once
// MATERIAL statements and the MATERIAL= of PART (docs/theory.md, "Parts as ADAMS accepts
// them"): read and checked as data. ADAMS/Solver takes a rigid part's mass and inertia from
// MASS and IP (ADAMS/View computes those from geometry and a material before it writes the
// data set), so no element of the model reads a material yet and the Model keeps none.

#include <optional>
#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"

namespace openmss::model {

struct Material {
  long id = 0;
  std::string name;  // NAME=, upper-cased as the reader keeps words
  std::optional<double> density, youngsModulus, poissonsRatio;
  SourceLocation where;
};

// The MATERIAL statements in data-set order (the first of a repeated id), each property
// checked, then every PART's MATERIAL= checked to name one by NAME (a warning otherwise: the
// reference has no effect).
std::vector<Material> readMaterials(const language::Dataset& dataset, Diagnostics& diags);

}  // namespace openmss::model
