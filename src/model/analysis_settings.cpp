#include "model/analysis_settings.hpp"
#include "model/settings_arguments.hpp"

#include <string>

#include "model/statement_arguments.hpp"

namespace openmss::model {
namespace {

// PATTERN=c1:...:c10 (T or F each). The values given repeat until MAXIT (docs/language.md,
// "EQUILIBRIUM and IC"): T:F means every other iteration.
void readPattern(StatementArguments& r, const language::Argument& a, RefreshPattern& out) {
  if (a.values.empty() || a.values.size() > 10) {
    r.error(a, a.name + " takes 1 to 10 of T and F", "Write " + a.name + "=T:F:F:F, for example.");
    return;
  }
  std::array<bool, 10> flags{};
  for (size_t k = 0; k < 10; ++k) {
    const std::string& w = a.values[k % a.values.size()].text;
    flags[k] = w == "T" || w == "TRUE";
  }
  out.evaluate = flags;
}

}  // namespace

bool applyEquilibriumArguments(const language::Statement& s, EquilibriumSettings& settings,
                               Diagnostics& diags) {
  StatementArguments r(s, diags);
  if (s.has("DEFAULT")) settings = {};
  for (const language::Argument& a : s.args) {
    if (a.name == "DEFAULT" || a.name == "LIST" || a.name == "STATIC") continue;
    if (a.name == "ALIMIT")
      r.positive(a, settings.angleLimit);
    else if (a.name == "ERROR")
      r.positive(a, settings.error);
    else if (a.name == "IMBALANCE")
      r.positive(a, settings.imbalance);
    else if (a.name == "MAXIT")
      r.count(a, settings.maxit);
    else if (a.name == "PATTERN")
      readPattern(r, a, settings.pattern);
    else if (a.name == "STABILITY")
      r.positive(a, settings.stability);
    else if (a.name == "TLIMIT")
      r.positive(a, settings.translationLimit);
    else
      r.unsupported(a,
                    "Static equilibrium is found by Newton-Raphson on the balance equations "
                    "(docs/theory.md, Statics); dynamic relaxation and its parameters are not "
                    "implemented. Remove " +
                        a.name + ".");
  }
  return r.ok();
}

bool applyInitialConditionArguments(const language::Statement& s,
                                    InitialConditionSettings& settings, Diagnostics& diags) {
  StatementArguments r(s, diags);
  if (s.has("DEFAULT")) settings = {};
  for (const language::Argument& a : s.args) {
    if (a.name == "DEFAULT" || a.name == "LIST") continue;
    if (a.name == "AERROR")
      r.positive(a, settings.accelerationError);
    else if (a.name == "ALIMIT")
      r.positive(a, settings.angleLimit);
    else if (a.name == "AMAXIT")
      r.count(a, settings.accelerationMaxit);
    else if (a.name == "APATTERN")
      readPattern(r, a, settings.accelerationPattern);
    else if (a.name == "ERROR")
      r.positive(a, settings.error);
    else if (a.name == "MAXIT")
      r.count(a, settings.maxit);
    else if (a.name == "PATTERN")
      readPattern(r, a, settings.pattern);
    else if (a.name == "TLIMIT")
      r.positive(a, settings.translationLimit);
    else if (a.name == "VERROR")
      r.positive(a, settings.velocityError);
    else
      r.unsupported(a, "Remove " + a.name + ".");
  }
  return r.ok();
}

bool applyKinematicArguments(const language::Statement& s, KinematicSettings& settings,
                             Diagnostics& diags) {
  StatementArguments r(s, diags);
  if (s.has("DEFAULT")) settings = {};
  for (const language::Argument& a : s.args) {
    if (a.name == "DEFAULT" || a.name == "LIST") continue;
    if (a.name == "AERROR") {
      r.positive(a, settings.accelerationError);
    } else if (a.name == "ALIMIT") {
      r.positive(a, settings.angleLimit);
    } else if (a.name == "AMAXIT" || a.name == "APATTERN") {
      // Read (and checked) for the LIST output, but the acceleration phase is one direct solve
      // of the linear saddle-point system (docs/theory.md §7): no iterations to limit.
      if (a.name == "AMAXIT")
        r.count(a, settings.accelerationMaxit);
      else
        readPattern(r, a, settings.accelerationPattern);
      diags.warning(a.where, s.subject(),
                    a.name + " has no effect: the accelerations and forces of a kinematic "
                             "analysis are one direct linear solve, without iterations",
                    "Remove " + a.name + " to silence this warning.");
    } else if (a.name == "ERROR") {
      r.positive(a, settings.error);
    } else if (a.name == "HMAX") {
      r.positive(a, settings.hmax.emplace());
    } else if (a.name == "MAXIT") {
      r.count(a, settings.maxit);
    } else if (a.name == "PATTERN") {
      readPattern(r, a, settings.pattern);
    } else if (a.name == "TLIMIT") {
      r.positive(a, settings.translationLimit);
    } else {
      r.unsupported(a, "docs/language.md lists the KINEMATICS arguments; remove " + a.name + ".");
    }
  }
  return r.ok();
}

const char* integratorTypeName(IntegratorType type) {
  switch (type) {
    case IntegratorType::Gstiff: return "GSTIFF";
    case IntegratorType::Wstiff: return "WSTIFF";
    case IntegratorType::Dstiff: return "DSTIFF";
    case IntegratorType::Hht: return "HHT";
    case IntegratorType::Newmark: return "NEWMARK";
    case IntegratorType::Abam: return "ABAM";
    case IntegratorType::ConstantBdf: return "CONSTANT_BDF";
    case IntegratorType::Hastiff: return "HASTIFF";
    case IntegratorType::Cpbdf: return "CPBDF";
    case IntegratorType::Merson: return "MERSON";
  }
  return "?";
}

const char* formulationName(IntegratorFormulation f) {
  switch (f) {
    case IntegratorFormulation::I3: return "I3";
    case IntegratorFormulation::Si2: return "SI2";
    case IntegratorFormulation::Si1: return "SI1";
  }
  return "?";
}

bool applyIntegratorArguments(const language::Statement& s, IntegratorSettings& settings,
                              Diagnostics& diags, const char* method) {
  StatementArguments r(s, diags);
  if (s.has("DEFAULT")) settings = {};
  using T = IntegratorType;
  using F = IntegratorFormulation;
  static const std::pair<const char*, T> kTypes[] = {
      {"GSTIFF", T::Gstiff}, {"WSTIFF", T::Wstiff},   {"DSTIFF", T::Dstiff},
      {"HHT", T::Hht},       {"NEWMARK", T::Newmark}, {"ABAM", T::Abam},
      {"CONSTANT_BDF", T::ConstantBdf}, {"HASTIFF", T::Hastiff}, {"CPBDF", T::Cpbdf},
      {"MERSON", T::Merson}};
  if (method)
    for (const auto& [name, type] : kTypes)
      if (std::string(method) == name) settings.type = type;
  for (const language::Argument& a : s.args) {
    bool isType = false;
    for (const auto& [name, type] : kTypes)
      if (a.name == name) {
        settings.type = type;
        isType = true;
      }
    if (a.name == "CONSTANT_BDF" || a.name == "HASTIFF" || a.name == "CPBDF")
      r.unsupported(a, "Use GSTIFF or WSTIFF (BDF), DSTIFF (IDA), HHT or NEWMARK; "
                       "docs/integrators.md compares them.");
    if (isType || a.name == "DEFAULT" || a.name == "LIST") continue;
    if (a.name == "SI2_GSTIFF") {
      settings.type = T::Gstiff;
      settings.formulation = F::Si2;
    } else if (a.name == "I3") {
      settings.formulation = F::I3;
    } else if (a.name == "SI2") {
      settings.formulation = F::Si2;
    } else if (a.name == "SI1") {
      r.unsupported(a, "SI1 is a FORTRAN-solver formulation without a published definition; "
                       "use I3 or SI2.");
    } else if (a.name == "ERROR") {
      r.positive(a, settings.error.emplace());
    } else if (a.name == "HINIT") {
      r.positive(a, settings.hinit.emplace());
    } else if (a.name == "HMAX") {
      r.positive(a, settings.hmax.emplace());
    } else if (a.name == "HMIN") {
      r.positive(a, settings.hmin.emplace());
    } else if (a.name == "KMAX") {
      double k = 6;
      r.within(a, 1, 12, "a whole number from 1 to 12 (6 for the BDF integrators)", k);
      settings.kmax = static_cast<int>(k);
    } else if (a.name == "MAXIT") {
      r.count(a, settings.maxit);
    } else if (a.name == "PATTERN") {
      readPattern(r, a, settings.pattern.emplace());
    } else if (a.name == "INTERPOLATE") {
      settings.interpolate = !a.values.empty() && a.values[0].text == "ON";
    } else if (a.name == "ALPHA") {
      r.within(a, -1.0 / 3.0, 0.0, "between -1/3 and 0", settings.alpha);
    } else if (a.name == "BETA") {
      r.positive(a, settings.beta.emplace());
    } else if (a.name == "GAMMA") {
      r.positive(a, settings.gamma.emplace());
    } else if (a.name == "ADAPTIVITY") {
      r.positive(a, settings.adaptivity.emplace());
    } else if (a.name == "CORRECTOR") {
      // ORIGINAL: every differential unknown converges; MODIFIED: those of the error test
      // (docs/integrators.md, "Corrector"). ORIG_CONSTANT is ORIGINAL without ADAMS's
      // automatic switch to MODIFIED, which is never made here.
      settings.modifiedCorrector = !a.values.empty() && a.values[0].text == "MODIFIED";
    } else {
      r.unsupported(a, "docs/integrators.md lists the INTEGRATOR arguments implemented; "
                       "remove " + a.name + ".");
    }
  }
  // Combinations: SI2 belongs to the BDF family; NEWMARK must be unconditionally stable.
  // DSTIFF always runs on the SI2 form (docs/integrators.md, "DSTIFF and ABAM"), so SI2 is
  // accepted with it, and an explicit I3, which it cannot honour, is reported.
  if (settings.formulation == F::Si2 && settings.type != T::Gstiff &&
      settings.type != T::Wstiff && settings.type != T::Dstiff && !s.args.empty()) {
    const language::Argument* a = s.find("SI2") ? s.find("SI2") : &s.args.front();
    r.error(*a,
            std::string("the SI2 formulation applies to GSTIFF, WSTIFF and DSTIFF, not to ") +
                integratorTypeName(settings.type),
            "Write I3, or choose GSTIFF, WSTIFF or DSTIFF.");
  }
  if (settings.type == T::Dstiff && settings.formulation == F::I3 && s.find("I3")) {
    diags.warning(s.find("I3")->where, s.subject(),
                  "DSTIFF always runs on the SI2 formulation (on I3 its global error does not "
                  "follow ERROR; docs/integrators.md, \"DSTIFF and ABAM\"): I3 has no effect",
                  "Write SI2 or remove I3 to silence this warning.");
  }
  // MODIFIED on HHT and NEWMARK ignores the multipliers' changes (ADAMS), which their
  // corrector here never tests: accepted, the same corrector. DSTIFF (IDA's own test), ABAM and
  // MERSON have no such option.
  if (settings.modifiedCorrector && settings.type != T::Gstiff && settings.type != T::Wstiff &&
      settings.type != T::Hht && settings.type != T::Newmark) {
    r.error(*s.find("CORRECTOR"),
            std::string("CORRECTOR=MODIFIED is implemented for GSTIFF, WSTIFF, HHT and NEWMARK, "
                        "not for ") +
                integratorTypeName(settings.type),
            "Write CORRECTOR=ORIGINAL (or remove it), or choose GSTIFF, WSTIFF or HHT.");
    settings.modifiedCorrector = false;
  }
  // ADAPTIVITY loosens the corrector of GSTIFF and WSTIFF (and CONSTANT_BDF) only, as ADAMS
  // documents it (docs/integrators.md, "ADAPTIVITY"); the others run as without it, said so.
  if (settings.adaptivity && settings.type != T::Gstiff && settings.type != T::Wstiff)
    if (const language::Argument* a = s.find("ADAPTIVITY"))
      diags.warning(a->where, s.subject(),
                    std::string("ADAPTIVITY loosens the corrector of GSTIFF and WSTIFF only; it "
                                "has no effect on ") +
                        integratorTypeName(settings.type),
                    "Remove ADAPTIVITY to silence this warning.");
  // MERSON is one explicit fourth-order formula without a corrector or a Jacobian: an order
  // limit or a Jacobian pattern would be silently meaningless, so they are refused.
  if (settings.type == T::Merson)
    for (const char* name : {"KMAX", "PATTERN"})
      if (const language::Argument* a = s.find(name))
        r.error(*a, std::string("MERSON is an explicit method of fixed order 4 without a "
                                "Jacobian; ") + name + " does not apply to it",
                std::string("Remove ") + name + ", or choose GSTIFF for a variable-order "
                "implicit method.");
  if (settings.type == T::Newmark && (settings.beta || settings.gamma)) {
    const double beta = settings.beta.value_or(0.36), gamma = settings.gamma.value_or(0.7);
    if (!(gamma >= 0.5 && 2.0 * beta >= gamma)) {
      const language::Argument* a = s.find("BETA") ? s.find("BETA") : s.find("GAMMA");
      r.error(*a, "NEWMARK with BETA=" + std::to_string(beta) + " and GAMMA=" +
                      std::to_string(gamma) + " is not unconditionally stable",
              "Choose GAMMA >= 0.5 and BETA >= GAMMA/2, e.g. BETA=(GAMMA+0.5)^2/4.");
    }
  }
  // ALPHA = 0 (HHT) and GAMMA = 0.5 (NEWMARK) are in ADAMS's ranges, but the Newmark rule
  // without numerical damping is not stable on the index-3 equations (joints and motions, and
  // every part's orientation normalisation): the accelerations and reactions keep an undamped
  // oscillation, and the step size collapses (docs/integrators.md, "Without numerical
  // damping"). Run as asked, with a warning.
  const bool hht = settings.type == T::Hht;
  const double gamma =
      settings.gamma.value_or(hht ? (1.0 - 2.0 * settings.alpha) / 2.0 : 0.7);  // as resolved
  const language::Argument* undamped = s.find("GAMMA") ? s.find("GAMMA")
                                       : hht           ? s.find("ALPHA")
                                                       : nullptr;
  if ((hht || settings.type == T::Newmark) && gamma == 0.5 && undamped)
    diags.warning(undamped->where, s.subject(),
                  std::string(integratorTypeName(settings.type)) + " without numerical damping (" +
                      (undamped->name == "ALPHA" ? "ALPHA = 0" : "GAMMA = 0.5") +
                      ") is not stable on the index-3 equations of constrained or rotating "
                      "parts: the accelerations and reaction forces keep an undamped "
                      "oscillation and the step size collapses",
                  hht ? "Choose ALPHA below 0 (ADAMS's default is -0.3)."
                      : "Choose GAMMA above 0.5 (ADAMS's default is 0.7), or HHT.");
  return r.ok();
}

}  // namespace openmss::model
