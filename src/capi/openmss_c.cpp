// The C embedding API (include/openmss/openmss.h, docs/embedding.md) over a commands::Session:
// every call is a command the session executes (SIMULATE, SAVE, RELOAD, ...) or a read of its
// run state, so an embedded run writes the .msg and .req that `openmss run` would write for
// the same commands. Plant inputs are held by the solver and laid on the session's model and
// run state before each analysis (Session::setPlantInputs), so that they survive a RELOAD.

#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <new>
#include <set>
#include <string>
#include <vector>

#include "analysis/request_values.hpp"
#include "api/run.hpp"
#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/user_state_solve.hpp"
#include "openmss/openmss.h"

namespace fs = std::filesystem;
using openmss::Diagnostic;
using openmss::Severity;

struct openmss_solver {
  std::unique_ptr<openmss::commands::Session> session;
  std::map<int, double> inputs;  // VARIABLE index -> value set by the caller
};

namespace {

struct LastError {
  std::string text, file;
  int line = 0;
};
thread_local LastError lastError;

openmss_status ok() {
  lastError = {};
  return OPENMSS_OK;
}

openmss_status fail(openmss_status code, std::string text, std::string file = {}, int line = 0) {
  lastError = {std::move(text), std::move(file), line};
  return code;
}

openmss_status fail(openmss_status code, const Diagnostic& d) {
  return fail(code, openmss::api::toRecord(d).text, d.where.file, d.where.line);
}

// The first error the session added since it held `before` diagnostics.
const Diagnostic* firstErrorSince(const openmss::commands::Session& s, std::size_t before) {
  const auto& all = s.diagnostics().all();
  for (std::size_t k = before; k < all.size(); ++k)
    if (all[k].severity == Severity::Error) return &all[k];
  return nullptr;
}

openmss_status failSince(const openmss::commands::Session& s, std::size_t before,
                         openmss_status code, const std::string& what) {
  if (const Diagnostic* d = firstErrorSince(s, before)) return fail(code, *d);
  return fail(code, what);
}

bool usable(const openmss_solver* s) { return s != nullptr && s->session && s->session->model(); }

openmss_status noSolver() { return fail(OPENMSS_ERROR_ARGUMENT, "the solver is null"); }

const openmss::model::PlantVariables* plantList(const openmss_solver* s, long id, bool inputs) {
  const auto& lists = inputs ? s->session->model()->pinputs : s->session->model()->poutputs;
  for (const auto& p : lists)
    if (p.id == id) return &p;
  return nullptr;
}

openmss_status noPlantList(long id, bool inputs) {
  const std::string name = std::string(inputs ? "PINPUT/" : "POUTPUT/") + std::to_string(id);
  return fail(OPENMSS_ERROR_ARGUMENT, name + " is not in the data set");
}

// ACTIVATE, DEACTIVATE and the statement-redefining commands (commands/element_commands.cpp):
// the session rebuilds the model from the data set and the edits at the next analysis. /LIST
// alone only prints.
bool changesModel(const openmss::language::Statement& c) {
  static const std::set<std::string> names = {
      "ACTIVATE", "DEACTIVATE", "PART",   "MARKER",   "JOINT",  "MOTION",       "GCON",   "ACCGRAV",
      "BEAM",     "BUSHING",    "FIELD",  "GFORCE",   "SFORCE", "SPRINGDAMPER", "VFORCE", "VTORQUE",
      "ARRAY",    "SPLINE",     "STRING", "VARIABLE", "DIFF",   "SENSOR",       "REQUEST"};
  if (names.count(c.name) == 0) return false;
  return !(c.args.size() == 1 && c.has("LIST"));
}

// Executes command text; OPENMSS_ERROR_INPUT when it does not read or is refused before any
// analysis, OPENMSS_ERROR_ANALYSIS when its analysis fails.
openmss_status execute(openmss_solver* s, const std::string& text) {
  openmss::commands::Session& session = *s->session;
  const std::size_t before = session.diagnostics().all().size();
  openmss::language::CommandReader reader("<openmss_command>");
  reader.feedLine(text);
  reader.finish();
  const openmss::Diagnostics read = reader.takeDiagnostics();
  for (const auto& d : read.all())
    if (d.severity == Severity::Error) return fail(OPENMSS_ERROR_INPUT, d);
  const auto commands = reader.takeCommands();
  if (commands.empty()) return fail(OPENMSS_ERROR_INPUT, "no command in \"" + text + "\"");
  for (const auto& c : commands)
    if (!s->inputs.empty() && changesModel(c))
      return fail(OPENMSS_ERROR_STATE,
                  c.subject() +
                      " changes the model after plant inputs were set: the model it "
                      "rebuilds at the next analysis would run that analysis with the "
                      "data set's FUNCTION for the inputs. Give model-changing commands "
                      "before the first openmss_set_pinput (docs/embedding.md).",
                  c.where.file, c.where.line);
  for (const auto& c : commands) {
    const long stepsBefore = session.summary().steps;
    session.echoCommand(text);
    if (!session.execute(c)) {
      const bool analysisRan = session.summary().steps != stepsBefore;
      return failSince(session, before, analysisRan ? OPENMSS_ERROR_ANALYSIS : OPENMSS_ERROR_INPUT,
                       "the command \"" + text + "\" failed");
    }
  }
  return ok();
}

// Lays the caller's plant inputs on the session's run state (a new one after a reload or a
// rebuilt model has none).
openmss_status applyInputs(openmss_solver* s) {
  if (s->inputs.empty()) return OPENMSS_OK;
  std::vector<std::pair<int, double>> values(s->inputs.begin(), s->inputs.end());
  if (!s->session->setPlantInputs(values))
    return fail(OPENMSS_ERROR_ANALYSIS,
                "the state cannot be made consistent with the plant inputs at time " +
                    openmss::api::exactNumber(s->session->state()->t));
  return OPENMSS_OK;
}

// The user algebraic unknowns (VARIABLE values, ...) solved for the current positions,
// velocities and differential states: the integrator's corrector leaves them converged only to
// its own tolerance, and a plant output is read as the value its FUNCTION has at the state
// (mechanics/user_state_solve.hpp, converged to 1e-12 (1 + |y|)).
Eigen::VectorXd consistentState(const openmss_solver* s) {
  const auto& st = *s->session->state();
  Eigen::VectorXd y = st.y;
  if (st.initialized) openmss::mechanics::solveUserAlgebraic(*s->session->system(), st.t, y);
  return y;
}

}  // namespace

extern "C" {

const char* openmss_version(void) { return OPENMSS_VERSION; }
const char* openmss_last_error(void) { return lastError.text.c_str(); }
const char* openmss_last_error_file(void) { return lastError.file.c_str(); }
int openmss_last_error_line(void) { return lastError.line; }

openmss_status openmss_open(const char* dataset_path, const char* output_dir,
                            openmss_solver** solver) {
  if (solver == nullptr) return fail(OPENMSS_ERROR_ARGUMENT, "the solver pointer is null");
  *solver = nullptr;
  if (dataset_path == nullptr) return fail(OPENMSS_ERROR_ARGUMENT, "the data set path is null");
  const std::string path = dataset_path;
  if (!fs::is_regular_file(path))
    return fail(OPENMSS_ERROR_FILE, path + ": error: the data set does not exist. Check the path.",
                path);
  openmss::commands::SessionOptions options;
  options.outputDirectory = output_dir != nullptr ? output_dir : ".";
  options.progress = false;
  options.echoDiagnostics = false;
  options.printInformation = false;
  auto s = std::unique_ptr<openmss_solver>(new (std::nothrow) openmss_solver);
  if (!s) return fail(OPENMSS_ERROR_STATE, "out of memory");
  s->session = std::make_unique<openmss::commands::Session>(options);
  if (!s->session->loadModel(path, fs::path(path).stem().string()))
    return failSince(*s->session, 0, OPENMSS_ERROR_INPUT, path + ": the data set does not load");
  *solver = s.release();
  return ok();
}

void openmss_close(openmss_solver* solver) { delete solver; }

openmss_status openmss_command(openmss_solver* solver, const char* command) {
  if (!usable(solver)) return noSolver();
  if (command == nullptr) return fail(OPENMSS_ERROR_ARGUMENT, "the command is null");
  if (const openmss_status st = applyInputs(solver); st != OPENMSS_OK) return st;
  return execute(solver, command);
}

openmss_status openmss_initialize(openmss_solver* solver) {
  if (!usable(solver)) return noSolver();
  if (solver->session->state()->initialized) return ok();
  if (const openmss_status st = applyInputs(solver); st != OPENMSS_OK) return st;
  return execute(solver, "SIMULATE/INITIAL_CONDITIONS");
}

openmss_status openmss_time(const openmss_solver* solver, double* time) {
  if (!usable(solver)) return noSolver();
  if (time == nullptr) return fail(OPENMSS_ERROR_ARGUMENT, "the time pointer is null");
  *time = solver->session->state()->t;
  return ok();
}

openmss_status openmss_advance(openmss_solver* solver, double end, int output_steps) {
  if (!usable(solver)) return noSolver();
  const double now = solver->session->state()->t;
  if (!std::isfinite(end) || !(end > now))
    return fail(OPENMSS_ERROR_STATE,
                "openmss_advance: the end time " + openmss::api::exactNumber(end) +
                    " is not after the current time " + openmss::api::exactNumber(now));
  if (output_steps < 1)
    return fail(OPENMSS_ERROR_ARGUMENT, "openmss_advance: output_steps must be at least 1");
  if (const openmss_status st = applyInputs(solver); st != OPENMSS_OK) return st;
  return execute(solver, "SIMULATE/DYNAMICS, END=" + openmss::api::exactNumber(end) +
                             ", STEPS=" + std::to_string(output_steps));
}

openmss_status openmss_pinput_count(const openmss_solver* solver, long pinput_id, int* count) {
  if (!usable(solver)) return noSolver();
  if (count == nullptr) return fail(OPENMSS_ERROR_ARGUMENT, "the count pointer is null");
  const auto* p = plantList(solver, pinput_id, true);
  if (p == nullptr) return noPlantList(pinput_id, true);
  *count = static_cast<int>(p->variables.size());
  return ok();
}

openmss_status openmss_poutput_count(const openmss_solver* solver, long poutput_id, int* count) {
  if (!usable(solver)) return noSolver();
  if (count == nullptr) return fail(OPENMSS_ERROR_ARGUMENT, "the count pointer is null");
  const auto* p = plantList(solver, poutput_id, false);
  if (p == nullptr) return noPlantList(poutput_id, false);
  *count = static_cast<int>(p->variables.size());
  return ok();
}

openmss_status openmss_set_pinput(openmss_solver* solver, long pinput_id, const double* values,
                                  int count) {
  if (!usable(solver)) return noSolver();
  const auto* p = plantList(solver, pinput_id, true);
  if (p == nullptr) return noPlantList(pinput_id, true);
  if (values == nullptr || count != static_cast<int>(p->variables.size()))
    return fail(OPENMSS_ERROR_ARGUMENT, "PINPUT/" + std::to_string(pinput_id) + " lists " +
                                            std::to_string(p->variables.size()) +
                                            " VARIABLEs; the call gives " + std::to_string(count) +
                                            " values");
  for (int k = 0; k < count; ++k)
    if (!std::isfinite(values[k]))
      return fail(OPENMSS_ERROR_ARGUMENT, "PINPUT/" + std::to_string(pinput_id) + " value " +
                                              std::to_string(k + 1) + " is not finite");
  // A FUNCTION with DELAY keeps a history the run state points into; replacing it is refused.
  for (int k = 0; k < count; ++k) {
    const auto& v = solver->session->model()->variables[static_cast<std::size_t>(p->variables[k])];
    if (solver->inputs.count(p->variables[k]) == 0 && v.function.expression.delayCount() > 0) {
      return fail(OPENMSS_ERROR_INPUT,
                  v.where.file + ":" + std::to_string(v.where.line) + ": error: VARIABLE/" +
                      std::to_string(v.id) +
                      ": a plant input's FUNCTION cannot read DELAY. "
                      "Give the PINPUT VARIABLE a FUNCTION without DELAY (FUNCTION=0).",
                  v.where.file, v.where.line);
    }
  }
  for (int k = 0; k < count; ++k) solver->inputs[p->variables[k]] = values[k];
  return applyInputs(solver) == OPENMSS_OK ? ok() : OPENMSS_ERROR_ANALYSIS;
}

openmss_status openmss_get_poutput(const openmss_solver* solver, long poutput_id, double* values,
                                   int count) {
  if (!usable(solver)) return noSolver();
  const auto* p = plantList(solver, poutput_id, false);
  if (p == nullptr) return noPlantList(poutput_id, false);
  if (values == nullptr || count != static_cast<int>(p->variables.size()))
    return fail(OPENMSS_ERROR_ARGUMENT, "POUTPUT/" + std::to_string(poutput_id) + " lists " +
                                            std::to_string(p->variables.size()) +
                                            " VARIABLEs; the call asks for " +
                                            std::to_string(count));
  const auto& layout = solver->session->system()->layout();
  const Eigen::VectorXd y = consistentState(solver);
  for (int k = 0; k < count; ++k) values[k] = y(layout.userAlg(p->variables[k]));
  return ok();
}

openmss_status openmss_variable(const openmss_solver* solver, long variable_id, double* value) {
  if (!usable(solver)) return noSolver();
  if (value == nullptr) return fail(OPENMSS_ERROR_ARGUMENT, "the value pointer is null");
  const auto& vars = solver->session->model()->variables;
  for (std::size_t k = 0; k < vars.size(); ++k)
    if (vars[k].id == variable_id) {
      *value =
          consistentState(solver)(solver->session->system()->layout().userAlg(static_cast<int>(k)));
      return ok();
    }
  return fail(OPENMSS_ERROR_ARGUMENT,
              "VARIABLE/" + std::to_string(variable_id) + " is not in the data set");
}

openmss_status openmss_request(const openmss_solver* solver, long request_id, double values[8]) {
  if (!usable(solver)) return noSolver();
  if (values == nullptr) return fail(OPENMSS_ERROR_ARGUMENT, "the values pointer is null");
  const auto& session = *solver->session;
  for (const auto& r : session.model()->requests) {
    if (r.id != request_id) continue;
    const auto& st = *session.state();
    // Accelerations and reactions consistent with the positions and velocities, as the
    // output steps compute them (analysis/dynamic_run.cpp).
    Eigen::VectorXd y = st.y, yp = st.yp;
    if (st.initialized) openmss::mechanics::solveAccelerations(*session.system(), st.t, y, yp);
    const auto c = openmss::analysis::requestColumns(*session.system(), r, st.t, y, yp);
    for (int k = 0; k < 8; ++k) values[k] = c[static_cast<std::size_t>(k)];
    return ok();
  }
  return fail(OPENMSS_ERROR_ARGUMENT,
              "REQUEST/" + std::to_string(request_id) + " is not in the data set");
}

openmss_status openmss_save(openmss_solver* solver, const char* path) {
  if (!usable(solver)) return noSolver();
  if (path == nullptr) return fail(OPENMSS_ERROR_ARGUMENT, "the path is null");
  const openmss_status st = execute(solver, std::string("SAVE/STATES, FILE=") + path);
  return st == OPENMSS_ERROR_INPUT ? OPENMSS_ERROR_FILE : st;
}

openmss_status openmss_reload(openmss_solver* solver, const char* path) {
  if (!usable(solver)) return noSolver();
  if (path == nullptr) return fail(OPENMSS_ERROR_ARGUMENT, "the path is null");
  const openmss_status st = execute(solver, std::string("RELOAD/STATES, FILE=") + path);
  return st == OPENMSS_ERROR_INPUT ? OPENMSS_ERROR_FILE : st;
}

}  // extern "C"
