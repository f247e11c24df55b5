// Command files (.acf) and the incremental reader of the interactive prompt (docs/language.md,
// "Command files and the prompt").

#include "language/command_reader.hpp"

#include <gtest/gtest.h>

#include "language/reader.hpp"

namespace openmss::language {
namespace {

using Lines = std::vector<std::string>;

struct CommandResult {
  CommandFile file;
  Lines diagnostics;
  const Statement& at(size_t k) const { return file.commands.at(k); }
};

CommandResult readCommands(const std::string& text) {
  CommandResult r;
  Diagnostics diags;
  readCommandText(text, "t.acf", r.file, diags);
  for (const auto& d : diags.all()) r.diagnostics.push_back(format(d));
  return r;
}

TEST(CommandFile, LinesOneAndTwoNameTheModelAndTheOutputPrefix) {
  auto r = readCommands("dir/model.adm\nrun_1\nstop\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.file.modelFile, "dir/model.adm");
  EXPECT_EQ(r.file.outputPrefix, "run_1");
  ASSERT_EQ(r.file.commands.size(), 1u);
  EXPECT_EQ(r.at(0).name, "STOP");
  EXPECT_EQ(r.at(0).where.line, 3);
}

TEST(CommandFile, ABlankLineTwoMeansTheModelBaseName) {
  auto r = readCommands("dir/model.adm\n\nstop\n");
  EXPECT_EQ(r.file.outputPrefix, "model");
}

TEST(CommandFile, ABlankLineOneMakesLineTwoAnOrdinaryCommand) {
  auto r = readCommands(
      "\nfile/model=generic_model\n! Insert ACF commands here:\n"
      "SIMULATE/DYNAMIC, END=20.0, DTOUT=0.1\nstop\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.file.modelFile, "");
  EXPECT_EQ(r.file.outputPrefix, "");
  ASSERT_EQ(r.file.commands.size(), 3u);
  EXPECT_EQ(r.at(0).name, "FILE");
  EXPECT_EQ(r.at(0).find("MODEL")->values.at(0).written, "generic_model");
  EXPECT_EQ(r.at(0).where.line, 2);
  EXPECT_TRUE(r.at(1).has("DYNAMICS"));
}

TEST(CommandFile, AbbreviatedCommandsOfRealFilesResolve) {
  auto r = readCommands(
      "m.adm\nm\nsim/stat\nsim/dyn, end=1.5, dtout=.005\n"
      "equil/maxit=500, stab=0.1, error=0.1, imbal=0.1, tlim=1.0, alim=2.0D\n"
      "output/noseparator\nintegrator/gstiff, error=1.0e-4, hmax=1e-5\n"
      "int/hht, err=1E-7, hmax=2.5E-4, INTERPOLATE=on\naccg/kgrav=0\n"
      "DEACTIVATE/JOINT, RANGE = 1301, 1321\nLINEAR/EIGENSOL, COORDS = 1, 25\nSTOP\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  ASSERT_EQ(r.file.commands.size(), 10u);
  EXPECT_EQ(r.at(0).name, "SIMULATE");
  EXPECT_TRUE(r.at(0).has("STATICS"));
  EXPECT_TRUE(r.at(1).has("DYNAMICS"));
  EXPECT_EQ(r.at(2).name, "EQUILIBRIUM");
  EXPECT_EQ(r.at(2).find("STABILITY")->values.at(0).number, 0.1);
  EXPECT_TRUE(r.at(2).find("ALIMIT")->values.at(0).degrees);
  EXPECT_TRUE(r.at(3).has("NOSEPARATOR"));
  EXPECT_EQ(r.at(5).find("INTERPOLATE")->values.at(0).text, "ON");
  EXPECT_EQ(r.at(6).name, "ACCGRAV");
  EXPECT_EQ(r.at(7).find("RANGE")->values.size(), 2u);
}

TEST(CommandFile, AmpersandContinuesACommandAndALeadingCommaIsItsDelimiter) {
  auto r = readCommands(
      "\nINTEGRATOR/ &\n, HHT &\n, ERROR = 1.0E-05\n"
      "VARIABLE/1102 &\n, FUNCTION=VARVAL(11021) * &\n, (STEP(TIME,0.0,0.0,0.0+15.0,500.0))\n"
      "VARIABLE/1002, FUNCTION = IF(TIME-4.0: 0, 0, &\n -PI*(TIME-4.0))\nstop\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  ASSERT_EQ(r.file.commands.size(), 4u);
  EXPECT_TRUE(r.at(0).has("HHT"));
  EXPECT_EQ(r.at(0).find("ERROR")->values.at(0).number, 1e-5);
  EXPECT_EQ(r.at(0).lastLine, 4);
  EXPECT_EQ(r.at(1).find("FUNCTION")->expression,
            "VARVAL(11021) *(STEP(TIME,0.0,0.0,0.0+15.0,500.0))");
  EXPECT_EQ(r.at(2).find("FUNCTION")->expression, "IF(TIME-4.0: 0, 0,-PI*(TIME-4.0))");
}

TEST(CommandFile, UnknownCommandsAndCommaContinuationsAreDiagnosed) {
  auto r = readCommands("m.adm\nm\nsimulate/dynamic\n, end=1\nFROB/1\nstop\n");
  EXPECT_EQ(r.diagnostics,
            (Lines{"t.acf:4:1: error: SIMULATE: a command continues on a new line only after "
                   "'&' at the end of the previous line. End the previous line with '&'",
                   "t.acf:5:1: error: FROB/1: 'FROB' is not an ADAMS command. Check the "
                   "spelling; docs/language.md lists every command"}));
}

TEST(CommandFile, ReadingStopsAtStop) {
  auto r = readCommands("m.adm\nm\nstop\nthis is never read\n");
  EXPECT_EQ(r.diagnostics, Lines{});
  EXPECT_EQ(r.file.commands.size(), 1u);
}

TEST(CommandReader, AsksForMoreLinesAfterAnAmpersand) {
  CommandReader reader;
  EXPECT_TRUE(reader.feedLine("simulate/transient, &"));
  EXPECT_TRUE(reader.needsMoreLines());
  EXPECT_TRUE(reader.takeCommands().empty());
  EXPECT_FALSE(reader.feedLine("   end=5.0, dtout=1.0E-002"));
  auto commands = reader.takeCommands();
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].name, "SIMULATE");
  EXPECT_EQ(commands[0].find("END")->values.at(0).number, 5.0);
  EXPECT_EQ(commands[0].where.file, "<stdin>");
  EXPECT_TRUE(reader.takeDiagnostics().all().empty());
}

TEST(CommandReader, ReportsBadCommandsAndKeepsGoing) {
  CommandReader reader("<stdin>", 1);
  reader.feedLine("sim/dyn, end=two");
  reader.feedLine("stop");
  auto commands = reader.takeCommands();
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_FALSE(commands[0].has("END"));
  auto diags = reader.takeDiagnostics();
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(format(diags.all()[0]),
            "<stdin>:1:14: error: SIMULATE: END expects a number, not 'two'. Write a number such "
            "as 1.5, -2E-3 or 90D");
}

TEST(CommandReader, AnUnfinishedCommandIsDiagnosedAtTheEnd) {
  CommandReader reader("t.acf", 3);
  reader.feedLine("output/noseparator &");
  reader.finish();
  auto diags = reader.takeDiagnostics();
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(format(diags.all()[0]),
            "t.acf:3:20: error: the command ends with '&' but no line follows. Remove the '&' or "
            "add the rest of the command");
  EXPECT_EQ(reader.takeCommands().size(), 1u);
}

}  // namespace
}  // namespace openmss::language
