#pragma once
// What the corpus tests ask of a real data set and its command file (tests/analysis and
// tests/app): the statements the model builder rejects, and the model a command file loads.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <string>

#include "common/diagnostics.hpp"
#include "language/reader.hpp"
#include "model/model_builder.hpp"

namespace openmss::testing {

// The statements the builder rejected (their names; "(reader)" for reader errors), empty when
// the model is usable.
inline std::set<std::string> rejectedStatements(const std::filesystem::path& adm) {
  Diagnostics diags;
  language::Dataset dataset;
  language::readDatasetFile(adm.string(), dataset, diags);
  model::Model m;
  model::buildModel(dataset, m, diags);
  std::set<std::string> names;
  for (const auto& d : diags.all())
    if (d.severity == Severity::Error)
      names.insert(d.subject.empty() ? "(reader)" : d.subject.substr(0, d.subject.find('/')));
  return names;
}

// The model a command file's text loads: FILE/MODEL=name, else line 1 (the classic layout);
// carriage returns and surrounding blanks removed.
inline std::string modelNameOf(std::string acf) {
  acf.erase(std::remove(acf.begin(), acf.end(), '\r'), acf.end());
  auto trim = [](std::string s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.erase(0, 1);
    return s;
  };
  std::string lower = acf;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (const auto p = lower.find("file/model="); p != std::string::npos)
    return trim(acf.substr(p + 11, acf.find('\n', p) - p - 11));
  return trim(acf.substr(0, acf.find('\n')));
}

}  // namespace openmss::testing
