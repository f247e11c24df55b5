#pragma once
// The interactive prompt: `openmss` with no arguments reads ADAMS commands from standard
// input, one line at a time, and runs each as soon as it is complete.

#include <istream>
#include <string>

namespace openmss::app {

struct PromptOptions {
  std::string outputDirectory = ".";
  // Show the banner and the prompts ("openmss> ", "      > " for a continuation line). Off
  // when standard input is not a terminal, so piped scripts give clean output.
  bool interactive = false;
};

// Reads commands from `in` until STOP or the end of input. A rejected or failed command is
// reported and the prompt goes on (unlike an .acf, where it ends the run). Returns the exit
// status: 0 when every command was read and ran, 1 when any was rejected or failed.
int runPrompt(std::istream& in, const PromptOptions& options);

}  // namespace openmss::app
