#include "commands/simulate_command.hpp"

#include <cmath>

#include "model/statement_arguments.hpp"

namespace openmss::commands {
namespace {

analysis::RunOrigin originOf(const language::Statement& c) { return {c.where, c.subject()}; }

std::string formatTime(double t) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", t);
  return buf;
}

// The output count of END with STEPS= or DTOUT= (0 when neither gives one).
long outputCount(const model::StatementArguments& args, double now, double end) {
  const auto steps = args.firstNumber("STEPS");
  const auto dtout = args.firstNumber("DTOUT");
  if (steps && *steps >= 1) return static_cast<long>(std::llround(*steps));
  if (dtout && *dtout > 0)
    return std::max(1L, static_cast<long>(std::llround((end - now) / *dtout)));
  return 0;
}

std::optional<SimulateRequest> readInitialConditions(model::StatementArguments& args) {
  const language::Statement& c = args.statement();
  for (const char* bad : {"END", "DURATION", "STEPS", "DTOUT"})
    if (c.has(bad)) {
      args.error(c.where, std::string(bad) + " has no meaning for SIMULATE/INITIAL_CONDITIONS",
                 "Remove it: the initial-condition analysis writes one output step at the current "
                 "time.");
      return std::nullopt;
    }
  analysis::InitialConditionsRun r;
  // Phases up to the one named (velocities need assembled positions, accelerations both).
  r.last = c.has("DISPLACEMENT") ? analysis::InitialConditionsPhase::Displacement
           : c.has("VELOCITY")   ? analysis::InitialConditionsPhase::Velocity
                                 : analysis::InitialConditionsPhase::Acceleration;
  r.origin = originOf(c);
  return r;
}

// SIMULATE/STATICS [, END | DURATION, STEPS | DTOUT]: one equilibrium at the current time,
// or a quasi-static sequence of equilibria at the output times.
std::optional<SimulateRequest> readStatics(model::StatementArguments& args, double now) {
  const language::Statement& c = args.statement();
  analysis::StaticsRun r;
  r.origin = originOf(c);
  auto end = args.firstNumber("END");
  if (auto duration = args.firstNumber("DURATION"); !end && duration) end = now + *duration;
  if (end) {
    if (*end <= now) {
      args.error(c.where,
                 "END (or DURATION) must give a time after the current time " + formatTime(now),
                 "Add END=<time> greater than the current time, or leave END out for one static "
                 "equilibrium.");
      return std::nullopt;
    }
    r.outputSteps = outputCount(args, now, *end);
    if (r.outputSteps == 0) {
      args.error(c.where, "a quasi-static run needs the output step",
                 "Add STEPS=<count> or DTOUT=<interval>.");
      return std::nullopt;
    }
  } else if (c.has("STEPS") || c.has("DTOUT")) {
    args.error(c.where, "STEPS and DTOUT need END (or DURATION) in a static analysis",
               "Add END=<time> for a quasi-static run, or remove STEPS/DTOUT for one equilibrium.");
    return std::nullopt;
  }
  r.end = end;
  return r;
}

std::optional<SimulateRequest> readTransient(model::StatementArguments& args, double now) {
  const language::Statement& c = args.statement();
  analysis::TransientRun r;
  r.kind = c.has("KINEMATICS") ? analysis::TransientKind::Kinematics
           : c.has("DYNAMICS") ? analysis::TransientKind::Dynamics
                               : analysis::TransientKind::Transient;
  r.origin = originOf(c);
  auto end = args.firstNumber("END");
  const auto duration = args.firstNumber("DURATION");
  if (!end && duration) end = now + *duration;
  if (!end || *end <= now) {
    args.error(c.where,
               "END (or DURATION) must give a time after the current time " + formatTime(now),
               "Add END=<time> greater than the current time.");
    return std::nullopt;
  }
  r.end = *end;
  r.outputSteps = outputCount(args, now, *end);
  if (r.outputSteps == 0) {
    args.error(c.where, "the output step is missing", "Add STEPS=<count> or DTOUT=<interval>.");
    return std::nullopt;
  }
  return r;
}

}  // namespace

std::optional<SimulateRequest> readSimulate(const language::Statement& c, double now,
                                            Diagnostics& diags) {
  model::StatementArguments args(c, diags);
  int kinds = 0;
  for (const char* k : {"DYNAMICS", "KINEMATICS", "STATICS", "TRANSIENT", "INITIAL_CONDITIONS"})
    kinds += c.has(k) ? 1 : 0;
  if (kinds == 0) {
    args.error(
        c.where, "the kind of simulation is missing",
        "Write SIMULATE/TRANSIENT (or DYNAMICS, KINEMATICS), END=..., DTOUT=... or STEPS=....");
    return std::nullopt;
  }
  if (kinds > 1) {
    args.error(c.where, "SIMULATE takes one kind of analysis",
               "Write one of DYNAMICS, KINEMATICS, STATICS, TRANSIENT, INITIAL_CONDITIONS.");
    return std::nullopt;
  }
  if (c.has("INITIAL_CONDITIONS")) return readInitialConditions(args);
  if (c.has("STATICS")) return readStatics(args, now);
  return readTransient(args, now);
}

}  // namespace openmss::commands
