#pragma once
// Where the tests find validation data (docs/validation.md, "Where the data is").
//
// * The nine ADAMS joint cases (models, command files and the outputs real ADAMS wrote) are in
//   the repository, tests/validation/adams-joints/ (README.md there gives their source and
//   licence): every clone runs the validation against ADAMS, and a test that reads them fails,
//   never skips, when a file is missing.
// * The corpus of real data sets is not in the repository. It is read from
//   OPENMSS_SHARED_DIR/validation/corpus (a CMake cache variable, ../shared by default); the
//   tests that read it skip, saying so, when it is absent.

#include <filesystem>
#include <string>

namespace openmss::testing {

inline std::filesystem::path adamsJointsDir() {
  return std::filesystem::path(OPENMSS_SOURCE_DIR) / "tests" / "validation" / "adams-joints";
}

// Defined in validation_data.cpp, the one source compiled with OPENMSS_SHARED_DIR.
std::filesystem::path corpusDir();

// The message of every test skipped for want of the corpus.
inline std::string corpusAbsentMessage() {
  return "the real-data corpus is absent (" + corpusDir().string() +
         "; configure with -DOPENMSS_SHARED_DIR=<folder holding validation/corpus>)";
}

}  // namespace openmss::testing
