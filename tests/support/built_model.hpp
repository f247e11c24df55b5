#pragma once
// A model built from data-set text, with its diagnostics formatted one per line: the fixture of
// the model-builder unit tests (tests/model/*_builder_test.cpp) and of the user-routine tests
// (tests/user/, readAndBuildModel).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/reader.hpp"
#include "model/model.hpp"
#include "model/model_builder.hpp"

namespace openmss::testing {

struct BuiltModel {
  model::Model model;
  Diagnostics diags;
  bool ok = false;  // buildModel's verdict
  std::vector<std::string> messages() const {
    std::vector<std::string> out;
    for (const auto& d : diags.all()) out.push_back(format(d));
    return out;
  }
  const model::Marker& marker(long id) const { return model.markers.at(model.markerIndex.at(id)); }
  const model::Part& part(long id) const { return model.parts.at(model.partIndex.at(id)); }
};

// Reads `text` as the data set `file` (the reader must accept it: these tests are about the
// builder) and builds the model.
inline BuiltModel buildModelFromText(const std::string& text, const std::string& file) {
  BuiltModel b;
  language::Dataset dataset;
  language::readDatasetText(text, file, dataset, b.diags);
  EXPECT_FALSE(b.diags.hasErrors()) << "the reader must accept the data set";
  b.ok = model::buildModel(dataset, b.model, b.diags);
  return b;
}

// Reads and builds `text` as the data set `file` where either stage may refuse it (tests of
// statements whose errors the reader or the builder reports): true when the builder succeeds
// and neither stage reported an error; every diagnostic of both, one per line, is appended to
// *messages. Unlike buildModelFromText, a reader error is a result to check, not a failure.
inline bool readAndBuildModel(const std::string& text, const std::string& file, model::Model& m,
                              std::string* messages) {
  language::Dataset dataset;
  Diagnostics diags;
  language::readDatasetText(text, file, dataset, diags);
  const bool ok = model::buildModel(dataset, m, diags) && !diags.hasErrors();
  for (const auto& d : diags.all()) *messages += format(d) + "\n";
  return ok;
}

}  // namespace openmss::testing
