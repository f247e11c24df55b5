#include "app/python_tool.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace fs = std::filesystem;

namespace openmss::app {

std::string pythonInterpreter() {
  const char* env = std::getenv("OPENMSS_PYTHON");
  return env && *env ? env : "/usr/bin/python3";
}

std::string pythonPackageDirectory() {
  if (const char* env = std::getenv("OPENMSS_PYTHONPATH"); env && *env) return env;
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path beside = self.parent_path() / "python";
    if (fs::exists(beside / "openmss" / "__init__.py", ec)) return beside.string();
  }
#ifdef OPENMSS_PYTHON_DIR
  return OPENMSS_PYTHON_DIR;
#else
  return {};
#endif
}

int runPythonTool(const std::string& module, const std::vector<std::string>& args) {
  const std::string python = pythonInterpreter();
  const std::string package = pythonPackageDirectory();
  std::string path = package;
  if (const char* old = std::getenv("PYTHONPATH"); old && *old) path += ":" + std::string(old);
  std::vector<std::string> argv = {python, "-m", "openmss." + module};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> cargv;
  for (auto& a : argv) cargv.push_back(a.data());
  cargv.push_back(nullptr);
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = fork();
  if (pid < 0) {
    std::fprintf(stderr, "openmss: cannot start %s: %s\n", python.c_str(), std::strerror(errno));
    return 127;
  }
  if (pid == 0) {
    setenv("PYTHONPATH", path.c_str(), 1);
    // Plots are written to files; no display is needed or wanted.
    if (!std::getenv("MPLBACKEND")) setenv("MPLBACKEND", "Agg", 1);
    execv(python.c_str(), cargv.data());
    std::fprintf(stderr,
                 "openmss: cannot run %s: %s (install python3 with scripts/install-deps.sh, or "
                 "set OPENMSS_PYTHON)\n",
                 python.c_str(), std::strerror(errno));
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return 127;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 127;
}

}  // namespace openmss::app
