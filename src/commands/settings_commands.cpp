// Session: the commands that change the model's settings for later analyses: INTEGRATOR (and
// the FORTRAN-era GSTIFF, WSTIFF, DSTIFF), OUTPUT, EQUILIBRIUM, IC and KINEMATICS (docs/theory.md
// §7 and "Statics"), DEBUG. A rejected command leaves the settings as they were.

#include "analysis/analysis_context.hpp"
#include "analysis/integrator_factory.hpp"
#include "commands/session.hpp"
#include "model/model_builder.hpp"
#include "model/settings_arguments.hpp"

namespace openmss::commands {
namespace {

using analysis::formatNumber;

std::string patternText(const model::RefreshPattern& p) {
  std::string s;
  for (size_t k = 0; k < p.evaluate.size(); ++k)
    s += std::string(k ? ":" : "") + (p.evaluate[k] ? "T" : "F");
  return s;
}

std::string equilibriumListing(const model::EquilibriumSettings& e) {
  return " EQUILIBRIUM: ALIMIT=" + formatNumber("%g", e.angleLimit) +
         " rad, ERROR=" + formatNumber("%g", e.error) +
         ", IMBALANCE=" + formatNumber("%g", e.imbalance) + ", MAXIT=" + std::to_string(e.maxit) +
         ", PATTERN=" + patternText(e.pattern) + ", STABILITY=" + formatNumber("%g", e.stability) +
         ", TLIMIT=" + formatNumber("%g", e.translationLimit);
}

std::string initialConditionListing(const model::InitialConditionSettings& i) {
  return " IC: AERROR=" + formatNumber("%g", i.accelerationError) +
         ", ALIMIT=" + formatNumber("%g", i.angleLimit) +
         " rad, AMAXIT=" + std::to_string(i.accelerationMaxit) +
         ", APATTERN=" + patternText(i.accelerationPattern) +
         ", ERROR=" + formatNumber("%g", i.error) + ", MAXIT=" + std::to_string(i.maxit) +
         ", PATTERN=" + patternText(i.pattern) +
         ", TLIMIT=" + formatNumber("%g", i.translationLimit) +
         ", VERROR=" + formatNumber("%g", i.velocityError);
}

std::string kinematicListing(const model::KinematicSettings& k) {
  return " KINEMATICS: AERROR=" + formatNumber("%g", k.accelerationError) +
         ", ALIMIT=" + formatNumber("%g", k.angleLimit) +
         " rad, AMAXIT=" + std::to_string(k.accelerationMaxit) +
         ", APATTERN=" + patternText(k.accelerationPattern) +
         ", ERROR=" + formatNumber("%g", k.error) +
         ", HMAX=" + (k.hmax ? formatNumber("%g", *k.hmax) : std::string("(output step)")) +
         ", MAXIT=" + std::to_string(k.maxit) + ", PATTERN=" + patternText(k.pattern) +
         ", TLIMIT=" + formatNumber("%g", k.translationLimit);
}

}  // namespace

bool Session::setOutput(const language::Statement& c) {
  for (const auto& a : c.args) {
    if (a.name == "NOSEPARATOR")
      model_->output.noseparator = true;
    else if (a.name == "SEPARATOR")
      model_->output.noseparator = false;
    else if (a.name == "REQSAVE")
      model_->output.reqsave = true;
    else if (a.name == "NOPRINT")  // no further .out steps (docs/output-files.md)
      results_.noPrint = true;
    else {
      Diagnostic d;
      d.severity = Severity::Warning;
      d.where = a.where;
      d.subject = c.subject();
      d.message = a.name + " is not supported yet and has no effect";
      d.hint = "Remove it to silence this warning.";
      diagnostic(d);
    }
  }
  return true;
}

// The same arguments as the INTEGRATOR statement (model/analysis_settings.cpp).
bool Session::setIntegrator(const language::Statement& c) {
  Diagnostics local;
  model::IntegratorSettings next = model_->integrator;
  const bool ok = model::applyIntegratorArguments(
      c, next, local, c.name == "INTEGRATOR" ? nullptr : c.name.c_str());
  reportAll(local);
  if (!ok) return false;
  if (const auto why = analysis::integratorUnavailable(next)) {
    error(c, *why, "Choose another integrator (docs/integrators.md).");
    return false;
  }
  model_->integrator = next;
  return true;
}

bool Session::setAnalysisParameters(const language::Statement& c) {
  model::Model& m = *model_;
  Diagnostics local;
  // Applied to a copy: a rejected command leaves the settings as they were.
  bool ok = false;
  if (c.name == "EQUILIBRIUM") {
    model::EquilibriumSettings next = m.equilibrium;
    if ((ok = model::applyEquilibriumArguments(c, next, local))) m.equilibrium = next;
  } else if (c.name == "KINEMATICS") {
    model::KinematicSettings next = m.kinematics;
    if ((ok = model::applyKinematicArguments(c, next, local))) m.kinematics = next;
  } else {
    model::InitialConditionSettings next = m.initialConditions;
    if ((ok = model::applyInitialConditionArguments(c, next, local))) m.initialConditions = next;
  }
  reportAll(local);
  if (c.has("LIST"))
    msg_.line(c.name == "EQUILIBRIUM"  ? equilibriumListing(m.equilibrium)
              : c.name == "KINEMATICS" ? kinematicListing(m.kinematics)
                                       : initialConditionListing(m.initialConditions));
  return ok;
}

bool Session::setDebug(const language::Statement& c) {
  Diagnostics local;
  model::applyDebugArguments(c, model_->debug, local);
  reportAll(local);
  if (c.has("LIST"))
    msg_.line(std::string(" DEBUG: EPRINT ") + (model_->debug.eprint ? "on" : "off"));
  return !local.hasErrors();
}

}  // namespace openmss::commands
