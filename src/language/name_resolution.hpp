#pragma once
// Resolving a written (possibly abbreviated) name against a list of canonical names, with the
// ADAMS rule: an exact name or alias wins; otherwise the written text must be a prefix of a
// name and at least that name's minimum abbreviation long; one match resolves, several are
// ambiguous.

#include <string>
#include <string_view>
#include <vector>

namespace openmss::language {

struct NameCandidate {
  std::string_view name;
  int minAbbreviation = 1;
  const std::vector<std::string>* aliases = nullptr;
};

struct NameResolution {
  enum class Status { Resolved, Ambiguous, Unknown };
  Status status = Status::Unknown;
  int index = -1;                      // into the candidate list when Resolved
  std::vector<std::string> ambiguous;  // the matching names when Ambiguous
};

// `written` must already be upper case.
NameResolution resolveName(std::string_view written, const std::vector<NameCandidate>& candidates);

// Shortest prefix length that tells `name` apart from every other name in `names`
// (never more than the name's length).
int shortestUniquePrefix(std::string_view name, const std::vector<std::string_view>& names);

std::string toUpper(std::string_view s);

}  // namespace openmss::language
