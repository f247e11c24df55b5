#include "language/source_line.hpp"

namespace openmss::language {

int SourceLine::firstColumn() const {
  auto p = text.find_first_not_of(" \t");
  return p == std::string_view::npos ? 0 : static_cast<int>(p) + 1;
}

SourceLine prepareLine(std::string_view raw, int number) {
  SourceLine line;
  line.number = number;
  line.rawLength = static_cast<int>(raw.size());
  // '!' starts a comment unless it is inside a double-quoted string (CNAMES="a!b").
  bool inQuotes = false;
  size_t end = raw.size();
  for (size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == '"') inQuotes = !inQuotes;
    if (raw[i] == '!' && !inQuotes) {
      end = i;
      break;
    }
  }
  while (end > 0 && (isBlank(raw[end - 1]) || raw[end - 1] == '\r')) --end;
  if (end > 0 && raw[end - 1] == '&') {
    line.endsWithAmpersand = true;
    line.ampersandColumn = static_cast<int>(end);
    --end;
    while (end > 0 && isBlank(raw[end - 1])) --end;
  }
  line.text = raw.substr(0, end);
  return line;
}

std::vector<std::string_view> splitPhysicalLines(std::string_view text) {
  std::vector<std::string_view> lines;
  size_t start = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\n' && text[i] != '\r') continue;
    lines.push_back(text.substr(start, i - start));
    if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    start = i + 1;
  }
  if (start < text.size()) lines.push_back(text.substr(start));
  return lines;
}

}  // namespace openmss::language
