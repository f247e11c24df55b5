// Session: CONTROL/FUNCTION=USER(r1[, ..., r30]) [, ROUTINE=lib::name] hands the run to the
// user's CONSUB (user/control_routine.hpp; docs/user-subroutines.md, "CONSUB"). Inside it:
// - ANALYS(antype, cid, timbeg, timend, init) runs SIMULATE/<antype>, END=timend, STEPS=1
//   without writing output (the output of a CONSUB run is what DATOUT writes), from timbeg,
//   which must be the current time; init nonzero solves the initial conditions again first;
// - DATOUT writes one output step (.req, .out, .res) at the current state;
// - MODIFY executes one command, as if it stood in the command file after CONTROL.
// Every diagnostic is located at the CONTROL command. ANALYS through SIMULATE means a CONSUB
// sequence and the same commands written in an .acf take the same steps: their output at the
// same times is bit-identical (tests/user/consub_test.cpp).

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "analysis/model_summary.hpp"
#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "model/user_subroutine_arguments.hpp"
#include "user/control_routine.hpp"

namespace openmss::commands {
namespace {

std::string exact(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

}  // namespace

bool Session::control(const language::Statement& c) {
  Diagnostics local;
  const auto par = model::userParameters(c, local);
  reportAll(local);
  if (!par) return false;
  std::string why;
  const auto routine =
      user::ControlRoutine::load(model::elementRoutineName(c), modelDirectory(), why);
  if (!routine) {
    error(c, why, "Build the library with a CONSUB (docs/user-subroutines.md, \"CONSUB\").");
    return false;
  }
  if (options_.checkOnly) return true;  // found; not run
  msg_.line(" CONTROL: CONSUB (" + routine->symbolName() + ") starts at time " +
            analysis::formatNumber("%g", state_->t));
  user::ControlHooks hooks;
  hooks.analys = [&](const std::string& antype, const std::string& cid, double timbeg,
                     double timend,
                     bool init) { return controlAnalys(c, antype, cid, timbeg, timend, init); };
  hooks.datout = [&] { return controlDatout(c); };
  hooks.modify = [&](const std::string& text) { return controlModify(c, text); };
  const std::string fatal = routine->run(*par, hooks);
  outputSuppressed_ = false;
  if (!fatal.empty()) {
    error(c, fatal,
          "CONSUB ended the control sequence; the outputs written so far are complete. "
          "Later commands run from the state it left.");
    return false;
  }
  msg_.line(" CONTROL: CONSUB returned at time " + analysis::formatNumber("%g", state_->t));
  return true;  // a SENSOR's HALT inside an ANALYS stopped the session as STOP does
}

int Session::controlAnalys(const language::Statement& c, const std::string& antype,
                           const std::string& cid, double timbeg, double timend, bool init) {
  const bool statics = antype == "STATIC" || antype == "STATICS";
  const bool transient = antype == "TRANSIENT" || antype == "DYNAMICS" || antype == "KINEMATICS";
  if (!statics && !transient) {
    error(c, "CONSUB: ANALYS of an unknown analysis type \"" + antype + "\"",
          "Use TRANSIENT, DYNAMICS, KINEMATICS, STATIC or STATICS.");
    return 1;
  }
  // TIMBEG must be the current time: ADAMS continues from the state, it does not jump. A
  // relative 1e-12 allows a time the user computed by adding steps.
  const double now = state_->t;
  if (!std::isfinite(timbeg) || !std::isfinite(timend) ||
      std::abs(timbeg - now) > 1e-12 * std::max(1.0, std::abs(now)) ||
      (transient && !(timend > now))) {
    error(c,
          "CONSUB: ANALYS " + antype + " from " + exact(timbeg) + " to " + exact(timend) +
              " at time " + exact(now) + ": TIMBEG must be the current time and TIMEND after it",
          "Pass the current time (TIMGET) as TIMBEG; nothing was run.");
    return 1;
  }
  const std::string text = statics ? std::string("SIMULATE/STATICS")
                                   : "SIMULATE/" + antype + ", END=" + exact(timend) + ", STEPS=1";
  language::CommandReader reader(c.where.file, c.where.line);
  reader.feedLine(text);
  reader.finish();
  reportAll(reader.takeDiagnostics());
  auto commands = reader.takeCommands();
  if (commands.size() != 1) return 1;
  msg_.line(" CONSUB: ANALYS " + antype + (cid.empty() ? "" : " \"" + cid + "\"") + " (" + text +
            ")");
  if (init) state_->initialized = false;  // the initial conditions are solved again
  outputSuppressed_ = true;
  const bool ok = simulate(commands[0]);
  outputSuppressed_ = false;
  return ok ? 0 : 1;
}

int Session::controlDatout(const language::Statement& c) {
  if (!state_->initialized) {
    error(c, "CONSUB: DATOUT before an analysis has solved the state",
          "Call ANALYS first; nothing was written.");
    return 1;
  }
  const std::string& last = state_->summary.analysis;
  const output::OutputKind kind = last == "static"      ? output::OutputKind::Static
                                  : last == "kinematic" ? output::OutputKind::Kinematic
                                                        : output::OutputKind::Dynamic;
  return context().writeOutputStep(state_->t, state_->y, state_->yp, kind) ? 0 : 1;
}

int Session::controlModify(const language::Statement& c, const std::string& text) {
  language::CommandReader reader(c.where.file, c.where.line);
  reader.feedLine(text);
  reader.finish();
  const Diagnostics read = reader.takeDiagnostics();
  reportAll(read);
  if (read.hasErrors()) return 1;
  for (const auto& command : reader.takeCommands()) {
    if (command.name == "CONTROL" || command.name == "FILE" || command.name == "STOP" ||
        command.name == "HELP") {
      error(c, "CONSUB: MODIFY cannot run " + command.name,
            "CONSUB returns to the command file, which may give it after CONTROL.");
      return 1;
    }
    echoCommand(text);  // the .msg, and SAVE/SYSTEM's history of model changes
    if (!execute(command)) return 1;
  }
  return 0;
}

}  // namespace openmss::commands
