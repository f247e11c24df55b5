#include "variant_run.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/command_runner.hpp"
#include "commands/session.hpp"
#include "language/command_reader.hpp"

namespace fs = std::filesystem;

namespace openmss::pybind {
namespace {

// The shortest text that reads back as the same double, as `openmss run` writes --end and
// --dtout into its SIMULATE command (src/app/main.cpp), so the .msg echoes the same command.
std::string exact(double v) {
  char text[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    if (std::strtod(text, nullptr) == v) break;
  }
  return text;
}

int runCommandFile(const std::string& path, commands::SessionOptions opt) {
  commands::Session session(std::move(opt));
  std::FILE* sink = std::fopen("/dev/null", "w");  // HELP listings: --quiet drops stdout
  app::CommandRunner runner(session, sink ? sink : stderr);
  const app::RunOutcome outcome = runner.runCommandFile(path);
  if (sink) std::fclose(sink);
  if (outcome == app::RunOutcome::InputError) return 1;
  return outcome == app::RunOutcome::Completed ? 0 : 2;
}

int runModel(const std::string& path, double end, long steps, double dtout,
             commands::SessionOptions opt) {
  commands::Session session(std::move(opt));
  if (!session.loadModel(path, fs::path(path).stem().string())) return 1;
  const std::string text =
      "SIMULATE/TRANSIENT, END=" + exact(end) +
      (dtout > 0 ? ", DTOUT=" + exact(dtout) : ", STEPS=" + std::to_string(steps));
  language::CommandReader reader("<command line>");
  reader.feedLine(text);
  reader.finish();
  bool ok = true;
  for (const auto& c : reader.takeCommands()) {
    session.echoCommand(text);
    ok = session.execute(c) && ok;
  }
  return ok ? 0 : 2;
}

// Standard error of this process sent to an anonymous file while `run` runs, and read back:
// the diagnostics the program prints there (its .msg holds them too) are the variant's
// message when it wrote no .msg. Tasks run one at a time in a study's worker (one thread).
template <class Run>
VariantRun captureStderr(Run run) {
  VariantRun r;
  std::FILE* capture = std::tmpfile();
  const int saved = capture ? dup(STDERR_FILENO) : -1;
  std::fflush(stderr);
  if (saved >= 0) dup2(fileno(capture), STDERR_FILENO);
  r.exitStatus = run();
  std::fflush(stderr);
  if (saved >= 0) {
    dup2(saved, STDERR_FILENO);
    close(saved);
    std::rewind(capture);
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, capture)) > 0;)
      r.errorText.append(buffer, n);
  }
  if (capture) std::fclose(capture);
  return r;
}

}  // namespace

VariantRun runVariant(const std::string& model, const std::string& outdir,
                      const std::vector<std::string>& overrides, double end, long steps,
                      double dtout) {
  return captureStderr([&]() -> int {
    if (!fs::exists(model)) {
      std::fprintf(stderr, "openmss run: %s: no such file\n", model.c_str());
      return 1;
    }
    // As `openmss run --quiet`: no progress line; diagnostics echoed on (captured) stderr;
    // INFO and SHOW only in the .msg (the program's stdout is not read by a study).
    commands::SessionOptions opt;
    opt.overrides = overrides;
    opt.outputDirectory = outdir;
    opt.progress = false;
    opt.printInformation = false;
    const std::string ext = fs::path(model).extension().string();
    return ext == ".acf" || ext == ".ACF" ? runCommandFile(model, std::move(opt))
                                          : runModel(model, end, steps, dtout, std::move(opt));
  });
}

}  // namespace openmss::pybind
