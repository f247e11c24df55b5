// Session: the information commands (INFO, SHOW, TIME, MENU) and the commands that choose the
// solver's environment (PREFERENCES, LSOLVER, ENVIRONMENT, CONTROL); docs/commands.md.
// What they print goes to the message file and, with SessionOptions::printInformation, to
// stdout. CPU time is printed on stdout only: the message file stays identical run to run.

#include <cstdio>
#include <ctime>

#include "analysis/analysis_context.hpp"
#include "analysis/request_values.hpp"
#include "commands/session.hpp"
#include "language/schema.hpp"
#include "model/solver_preferences.hpp"

namespace openmss::commands {
namespace {

using analysis::formatNumber;

std::string fixed(double v) { return formatNumber("%14.6e", v); }

}  // namespace

bool Session::isInformationCommand(const std::string& name) {
  return name == "INFO" || name == "SHOW" || name == "TIME" || name == "MENU" ||
         name == "PREFERENCES" || name == "LSOLVER" || name == "ENVIRONMENT" || name == "CONTROL";
}

void Session::inform(const std::string& text, bool messageFile) {
  if (messageFile) msg_.line(text);
  if (options_.printInformation) std::printf("%s\n", text.c_str());
}

bool Session::informationCommand(const language::Statement& c) {
  if (c.name == "CONTROL") return control(c);  // control_command.cpp
  if (c.name == "INFO") return info(c);
  if (c.name == "SHOW" || c.name == "TIME") return show(c);
  if (c.name == "MENU") {
    std::string line = " Commands:";
    for (const auto& s : language::commandSchema()) {
      if (line.size() + s.name.size() > 78) {
        inform(line, false);
        line = "          ";
      }
      line += " " + s.name;
    }
    inform(line, false);
    return true;
  }
  return preferences(c);
}

bool Session::info(const language::Statement& c) {
  if (!applyEdits(c)) return false;
  model::Request r;
  int kinds = 0;
  const std::pair<const char*, model::Request::Kind> table[] = {
      {"DISPLACEMENT", model::Request::Kind::Displacement},
      {"VELOCITY", model::Request::Kind::Velocity},
      {"ACCELERATION", model::Request::Kind::Acceleration},
      {"FORCE", model::Request::Kind::Force}};
  const char* kindName = "";
  for (const auto& [name, kind] : table)
    if (c.has(name)) {
      r.kind = kind;
      kindName = name;
      ++kinds;
    }
  if (kinds != 1) {
    error(c, "INFO lists one of DISPLACEMENT, VELOCITY, ACCELERATION or FORCE",
          "Write e.g. INFO/DISPLACEMENT, I=20, J=10.");
    return false;
  }
  const struct {
    const char* name;
    int* index;
  } markers[] = {{"I", &r.iMarker}, {"J", &r.jMarker}, {"RM", &r.rmMarker}};
  for (const auto& m : markers) {
    const language::Argument* a = c.find(m.name);
    if (!a || a->values.empty() || a->values[0].number == 0) continue;
    const long id = static_cast<long>(a->values[0].number);
    const auto it = model_->markerIndex.find(id);
    if (it == model_->markerIndex.end()) {
      Diagnostic d;
      d.where = a->valueWhere;
      d.subject = c.subject();
      d.message = "MARKER/" + std::to_string(id) + " does not exist";
      d.hint = "Check the marker id.";
      diagnostic(d);
      return false;
    }
    *m.index = it->second;
  }
  if (r.iMarker < 0) {
    error(c, "INFO needs the I marker", "Add I=<marker id>.");
    return false;
  }
  const auto v = analysis::requestColumns(*system_, r, state_->t, state_->y, state_->yp);
  inform(" INFO/" + std::string(kindName) + " at time " + formatNumber("%g", state_->t) +
         (state_->initialized ? "" : " (before the initial conditions are solved)") + ":");
  inform("   x, y, z:    " + fixed(v[1]) + fixed(v[2]) + fixed(v[3]));
  inform(std::string(r.kind == model::Request::Kind::Displacement ? "   psi,theta,phi:"
                                                                  : "   ax, ay, az: ") +
         fixed(v[5]) + fixed(v[6]) + fixed(v[7]));
  return true;
}

bool Session::show(const language::Statement& c) {
  const analysis::RunSummary& s = summary();
  const bool all = c.name == "TIME" || c.args.empty();
  if (all || c.has("TIME") || c.has("STATUS")) {
    inform(" Simulation time " + formatNumber("%g", state_->t) + ", last analysis " +
           (s.analysis.empty() ? std::string("none") : s.analysis) + ", " +
           std::to_string(s.steps) + " integration steps, " + std::to_string(s.outputSteps) +
           " output steps, " + std::to_string(s.jacobians) + " Jacobians, " +
           std::to_string(s.residuals) + " residuals");
  }
  if (c.has("STATUS"))
    inform(" Degrees of freedom " + std::to_string(state_->degreesOfFreedom) +
           (state_->initialized ? ", initial conditions solved" : ", initial conditions pending"));
  if (all || c.has("CPU"))  // not in the .msg: CPU time differs from run to run
    inform(" CPU time " + formatNumber("%.2f", static_cast<double>(std::clock()) / CLOCKS_PER_SEC) +
               " s",
           false);
  if (c.has("GRAPHICS")) inform(" Graphics: none (OpenMSS writes no graphics display)");
  return true;
}

// PREFERENCES, LSOLVER, ENVIRONMENT: options that choose solver internals. Those that map onto
// OpenMSS are honoured (SIMFAIL=STOPCF); the others warn once each per session, named, and
// change nothing (model/solver_preferences.hpp, shared with the statements).
bool Session::preferences(const language::Statement& c) {
  Diagnostics local;
  model::applySolverPreferences(c, local);
  for (const auto& d : local.all())
    if (d.severity != Severity::Warning || warnedOptions_.insert(d.message).second) diagnostic(d);
  if (c.has("LIST")) inform(" " + c.name + ": OpenMSS defaults (one thread, its own LU)");
  return !local.hasErrors();
}

}  // namespace openmss::commands
