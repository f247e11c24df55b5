// openmss: the command-line program. Subcommands: run, check, eval (see --help); with no
// arguments, the interactive command prompt (prompt.cpp).

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/model_summary.hpp"
#include "app/api_command.hpp"
#include "app/command_runner.hpp"
#include "app/print_diagnostics.hpp"
#include "app/prompt.hpp"
#include "app/python_tool.hpp"
#include "app/view_command.hpp"
#include "commands/session.hpp"
#include "common/parallel_for.hpp"
#include "expr/standalone.hpp"
#include "language/command_reader.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"
#include "model/releasing_build.hpp"
#include "model/results_arguments.hpp"
#include "solvers/pivot_order.hpp"
#include "user/element_routine.hpp"
#include "user/user_library.hpp"

namespace fs = std::filesystem;
using namespace openmss;

namespace {

constexpr const char* kMainHelp =
    "openmss - mechanical system simulation with ADAMS/Solver data sets\n"
    "\n"
    "Usage:\n"
    "  openmss                                      interactive prompt: ADAMS commands from\n"
    "                                               the terminal (HELP lists them)\n"
    "  openmss run FILE.acf [--outdir DIR]          run an ADAMS command file\n"
    "  openmss run FILE.adm [--end T] [--steps N | --dtout H] [--outdir DIR]\n"
    "                                               run a model with a transient simulation\n"
    "  openmss run FILE [--set STATEMENT/id.ARGUMENT=value ...]\n"
    "                                               run with arguments of the data set changed\n"
    "  openmss check FILE.adm [--user-library LIB]  read and check a model, print its DOF\n"
    "  openmss check FILE.acf                       check a command file and its model\n"
    "  openmss eval 'EXPR' [--time T] [--derivative]  evaluate a function expression\n"
    "  openmss plot RESULT --request ID --component N [--vs OTHER] [-o OUT.png]\n"
    "                                               plot a request of a .req or .res (Python)\n"
    "  openmss view RESULT [--model FILE.adm] [--port P]  3-D viewer in the browser\n"
    "  openmss study run STUDY.yaml [--scheduler ADDRESS] [--workers N] [--out DIR]\n"
    "                                               a design study on Dask (Python,\n"
    "                                               docs/studies.md)\n"
    "  openmss COMMAND --help                       help on one command\n"
    "  openmss --version                            print the version\n"
    "\n"
    "Environment: OPENMSS_THREADS=N runs the equations of large models on N threads\n"
    "  (default: one per core; outputs are bit-identical for any N, docs/performance.md).\n"
    "Exit status: 0 success, 1 input errors, 2 analysis failure, 64 usage error.\n";

constexpr const char* kRunHelp =
    "openmss run FILE.acf [--outdir DIR] [--quiet]\n"
    "  Runs an ADAMS command file as ADAMS does: line 1 names the model (relative paths\n"
    "  resolve against the command file's folder; .adm is supplied when missing), line 2 the\n"
    "  output prefix (blank: the model's base name), then commands until STOP.\n"
    "openmss run FILE.adm [--end T] [--steps N | --dtout H] [--outdir DIR] [--quiet]\n"
    "  Runs a model with SIMULATE/TRANSIENT, END=T (default 1), and STEPS=N (default 100) or\n"
    "  DTOUT=H; writes the request file when the model asks for it (OUTPUT/REQSAVE).\n"
    "Outputs go to the current directory or to --outdir: <prefix>.msg, <prefix>.req.\n"
    "A progress line (simulated time, steps, ETA) is shown on a terminal.\n"
    "--user-library LIB names the default library of user-written subroutines (ADAMS's\n"
    "  run-user mode): GSEs without ROUTINE=lib:: or INTERFACE= take their routines from it.\n"
    "--set STATEMENT/id.ARGUMENT=value (repeatable) changes one argument of the data set as\n"
    "  read, e.g. --set SPRINGDAMPER/3.K=12.5, --set VARIABLE/7.FUNCTION=2*TIME,\n"
    "  --set ACCGRAV.JGRAV=-9.81; the value is read as in a data set (docs/studies.md).\n"
    "  An unknown statement, id or argument is an input error (exit 1).\n"
    "--pivot-order default|nobtf|colamd (diagnostics) changes KLU's pivot order for GSTIFF,\n"
    "  WSTIFF and DSTIFF: results then differ by round-off, which shows how sensitive a run\n"
    "  is to it (docs/integrators.md, \"A second failure at a flat passage\").\n";

constexpr const char* kCheckHelp =
    "openmss check FILE.adm [--user-library LIB]\n"
    "  Reads and checks a data set without simulating. Prints every diagnostic\n"
    "  (file:line: severity: STATEMENT/id: message. what to change), the Gruebler count and\n"
    "  the degrees of freedom from the rank of the constraint Jacobian.\n"
    "  Exit status 0 when the model is clean, 1 otherwise.\n"
    "openmss check FILE.acf\n"
    "  Reads the command file and the model it names in one pass, without simulating, and\n"
    "  reports every error in either: unknown commands and arguments, ids the model lacks,\n"
    "  redefinitions that leave the model without a build, SIMULATE times out of order.\n";

constexpr const char* kEvalHelp =
    "openmss eval 'EXPR' [--time T] [--derivative]\n"
    "  Evaluates a function expression that needs no model (numbers, constants, TIME and the\n"
    "  general functions STEP, POLY, IMPACT, ...) and prints its value; with --derivative also\n"
    "  d/dTIME.\n";

bool wantsHelp(int argc, char** argv) {
  for (int i = 2; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") return true;
  return false;
}

int printSummary(const commands::Session& s, bool ok) {
  const model::Model* m = s.model();
  if (!m) return 1;
  std::printf("OpenMSS: %s\n", m->title.c_str());
  std::printf("  model:    %d moving parts, %zu joints, %zu motions, %zu force elements, %zu requests; "
              "%d degrees of freedom (Gruebler count %d)\n",
              m->bodyCount(), m->joints.size(), m->motions.size(),
              m->sforces.size() + m->springDampers.size() + m->linearFields.size() +
                  m->vectorForces.size() + m->contacts.size(),
              m->requests.size(), s.degreesOfFreedom(), s.grueblerDegreesOfFreedom());
  const auto& r = s.summary();
  if (!r.analysis.empty())
    std::printf("  analysis: %s, reached t = %g with %ld integration steps, %ld output steps\n",
                r.analysis.c_str(), r.time, r.steps, r.outputSteps);
  // Only the files that are on disk (a model without requests, or a run that failed before
  // its first output, has no request file).
  std::string outputs;
  for (const std::string& path : {s.messageFilePath(), s.requestFilePath(), s.resultsFilePath(),
                                   s.tabularFilePath()})
    if (!path.empty() && fs::exists(path)) outputs += (outputs.empty() ? "" : ", ") + path;
  std::printf("  outputs:  %s\n", outputs.empty() ? "(none written)" : outputs.c_str());
  if (!ok) std::printf("  the run did not complete: see the diagnostics above\n");
  return 0;
}

// `openmss run --pivot-order NAME` (diagnostics): KLU's pivot order, for tests and benches
// (solvers/pivot_order.hpp). An unknown name ends the program, as a missing value does.
solvers::PivotOrder readPivotOrder(const std::string& name) {
  if (name == "default") return solvers::PivotOrder::Default;
  if (name == "nobtf") return solvers::PivotOrder::NoBtf;
  if (name == "colamd") return solvers::PivotOrder::Colamd;
  std::fprintf(stderr, "openmss run: --pivot-order is default, nobtf or colamd, not %s\n",
               name.c_str());
  std::exit(64);
}

int runCommandFile(const std::string& path, const std::string& outdir, bool quiet,
                   const std::vector<std::string>& overrides, solvers::PivotOrder pivotOrder) {
  commands::SessionOptions opt;
  opt.overrides = overrides;
  opt.pivotOrder = pivotOrder;
  opt.outputDirectory = outdir;
  opt.progress = !quiet && isatty(STDERR_FILENO);
  commands::Session session(opt);
  app::CommandRunner runner(session, stdout);
  const app::RunOutcome outcome = runner.runCommandFile(path);
  if (outcome == app::RunOutcome::InputError) return 1;
  const bool ok = outcome == app::RunOutcome::Completed;
  if (!quiet) printSummary(session, ok);
  return ok ? 0 : 2;
}

int runModel(const std::string& path, double end, long steps, double dtout,
             const std::string& outdir, bool quiet, const std::vector<std::string>& overrides,
             solvers::PivotOrder pivotOrder) {
  commands::SessionOptions opt;
  opt.overrides = overrides;
  opt.pivotOrder = pivotOrder;
  opt.outputDirectory = outdir;
  opt.progress = !quiet && isatty(STDERR_FILENO);
  commands::Session session(opt);
  if (!session.loadModel(path, fs::path(path).stem().string())) return 1;
  // The shortest text that reads back as the same double (std::to_string's six decimals
  // turned --end 1e-7 into END=0.000000): 1e-07, 0.1, 2.5.
  auto exact = [](double v) {
    char text[32];
    for (int digits = 15; digits <= 17; ++digits) {
      std::snprintf(text, sizeof text, "%.*g", digits, v);
      if (std::strtod(text, nullptr) == v) break;
    }
    return std::string(text);
  };
  std::string text = "SIMULATE/TRANSIENT, END=" + exact(end) +
                     (dtout > 0 ? ", DTOUT=" + exact(dtout) : ", STEPS=" + std::to_string(steps));
  language::CommandReader reader("<command line>");
  reader.feedLine(text);
  reader.finish();
  auto cmds = reader.takeCommands();
  bool ok = true;
  for (const auto& c : cmds) {
    session.echoCommand(text);
    ok = session.execute(c) && ok;
  }
  if (!quiet) printSummary(session, ok);
  return ok ? 0 : 2;
}

// `openmss check FILE.acf`: the command file and the model it names, in one pass, without
// simulating: every command is checked against the model as the run would see it.
int checkCommandFile(const std::string& path) {
  commands::SessionOptions opt;
  opt.checkOnly = true;
  opt.printInformation = false;
  commands::Session session(opt);
  app::CommandRunner runner(session, stdout);
  runner.setKeepGoing(true);
  const app::RunOutcome outcome = runner.runCommandFile(path);
  int errors = session.diagnostics().errorCount() + runner.readErrors();
  const int warnings = session.diagnostics().warningCount() + runner.readWarnings();
  if (outcome == app::RunOutcome::InputError && errors == 0) errors = 1;  // e.g. no model file
  if (const model::Model* m = session.model(); m && runner.modelLoaded())
    std::printf("%s: model %s: %d moving parts, DOF %d\n", path.c_str(), m->title.c_str(),
                m->bodyCount(), session.degreesOfFreedom());
  std::printf("%s: %d error(s), %d warning(s)\n", path.c_str(), errors, warnings);
  return errors > 0 ? 1 : 0;
}

int check(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".acf" || ext == ".ACF") return checkCommandFile(path);
  Diagnostics diags;
  language::Dataset ds;
  language::readDatasetFile(path, ds, diags);
  model::Model m;
  bool built = false;
  // Build even after reading errors, so that one pass reports the model-level errors too.
  built = model::buildModelReleasingContacts(ds, m, diags);
  model::readResultsSettings(ds, diags);  // RESULTS and CNAMES diagnostics, as a run gives them
  // Nothing below reads the statements: the tree is released before the system is set up
  // (a large data set's tree is the largest part of a check; docs/performance.md).
  ds = language::Dataset();
  app::printDiagnostics(diags);
  if (!built || diags.hasErrors()) {
    std::printf("%s: %d error(s), %d warning(s)\n", path.c_str(), diags.errorCount(),
                diags.warningCount());
    return 1;
  }
  mechanics::MultibodySystem system(m);
  Eigen::VectorXd y = system.initialState();
  const analysis::DegreeOfFreedomCount dof = analysis::countDegreesOfFreedom(system, y);
  std::printf("%s: %s\n", path.c_str(), m.title.c_str());
  std::printf("  %d moving parts, %zu joints, %zu motions, %zu force elements, %zu requests\n",
              m.bodyCount(), m.joints.size(), m.motions.size(),
              m.sforces.size() + m.springDampers.size() + m.linearFields.size() +
                  m.vectorForces.size() + m.contacts.size(),
              m.requests.size());
  std::printf("  Gruebler count: %d\n", dof.gruebler);
  std::printf("  loops: %d independent, %s dependent\n", dof.loops.independent,
              dof.loops.enumerated ? std::to_string(dof.loops.dependent).c_str()
                                   : "(not enumerated)");
  for (int k : dof.removed)
    std::printf("  redundant: %s\n", system.constraints().describe(k, m).c_str());
  std::printf("DOF %d\n", dof.degreesOfFreedom);
  std::printf("%d error(s), %d warning(s)\n", diags.errorCount(), diags.warningCount());
  return 0;
}

int eval(int argc, char** argv) {
  std::string text;
  double time = 0.0;
  bool derivative = false;
  for (int i = 2; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--time" && i + 1 < argc) time = std::atof(argv[++i]);
    else if (a == "--derivative") derivative = true;
    else if (text.empty()) text = a;
    else {
      std::fprintf(stderr, "openmss eval: unexpected argument %s\n%s", a.c_str(), kEvalHelp);
      return 64;
    }
  }
  if (text.empty()) {
    std::fprintf(stderr, "%s", kEvalHelp);
    return 64;
  }
  Diagnostics d;
  double v = 0.0, dv = 0.0;
  if (!expr::evaluateStandalone(text, time, &v, &dv, d)) {
    app::printDiagnostics(d);
    return 1;
  }
  std::printf("%.17g\n", v);
  if (derivative) std::printf("d/dTIME %.17g\n", dv);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // OPENMSS_THREADS (common/parallel_for.hpp) is checked before anything runs.
  if (const std::string problem = threadCountProblem(); !problem.empty()) {
    std::fprintf(stderr, "openmss: %s\n", problem.c_str());
    return 64;
  }
  if (argc < 2) {
    app::PromptOptions prompt;
    prompt.interactive = isatty(STDIN_FILENO) != 0;
    return app::runPrompt(std::cin, prompt);
  }
  if (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::printf("%s", kMainHelp);
    return 0;
  }
  if (std::string(argv[1]) == "--version") {
    std::printf("openmss %s\n", OPENMSS_VERSION);
    return 0;
  }
  const std::string cmd = argv[1];
  if (cmd == "run") {
    if (wantsHelp(argc, argv)) { std::printf("%s", kRunHelp); return 0; }
    std::string file, outdir = ".";
    double end = 1.0, dtout = 0.0;
    long steps = 100;
    bool quiet = false;
    std::vector<std::string> overrides;
    solvers::PivotOrder pivotOrder = solvers::PivotOrder::Default;
    for (int i = 2; i < argc; ++i) {
      std::string a = argv[i];
      auto next = [&]() -> const char* {
        if (i + 1 >= argc) {
          std::fprintf(stderr, "openmss run: %s needs a value\n", a.c_str());
          std::exit(64);
        }
        return argv[++i];
      };
      if (a == "--outdir") outdir = next();
      else if (a == "--end") end = std::atof(next());
      else if (a == "--steps") steps = std::atol(next());
      else if (a == "--dtout") dtout = std::atof(next());
      else if (a == "--quiet") quiet = true;
      else if (a == "--set") overrides.push_back(next());
      else if (a == "--pivot-order")
        pivotOrder = readPivotOrder(next());
      else if (a == "--user-library") user::setDefaultLibrary(fs::absolute(next()).string());
      else if (a.starts_with("--")) {
        std::fprintf(stderr, "openmss run: unknown option %s\n%s", a.c_str(), kRunHelp);
        return 64;
      }
      else if (file.empty()) file = a;
      else { std::fprintf(stderr, "openmss run: unexpected argument %s\n", a.c_str()); return 64; }
    }
    if (file.empty()) { std::fprintf(stderr, "%s", kRunHelp); return 64; }
    if (!fs::exists(file)) {
      std::fprintf(stderr, "openmss run: %s: no such file\n", file.c_str());
      return 1;
    }
    const std::string ext = fs::path(file).extension().string();
    const int status =
        ext == ".acf" || ext == ".ACF"
            ? runCommandFile(file, outdir, quiet, overrides, pivotOrder)
            : runModel(file, end, steps, dtout, outdir, quiet, overrides, pivotOrder);
    // A user subroutine that stopped the run (NaN, ERRMES STOP, a crash) is named last
    // (docs/user-subroutines.md, "Bad user code").
    if (const std::string fatal = user::firstUserFatal(); status != 0 && !fatal.empty()) {
      std::fflush(stdout);
      std::fprintf(stderr, "openmss: error: %s\n", fatal.c_str());
    }
    return status;
  }
  if (cmd == "check") {
    if (wantsHelp(argc, argv)) { std::printf("%s", kCheckHelp); return 0; }
    if (argc == 5 && std::string(argv[3]) == "--user-library")
      user::setDefaultLibrary(fs::absolute(argv[4]).string());
    else if (argc != 3) { std::fprintf(stderr, "%s", kCheckHelp); return 64; }
    return check(argv[2]);
  }
  if (cmd == "eval") {
    if (wantsHelp(argc, argv)) { std::printf("%s", kEvalHelp); return 0; }
    return eval(argc, argv);
  }
  // The machine interface of the Python package (api_command.hpp); not listed in --help.
  if (cmd == "api") return app::apiCommand(argc, argv);
  // Tools of the Python package (docs/python.md): arguments and exit status pass through.
  if (cmd == "plot" || cmd == "study")
    return app::runPythonTool(cmd, std::vector<std::string>(argv + 2, argv + argc));
  if (cmd == "view") {
    if (wantsHelp(argc, argv)) { std::printf("%s", app::kViewHelp); return 0; }
    return app::runView(argc, argv);
  }
  std::fprintf(stderr, "openmss: unknown command '%s'\n%s", cmd.c_str(), kMainHelp);
  return 64;
}
