#pragma once
// Running the openmss program from a test: a fresh scratch folder, the program's exit status
// and output, and file helpers. Shared by every end-to-end test (OPENMSS_BINARY is defined by
// tests/CMakeLists.txt).

#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace openmss::testing {

struct Result {
  int status = -1;
  std::string output;  // stdout and stderr
};

// An empty folder of its own under the system's temporary directory.
inline std::filesystem::path scratch(const std::string& name) {
  const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
  std::filesystem::path p = std::filesystem::temp_directory_path() /
                            ("openmss-test-" + name + "-" + std::to_string(ticks));
  std::filesystem::create_directories(p);
  return p;
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void write(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

// Runs `openmss ARGS` in `dir`; the output is also kept in dir/cli.log.
inline Result run(const std::string& args, const std::filesystem::path& dir) {
  const std::filesystem::path log = dir / "cli.log";
  const std::string cmd = "cd '" + dir.string() + "' && '" OPENMSS_BINARY "' " + args + " > '" +
                          log.string() + "' 2>&1";
  const int raw = std::system(cmd.c_str());
  Result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.output = slurp(log);
  return r;
}

}  // namespace openmss::testing
