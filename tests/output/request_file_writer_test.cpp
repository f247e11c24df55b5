// RequestFileWriter: byte layout against a file real ADAMS wrote, round trip through the reader,
// flushing, misuse and the units tokens.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "output/request_file.hpp"
#include "output/request_file_reader.hpp"
#include "support/validation_data.hpp"

namespace openmss::output {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> linesWithoutCr(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

// A fresh file name per test in the system temporary folder.
fs::path scratchFile(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() / "openmss-output-tests";
  fs::create_directories(folder);
  const fs::path path = folder / (name + ".req");
  fs::remove(path);
  return path;
}

std::vector<RequestEntry> twoEntries() {
  return {{1, kDisplacementRequest, 201, 101, "DISPLACEMENT"},
          {7, kExpressionRequest, 0, 0, "FORCES"}};
}

TEST(RequestFileWriter, ReproducesAdamsLayoutByteForByte) {
  const fs::path adamsFile =
      openmss::testing::adamsJointsDir() / "Revolute_Case01/test_Revolute_Case01_ADAMS.req";
  ASSERT_TRUE(fs::exists(adamsFile)) << adamsFile;

  std::string error;
  const auto adams = readRequestFile(adamsFile.string(), &error);
  ASSERT_TRUE(adams) << error;
  constexpr std::size_t kStepsCompared = 3;
  ASSERT_GE(adams->steps.size(), kStepsCompared);

  // The directory as the writer gets it from the model: comments as written in the .adm.
  const std::vector<RequestEntry> entries = {
      {1, 1, 201, 101, "DISPLACEMENT: X Y Z PSI THETA PHI (body-fixed-3-1-3)"},
      {2, 2, 201, 101, "VELOCITY X Y Z WX WY WZ"},
      {3, 3, 201, 101, "ACCELERATION X Y Z WDX WDY WDZ"},
      {4, 5, 0, 0, "EULER PARAMETERS"},
      {5, 5, 0, 0, "RForce X Y Z RTorque X Y Z"}};
  RequestFileHeader header;
  header.title = "ADAMS/View model name: test_Revolute_Case01";

  const fs::path ours = scratchFile("byte_layout");
  RequestFileWriter writer;
  ASSERT_TRUE(writer.open(ours.string(), header, entries, &error)) << error;
  for (std::size_t s = 0; s < kStepsCompared; ++s) {
    writer.writeStep(adams->steps[s].time, adams->steps[s].rows);
  }
  writer.close();
  ASSERT_FALSE(writer.failed()) << writer.error();

  const std::string oursText = readText(ours);
  EXPECT_EQ(oursText.find('\r'), std::string::npos) << "we write LF line ends";
  const std::vector<std::string> oursLines = linesWithoutCr(oursText);
  const std::vector<std::string> adamsLines = linesWithoutCr(readText(adamsFile));
  const std::size_t lineCount = 3 + 2 * entries.size() + kStepsCompared * (1 + entries.size());
  ASSERT_EQ(oursLines.size(), lineCount);
  ASSERT_GE(adamsLines.size(), lineCount);

  // Line 1: everything but the 19-character date stamp at columns 10-28.
  ASSERT_EQ(oursLines[0].size(), adamsLines[0].size());
  EXPECT_EQ(oursLines[0].substr(0, 9), adamsLines[0].substr(0, 9));
  EXPECT_EQ(oursLines[0].substr(28), adamsLines[0].substr(28));
  EXPECT_EQ(oursLines[0].substr(9, 19), "2000-01-01 00:00:00");
  for (std::size_t line = 1; line < lineCount; ++line) {
    EXPECT_EQ(oursLines[line], adamsLines[line]) << "line " << line + 1;
  }
}

TEST(RequestFileWriter, RoundTripsEveryValueToPrintedPrecision) {
  const std::vector<double> samples = {0.0,       -0.0,     1.0,         -1.0,         0.1,
                                       123456.7,  -9.80665, 5.85838e-16, -7.07107e-01, 1.0e-300,
                                       -1.0e-300, 1.0e300,  -2.5e-100,   3.14159e99,   42.0};
  const std::vector<RequestEntry> entries = twoEntries();
  RequestFileHeader header;
  header.title = "round trip";
  header.unitsToken = "MMKGS_N_RACA";
  header.lengthScale = 1.0e3;

  const fs::path path = scratchFile("round_trip");
  std::string error;
  std::vector<RequestFileStep> written;
  {
    RequestFileWriter writer;
    ASSERT_TRUE(writer.open(path.string(), header, entries, &error)) << error;
    for (std::size_t s = 0; s < samples.size(); ++s) {
      RequestFileStep step;
      step.time = 0.01 * static_cast<double>(s);
      for (std::size_t k = 0; k < entries.size(); ++k) {
        std::array<double, 6> row{};
        for (std::size_t c = 0; c < 6; ++c) row[c] = samples[(s + 3 * k + c) % samples.size()];
        step.rows.push_back(row);
      }
      writer.writeStep(step.time, step.rows);
      written.push_back(step);
    }
    ASSERT_FALSE(writer.failed()) << writer.error();
  }  // the destructor closes

  const auto read = readRequestFile(path.string(), &error);
  ASSERT_TRUE(read) << error;
  EXPECT_EQ(read->header.title, header.title);
  EXPECT_EQ(read->header.unitsToken, header.unitsToken);
  EXPECT_EQ(read->header.lengthScale, header.lengthScale);
  EXPECT_EQ(read->header.stamp, header.stamp);
  ASSERT_EQ(read->entries.size(), entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    EXPECT_EQ(read->entries[k].id, entries[k].id);
    EXPECT_EQ(read->entries[k].type, entries[k].type);
    EXPECT_EQ(read->entries[k].iMarker, entries[k].iMarker);
    EXPECT_EQ(read->entries[k].jMarker, entries[k].jMarker);
    EXPECT_EQ(read->entries[k].comment, entries[k].comment);
  }
  ASSERT_EQ(read->steps.size(), written.size());
  // Six significant digits: the printed value is within half a unit of the fifth decimal of
  // the mantissa, i.e. 5e-6 of the value (5e-5 for three-digit exponents, printed with one
  // digit less; these samples are exact in five digits anyway).
  constexpr double kPrintedRelative = 5.0e-6;
  for (std::size_t s = 0; s < written.size(); ++s) {
    EXPECT_NEAR(read->steps[s].time, written[s].time, kPrintedRelative * written[s].time);
    for (std::size_t k = 0; k < entries.size(); ++k) {
      for (std::size_t c = 0; c < 6; ++c) {
        // Written as given: displacement angles too (the caller supplies degrees).
        const double expected = written[s].rows[k][c];
        const double got = read->steps[s].rows[k][c];
        EXPECT_LE(std::abs(got - expected), kPrintedRelative * std::abs(expected))
            << "step " << s << " request " << k << " column " << c << ": " << got << " vs "
            << expected;
      }
    }
  }
}

TEST(RequestFileWriter, ValuesWithThreeDigitExponentsStaySeparatedByBlanks) {
  // The value -5.35523e-101 after another negative one: "%13.5E" printed the two as
  // "-1.00000E+00-5.35523E-101". Every record must split on whitespace into six numbers, keep
  // 79 columns, and read back at fixed columns to the printed five digits (relative 5e-5).
  const std::array<double, 6> row = {-1.0,          -5.35523e-101, 7.25e-150,
                                     -1.23456e+150, -0.0,          -9.99999e-100};
  const std::vector<RequestEntry> entries = {{1, kDisplacementRequest, 201, 101, "D"}};
  const fs::path path = scratchFile("three_digit_exponents");
  std::string error;
  {
    RequestFileWriter writer;
    ASSERT_TRUE(writer.open(path.string(), RequestFileHeader{}, entries, &error)) << error;
    writer.writeStep(-3.5e-120, {row});
    ASSERT_FALSE(writer.failed()) << writer.error();
  }
  const std::vector<std::string> lines = linesWithoutCr(readText(path));
  ASSERT_GE(lines.size(), 2u);
  const std::string& time = lines[lines.size() - 2];
  const std::string& record = lines.back();
  EXPECT_EQ(time, "  -3.5000E-120");
  EXPECT_EQ(record.size(), 79u) << record;
  std::istringstream fields(record);
  std::vector<double> numbers;
  std::string token;
  while (fields >> token) numbers.push_back(std::stod(token));
  ASSERT_EQ(numbers.size(), 6u) << record;
  const auto read = readRequestFile(path.string(), &error);
  ASSERT_TRUE(read) << error;
  ASSERT_EQ(read->steps.size(), 1u);
  EXPECT_EQ(read->steps[0].time, -3.5e-120);
  for (std::size_t c = 0; c < 6; ++c) {
    EXPECT_LE(std::abs(numbers[c] - row[c]), 5e-5 * std::abs(row[c])) << c << ": " << record;
    EXPECT_EQ(read->steps[0].rows[0][c], numbers[c]) << c;
  }
  // Values that fit keep ADAMS's six digits; a three-digit exponent costs one digit (and
  // -9.99999E-100 rounds to the five digits -1.0000E-99).
  EXPECT_EQ(record.substr(1, 13), " -1.00000E+00");
  EXPECT_EQ(record.substr(1 + 13, 13), " -5.3552E-101");
  EXPECT_EQ(record.substr(1 + 5 * 13, 13), "  -1.0000E-99") << record;
}

TEST(RequestFileWriter, EveryStepIsOnDiskBeforeClose) {
  const fs::path path = scratchFile("flushed");
  std::string error;
  RequestFileWriter writer;
  ASSERT_TRUE(writer.open(path.string(), RequestFileHeader{}, twoEntries(), &error)) << error;
  writer.writeStep(0.0, {{1, 2, 3, 4, 5, 6}, {7, 8, 9, 10, 11, 12}});
  writer.writeStep(0.5, {{1, 2, 3, 4, 5, 6}, {7, 8, 9, 10, 11, 12}});
  // Read while the writer is still open, as after a crash of the run.
  const auto read = readRequestFile(path.string(), &error);
  ASSERT_TRUE(read) << error;
  ASSERT_EQ(read->steps.size(), 2u);
  EXPECT_EQ(read->steps[1].time, 0.5);
  EXPECT_TRUE(writer.isOpen());
}

TEST(RequestFileWriter, RefusesAStepWithTheWrongNumberOfRows) {
  const fs::path path = scratchFile("wrong_rows");
  std::string error;
  RequestFileWriter writer;
  ASSERT_TRUE(writer.open(path.string(), RequestFileHeader{}, twoEntries(), &error)) << error;
  writer.writeStep(0.0, {{1, 2, 3, 4, 5, 6}, {7, 8, 9, 10, 11, 12}});
  EXPECT_FALSE(writer.failed());
  writer.writeStep(0.1, {{1, 2, 3, 4, 5, 6}});
  EXPECT_TRUE(writer.failed());
  EXPECT_NE(writer.error().find("1 rows for 2 requests"), std::string::npos) << writer.error();
  writer.close();
  // The file is still whole: the refused step left nothing behind.
  const auto read = readRequestFile(path.string(), &error);
  ASSERT_TRUE(read) << error;
  EXPECT_EQ(read->steps.size(), 1u);
}

TEST(RequestFileWriter, ReportsAFileThatCannotBeCreated) {
  RequestFileWriter writer;
  std::string error;
  EXPECT_FALSE(writer.open("/nonexistent-folder/x.req", RequestFileHeader{}, {}, &error));
  EXPECT_NE(error.find("/nonexistent-folder/x.req"), std::string::npos) << error;
  EXPECT_FALSE(writer.isOpen());
  writer.writeStep(0.0, {});
  EXPECT_TRUE(writer.failed());
}

TEST(RequestFileWriter, PadsCommentsToWholeWordsAndTitleToEightyColumns) {
  const fs::path path = scratchFile("padding");
  std::string error;
  RequestFileHeader header;
  header.title = "short title\r";  // a CR left over from a CRLF data set must not leak
  RequestFileWriter writer;
  ASSERT_TRUE(writer.open(path.string(), header,
                          {{1, 2, 3, 4, "ABCD"}, {2, 5, 0, 0, "ABCDE"}, {3, 5, 0, 0, ""}}, &error))
      << error;
  writer.close();
  const std::vector<std::string> lines = linesWithoutCr(readText(path));
  ASSERT_EQ(lines.size(), 9u);
  EXPECT_EQ(lines[1], "short title" + std::string(69, ' '));
  EXPECT_EQ(lines[2], "    3     M_KGS_N_RACA 1.000000000000000E+00");
  EXPECT_EQ(lines[3].substr(lines[3].size() - 2), " 1");
  EXPECT_EQ(lines[4], "ABCD");
  EXPECT_EQ(lines[5].substr(lines[5].size() - 2), " 2");
  EXPECT_EQ(lines[6], "ABCDE   ");
  EXPECT_EQ(lines[7].substr(lines[7].size() - 2), " 0");
  EXPECT_EQ(lines[8], "");
  const auto read = readRequestFile(path.string(), &error);
  ASSERT_TRUE(read) << error;
  ASSERT_EQ(read->entries.size(), 3u);
  EXPECT_EQ(read->entries[1].comment, "ABCDE");
  EXPECT_EQ(read->entries[2].comment, "");
}

TEST(RequestFileUnits, GivesTheTokensAdamsWrites) {
  const auto si = requestFileUnits("METER", "KILOGRAM", "SECOND", "NEWTON");
  ASSERT_TRUE(si);
  EXPECT_EQ(si->token, "M_KGS_N_RACA");
  EXPECT_EQ(si->lengthScale, 1.0);

  const auto mm = requestFileUnits("MILLIMETER", "KILOGRAM", "SECOND", "NEWTON");
  ASSERT_TRUE(mm);
  EXPECT_EQ(mm->token, "MMKGS_N_RACA");
  EXPECT_EQ(mm->lengthScale, 1.0e3);

  const auto cm = requestFileUnits("CENTIMETER", "KILOGRAM", "SECOND", "NEWTON");
  ASSERT_TRUE(cm);
  EXPECT_EQ(cm->token, "CMKGS_N_RACA");
  EXPECT_EQ(cm->lengthScale, 1.0e2);

  // As in a file real ADAMS wrote for an inch/pound model.
  const auto inch = requestFileUnits("INCH", "POUND_MASS", "SECOND", "POUND_FORCE");
  ASSERT_TRUE(inch);
  EXPECT_EQ(inch->token, "INLBS_PFRACA");
  char scale[32];
  std::snprintf(scale, sizeof scale, "%.15E", inch->lengthScale);
  EXPECT_STREQ(scale, "3.937007874015748E+01");
}

TEST(RequestFileUnits, DeclinesUnitsWithoutAKnownToken) {
  EXPECT_FALSE(requestFileUnits("FOOT", "SLUG", "SECOND", "POUND_FORCE"));
  EXPECT_FALSE(requestFileUnits("METER", "KILOGRAM", "MILLISECOND", "NEWTON"));
  EXPECT_FALSE(requestFileUnits("MILLIMETER", "KILOGRAM", "SECOND", "KNEWTON"));
}

}  // namespace
}  // namespace openmss::output
