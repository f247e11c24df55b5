#pragma once
// A source location of 12 bytes for the parsed statement tree (language/dataset.hpp): every
// argument and every value of a data set keeps one, and a SourceLocation repeats the file's
// path in each (32 bytes, and an allocation for a path over 15 characters). Here the path is an
// index into a table of the file names read by the process (docs/performance.md, "Memory of a
// parsed data set"); it converts back to a full SourceLocation for diagnostics.
//
// The table only grows (one entry per distinct file name, the paths of the files read); it is
// shared by all threads behind a mutex and never changes an entry, so a location read on one
// thread names the same file on every other.

#include <cstdint>
#include <string>
#include <string_view>

#include "common/source_location.hpp"

namespace openmss {

// The index of `file` in the process's table of file names (added when new); 0 is "".
std::uint32_t internFileName(std::string_view file);
// The file name of an index returned by internFileName.
const std::string& internedFileName(std::uint32_t index);

struct CompactLocation {
  std::uint32_t fileIndex = 0;  // internFileName's index of the file; 0: no file
  int line = 0;                 // 1-based physical line; 0 when unknown
  int column = 0;               // 1-based column; 0 when unknown

  CompactLocation() = default;
  // {"model.adm", 3, 10}: as a SourceLocation is written.
  CompactLocation(std::string_view file, int lineNumber, int columnNumber)
      : fileIndex(internFileName(file)), line(lineNumber), column(columnNumber) {}
  CompactLocation(const char* file, int lineNumber, int columnNumber)
      : CompactLocation(std::string_view(file), lineNumber, columnNumber) {}
  CompactLocation(const std::string& file, int lineNumber, int columnNumber)
      : CompactLocation(std::string_view(file), lineNumber, columnNumber) {}
  explicit CompactLocation(const SourceLocation& s)
      : CompactLocation(std::string_view(s.file), s.line, s.column) {}

  // A location in the file of an index interned before (the parser's hot path: no lookup).
  static CompactLocation inFile(std::uint32_t fileIdx, int lineNumber, int columnNumber) {
    CompactLocation c;
    c.fileIndex = fileIdx;
    c.line = lineNumber;
    c.column = columnNumber;
    return c;
  }

  const std::string& file() const { return internedFileName(fileIndex); }
  bool known() const { return line > 0; }
  SourceLocation full() const { return {file(), line, column}; }
  operator SourceLocation() const { return full(); }
};

static_assert(sizeof(CompactLocation) == 12);

}  // namespace openmss
