#pragma once
// One physical input line, prepared for the statement parser: the line terminator, a '!'
// comment and trailing blanks are removed, and a final '&' (continuation) is taken off and
// remembered. What is left is the statement text of the line; the five-blank comment rule is
// applied later by the parser because it does not hold inside expressions and text.
// The text is a view into the raw line: whoever prepares lines keeps their text alive while the
// lines are parsed (a data set's whole file, reader.cpp; a command's pending lines,
// command_reader.cpp), so a data set's lines are not copied (docs/performance.md).

#include <string>
#include <string_view>
#include <vector>

namespace openmss::language {

struct SourceLine {
  int number = 0;                  // 1-based physical line number
  std::string_view text;           // statement text (see above), a view into the raw line
  bool endsWithAmpersand = false;  // the statement text ended with '&'
  int ampersandColumn = 0;         // 1-based column of that '&'
  int rawLength = 0;               // characters on the line, terminator excluded

  bool blank() const { return text.find_first_not_of(" \t") == std::string_view::npos; }
  // 1-based column of the first non-blank character (0 when blank). A tab counts as one.
  int firstColumn() const;
};

SourceLine prepareLine(std::string_view raw, int number);

// Splits text into physical lines; "\r\n", "\n" and a lone "\r" all end a line.
std::vector<std::string_view> splitPhysicalLines(std::string_view text);

inline bool isBlank(char c) { return c == ' ' || c == '\t'; }

}  // namespace openmss::language
