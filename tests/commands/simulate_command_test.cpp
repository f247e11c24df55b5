// SIMULATE read into typed requests (commands/simulate_command.hpp): the resolved end time and
// output count, the kind, and each refusal located at the command.

#include "commands/simulate_command.hpp"

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "language/command_reader.hpp"

namespace openmss::commands {
namespace {

language::Statement command(const std::string& text) {
  language::CommandReader reader("study.acf", 5);
  reader.feedLine(text);
  reader.finish();
  auto commands = reader.takeCommands();
  EXPECT_EQ(commands.size(), 1u) << text;
  return commands.front();
}

TEST(SimulateCommand, DurationCountsFromTheCurrentTimeAndDtoutGivesTheOutputCount) {
  Diagnostics d;
  const auto r = readSimulate(command("SIMULATE/DYNAMICS, DURATION=0.5, DTOUT=0.01"), 1.25, d);
  ASSERT_TRUE(r && std::holds_alternative<analysis::TransientRun>(*r));
  const auto& t = std::get<analysis::TransientRun>(*r);
  EXPECT_EQ(t.kind, analysis::TransientKind::Dynamics);
  EXPECT_DOUBLE_EQ(t.end, 1.75);
  EXPECT_EQ(t.outputSteps, 50);  // llround(0.5 / 0.01)
  EXPECT_EQ(t.origin.where.line, 5);
  EXPECT_FALSE(d.hasErrors());
}

TEST(SimulateCommand, StaticsWithoutEndIsOneEquilibriumAndWithEndQuasiStatic) {
  Diagnostics d;
  const auto one = readSimulate(command("SIMULATE/STATICS"), 0.0, d);
  ASSERT_TRUE(one && std::holds_alternative<analysis::StaticsRun>(*one));
  EXPECT_FALSE(std::get<analysis::StaticsRun>(*one).end.has_value());
  const auto seq = readSimulate(command("SIMULATE/STATICS, END=2, STEPS=4"), 0.0, d);
  ASSERT_TRUE(seq && std::holds_alternative<analysis::StaticsRun>(*seq));
  EXPECT_DOUBLE_EQ(*std::get<analysis::StaticsRun>(*seq).end, 2.0);
  EXPECT_EQ(std::get<analysis::StaticsRun>(*seq).outputSteps, 4);
  const auto ic = readSimulate(command("SIMULATE/INITIAL_CONDITIONS, VELOCITY"), 0.0, d);
  ASSERT_TRUE(ic && std::holds_alternative<analysis::InitialConditionsRun>(*ic));
  EXPECT_EQ(std::get<analysis::InitialConditionsRun>(*ic).last,
            analysis::InitialConditionsPhase::Velocity);
  EXPECT_FALSE(d.hasErrors());
}

// Each refusal: one error, at the command's line, naming what to write instead.
TEST(SimulateCommand, BadCommandsAreRefusedAtTheirLine) {
  const std::pair<const char*, const char*> cases[] = {
      {"SIMULATE/END=1, STEPS=10", "the kind of simulation is missing"},
      {"SIMULATE/DYNAMICS, KINEMATICS, END=1, STEPS=10", "SIMULATE takes one kind"},
      {"SIMULATE/TRANSIENT, END=0.5, STEPS=10", "after the current time 1"},
      {"SIMULATE/TRANSIENT, END=2", "the output step is missing"},
      {"SIMULATE/STATICS, STEPS=3", "STEPS and DTOUT need END"},
      {"SIMULATE/INITIAL_CONDITIONS, END=3", "END has no meaning"},
  };
  int refused = 0;
  for (const auto& [text, message] : cases) {
    Diagnostics d;
    EXPECT_FALSE(readSimulate(command(text), 1.0, d)) << text;
    ASSERT_EQ(d.errorCount(), 1) << text;
    EXPECT_NE(d.all()[0].message.find(message), std::string::npos) << d.all()[0].message;
    EXPECT_EQ(d.all()[0].where.line, 5) << text;
    EXPECT_EQ(d.all()[0].where.file, "study.acf") << text;
    ++refused;
  }
  EXPECT_EQ(refused, 6);
}

}  // namespace
}  // namespace openmss::commands
