#pragma once
// Kinematic loops of a model (docs/theory.md §5, "Loops"): the graph whose vertices are the parts (ground
// included) and whose edges are the joints and joint primitives. The number of independent
// loops is the graph's cyclomatic number, edges - vertices + connected components; every other
// closed chain of parts is a dependent loop (a combination of independent ones).

#include "model/model.hpp"

namespace openmss::mechanics {

struct LoopCount {
  int independent = 0;
  int dependent = 0;       // simple cycles that are not counted as independent
  bool enumerated = true;  // false when there are too many independent loops to list cycles
};

LoopCount countLoops(const model::Model& model);

}  // namespace openmss::mechanics
