#include "language/name_resolution.hpp"

#include <algorithm>
#include <cctype>

#include "common/ascii_case.hpp"

namespace openmss::language {

std::string toUpper(std::string_view s) { return toUpperAscii(s); }

NameResolution resolveName(std::string_view written, const std::vector<NameCandidate>& candidates) {
  NameResolution result;
  if (written.empty()) return result;
  for (size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    bool exact = c.name == written;
    if (!exact && c.aliases)
      exact = std::find(c.aliases->begin(), c.aliases->end(), written) != c.aliases->end();
    if (exact) {
      result.status = NameResolution::Status::Resolved;
      result.index = static_cast<int>(i);
      result.ambiguous.clear();
      return result;
    }
  }
  std::vector<int> matches;
  for (size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    if (static_cast<int>(written.size()) >= c.minAbbreviation && written.size() <= c.name.size() &&
        c.name.substr(0, written.size()) == written)
      matches.push_back(static_cast<int>(i));
  }
  if (matches.size() == 1) {
    result.status = NameResolution::Status::Resolved;
    result.index = matches.front();
  } else if (matches.size() > 1) {
    result.status = NameResolution::Status::Ambiguous;
    for (int m : matches) result.ambiguous.emplace_back(candidates[m].name);
  } else {
    // Too short for any name's minimum but the start of several ("MA" for MARKER, MATERIAL,
    // MATRIX): calling it ambiguous tells the user what to add.
    std::vector<std::string> prefixOf;
    for (const auto& c : candidates)
      if (written.size() <= c.name.size() && c.name.substr(0, written.size()) == written)
        prefixOf.emplace_back(c.name);
    if (prefixOf.size() > 1) {
      result.status = NameResolution::Status::Ambiguous;
      result.ambiguous = std::move(prefixOf);
    }
  }
  return result;
}

int shortestUniquePrefix(std::string_view name, const std::vector<std::string_view>& names) {
  size_t longestShared = 0;
  for (auto other : names) {
    if (other == name) continue;
    size_t k = 0;
    while (k < name.size() && k < other.size() && name[k] == other[k]) ++k;
    longestShared = std::max(longestShared, k);
  }
  return static_cast<int>(std::min(name.size(), longestShared + 1));
}

}  // namespace openmss::language
