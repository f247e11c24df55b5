// CompactString and CompactLocation (common/compact_string.hpp, common/compact_location.hpp):
// the 16- and 12-byte forms of the parsed statement tree's names, tokens and locations keep
// every character and every location, at every length around the in-place limit.

#include "common/compact_string.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <utility>

#include "common/compact_location.hpp"

namespace openmss {
namespace {

TEST(CompactString, KeepsEveryLengthAroundTheInPlaceLimit) {
  // 15 characters are stored in place (the last byte is then the terminating NUL), 16 and more
  // on the heap: both sides of the limit, and the empty string.
  for (size_t n : {0u, 1u, 7u, 14u, 15u, 16u, 17u, 40u, 1000u}) {
    std::string s;
    for (size_t k = 0; k < n; ++k) s += static_cast<char>('A' + k % 26);
    const CompactString c(s);
    EXPECT_EQ(c.size(), n);
    EXPECT_EQ(c.empty(), n == 0);
    EXPECT_EQ(std::string(c.c_str()), s) << "c_str() is NUL-terminated";
    EXPECT_EQ(c.str(), s);
    EXPECT_TRUE(c == s);
    // Copies and moves keep the text; the moved-from string is empty.
    CompactString copy = c;
    EXPECT_EQ(copy.str(), s);
    CompactString moved = std::move(copy);
    EXPECT_EQ(moved.str(), s);
    EXPECT_TRUE(copy.empty());  // NOLINT(bugprone-use-after-move): defined as empty
    // Assignment over a string of the other kind (in place <-> heap) frees and replaces.
    CompactString other("a string longer than fifteen characters");
    other = c;
    EXPECT_EQ(other.str(), s);
    other = "short";
    EXPECT_EQ(other.str(), "short");
    other = std::move(moved);
    EXPECT_EQ(other.str(), s);
  }
}

TEST(CompactString, ReadsLikeAStdString) {
  const CompactString name("MARKER");
  EXPECT_EQ(name, "MARKER");
  EXPECT_NE(name, "MARK");
  EXPECT_EQ(name, std::string("MARKER"));
  EXPECT_EQ(std::string_view(name), "MARKER");
  EXPECT_EQ("missing " + name + "/1", "missing MARKER/1");
  EXPECT_EQ(name + '/' + std::string("2"), "MARKER/2");
  EXPECT_EQ(name.substr(0, 3), "MAR");
  EXPECT_EQ(name.find('K'), 3u);
  EXPECT_TRUE(name < CompactString("PART"));
  std::string s = name;
  s += name;
  EXPECT_EQ(s, "MARKERMARKER");
  std::ostringstream out;
  out << name;
  EXPECT_EQ(out.str(), "MARKER");
  static_assert(sizeof(CompactString) == 16);
}

TEST(CompactLocation, ConvertsBackToTheFullLocation) {
  const CompactLocation a("model.adm", 12, 7);
  const SourceLocation full = a;
  EXPECT_EQ(full.file, "model.adm");
  EXPECT_EQ(full.line, 12);
  EXPECT_EQ(full.column, 7);
  // One index per file name, the same for every location in it.
  const CompactLocation b(std::string("model.adm"), 13, 1);
  EXPECT_EQ(a.fileIndex, b.fileIndex);
  const CompactLocation c("/a/long/directory/name/other.adm", 1, 1);
  EXPECT_NE(c.fileIndex, a.fileIndex);
  EXPECT_EQ(c.file(), "/a/long/directory/name/other.adm");
  EXPECT_EQ(CompactLocation(full).full().file, "model.adm");
  // The default names no file and no line, as a default SourceLocation does.
  const SourceLocation none = CompactLocation();
  EXPECT_EQ(none.file, "");
  EXPECT_FALSE(none.known());
  static_assert(sizeof(CompactLocation) == 12);
}

}  // namespace
}  // namespace openmss
