// Session: SIMULATE/STATICS (static equilibrium and quasi-static runs), SIMULATE/
// INITIAL_CONDITIONS, and the EQUILIBRIUM and IC commands (docs/theory.md §7 and "Statics").

#include <cmath>
#include <cstdio>

#include "analysis/session.hpp"
#include "analysis/statics.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/user_state_solve.hpp"

namespace openmss::analysis {
namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::optional<double> numberOf(const language::Statement& s, const char* name) {
  const language::Argument* a = s.find(name);
  if (!a || a->values.empty() || a->values[0].kind != language::Value::Kind::Number)
    return std::nullopt;
  return a->values[0].number;
}

std::string patternText(const model::JacobianPattern& p) {
  std::string s;
  for (size_t k = 0; k < p.evaluate.size(); ++k)
    s += std::string(k ? ":" : "") + (p.evaluate[k] ? "T" : "F");
  return s;
}

const char* kCoordinateNames[6] = {"X", "Y", "Z", "PSI", "THETA", "PHI"};

// A redundant equation (not solved for) violated by more than this after assembly means the
// model cannot close: its data contradict the equations kept.
constexpr double kRedundantTolerance = 1e-6;

}  // namespace

bool Session::setAnalysisParameters(const language::Statement& c) {
  model::Model& m = *model_;
  Diagnostics local;
  const bool ok = c.name == "EQUILIBRIUM"
                      ? model::applyEquilibriumArguments(c, m.equilibrium, local)
                      : model::applyInitialConditionArguments(c, m.initialConditions, local);
  for (const auto& d : local.all()) {
    diags_.add(d);
    report(d);
  }
  if (c.has("LIST")) {
    if (c.name == "EQUILIBRIUM") {
      const auto& e = m.equilibrium;
      msg_.line(" EQUILIBRIUM: ALIMIT=" + fmt("%g", e.angleLimit) +
                " rad, ERROR=" + fmt("%g", e.error) + ", IMBALANCE=" + fmt("%g", e.imbalance) +
                ", MAXIT=" + std::to_string(e.maxit) + ", PATTERN=" + patternText(e.pattern) +
                ", STABILITY=" + fmt("%g", e.stability) +
                ", TLIMIT=" + fmt("%g", e.translationLimit));
    } else {
      const auto& i = m.initialConditions;
      msg_.line(
          " IC: AERROR=" + fmt("%g", i.accelerationError) + ", ALIMIT=" + fmt("%g", i.angleLimit) +
          " rad, AMAXIT=" + std::to_string(i.accelerationMaxit) +
          ", APATTERN=" + patternText(i.accelerationPattern) + ", ERROR=" + fmt("%g", i.error) +
          ", MAXIT=" + std::to_string(i.maxit) + ", PATTERN=" + patternText(i.pattern) +
          ", TLIMIT=" + fmt("%g", i.translationLimit) + ", VERROR=" + fmt("%g", i.velocityError));
    }
  }
  return ok;
}

mechanics::AssemblyResult Session::assembleForInitialConditions() {
  const model::Model& m = *model_;
  const model::InitialConditionSettings& ic = m.initialConditions;
  mechanics::AssemblyOptions o;
  o.tolerance = ic.error;
  o.maxIterations = ic.maxit;
  o.translationLimit = ic.translationLimit;
  o.angleLimit = ic.angleLimit;
  o.pattern = ic.pattern.evaluate;
  o.honourExact = true;
  o.holdJointInitialConditions = true;  // JOINT IC=, ICTRAN=, ICROT=
  mechanics::AssemblyResult r = mechanics::assemblePositions(*system_, t_, y_, o);
  // Equations found redundant at the data set's configuration are not solved for; a model whose
  // redundant equations disagree with the rest (a link too short to reach) cannot close either.
  if (r.converged) {
    const auto& eqs = system_->constraints().equations();
    for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
      if (eqs[k].active) continue;
      const double value = std::abs(system_->constraintValue(k, t_, y_.data()));
      if (value > kRedundantTolerance && value > r.residual) {
        r.converged = false;
        r.residual = value;
        r.worstEquation = k;
      }
    }
  }
  for (const auto& x : r.exactChanged) {
    const model::Part& p = m.parts[m.movingParts[x.body]];
    diags_.warning(p.where, "PART/" + std::to_string(p.id),
                   std::string("EXACT=") + kCoordinateNames[x.coordinate] +
                       " could not be held: the constraints changed it by " +
                       fmt("%.6E", x.change) + (x.coordinate < 3 ? "" : " rad"),
                   "The joints or motions demand another value; correct the part's position or "
                   "remove the coordinate from EXACT.");
    report(diags_.all().back());
  }
  return r;
}

bool Session::staticEquilibriumAt(double t) {
  const model::Model& m = *model_;
  Eigen::VectorXd y = y_;
  const EquilibriumResult r = solveStaticEquilibrium(*system_, t, y, m.equilibrium);
  using S = EquilibriumResult::Status;
  if (r.status == S::Unbalanced) {
    diags_.error({m.file, 0, 0}, "",
                 "there is no static equilibrium at time " + fmt("%.6E", t) + ": the " +
                     r.unbalanced->describe(m) +
                     " is a degree of freedom that nothing restrains, and a net generalised "
                     "force of " +
                     fmt("%.6E", std::abs(r.unbalanced->load)) +
                     " acts along it (its stiffness was zero at each of the " +
                     std::to_string(r.iterations + 1) + " configurations Newton tried)",
                 "Add a spring or a motion on that degree of freedom, balance the load, or run "
                 "SIMULATE/DYNAMICS to see where it goes.");
    report(diags_.all().back());
    return false;
  }
  if (r.status == S::NotConverged) {
    std::string text = "static equilibrium not found at time " + fmt("%.6E", t) + " in " +
                       std::to_string(r.iterations) + " iterations (MAXIT): largest imbalance " +
                       fmt("%.3E", r.imbalance) + " on PART/" +
                       std::to_string(m.parts[m.movingParts[r.worstBody]].id) +
                       ", last correction " + fmt("%.3E", r.correction) + ", constraint error " +
                       fmt("%.3E", r.constraintError);
    if (r.unbalanced) text += "; the stiffness is singular along the " + r.unbalanced->describe(m);
    diags_.error({m.file, 0, 0}, "", text,
                 "Raise MAXIT or loosen ERROR/IMBALANCE (EQUILIBRIUM), or start the model "
                 "nearer its equilibrium.");
    report(diags_.all().back());
    return false;
  }
  msg_.line("   Static equilibrium at time " + fmt("%.6E", t) + " after " +
            std::to_string(r.iterations) + " iterations: force imbalance " +
            fmt("%.3E", r.imbalance) + ", constraint error " + fmt("%.3E", r.constraintError));
  for (int b = 0; b < m.bodyCount(); ++b) {
    const int o = system_->layout().body(b);
    const double moved = (y.segment<3>(o) - y_.segment<3>(o)).norm();
    const double c = std::abs(y.segment<4>(o + mechanics::StateLayout::kE)
                                  .dot(y_.segment<4>(o + mechanics::StateLayout::kE)));
    const double turned = 2.0 * std::acos(std::min(1.0, c));
    if (moved > 1e-9 || turned > 1e-9)
      msg_.line("     PART/" + std::to_string(m.parts[m.movingParts[b]].id) + " moved by " +
                fmt("%.6E", moved) + " and turned by " + fmt("%.6E", turned) + " rad");
  }
  for (const auto& d : r.neutral) {
    diags_.warning({m.file, 0, 0}, "",
                   "the static equilibrium at time " + fmt("%.6E", t) + " is neutral: the " +
                       d.describe(m) +
                       " is free and unloaded, so the position along it is the "
                       "one the run started from",
                   "");
    report(diags_.all().back());
  }
  for (const auto& d : r.unstable) {
    diags_.warning({m.file, 0, 0}, "",
                   "the static equilibrium at time " + fmt("%.6E", t) +
                       " is unstable: its "
                       "stiffness along the " +
                       d.describe(m) + " is negative",
                   "A dynamic run started here will leave it; the stable equilibrium, if any, "
                   "lies elsewhere.");
    report(diags_.all().back());
  }
  y_ = y;
  t_ = t;
  yp_ = Eigen::VectorXd::Zero(y_.size());
  ++summary_.steps;
  // Outputs: positions and reactions of the equilibrium, zero velocities and accelerations.
  return writeOutputStep(t_, y_, yp_);
}

bool Session::simulateStaticsOrInitialConditions(const language::Statement& c) {
  const model::Model& m = *model_;
  int kinds = 0;
  for (const char* k : {"DYNAMICS", "KINEMATICS", "STATICS", "TRANSIENT", "INITIAL_CONDITIONS"})
    kinds += c.has(k) ? 1 : 0;
  if (kinds > 1) {
    error(c, "SIMULATE takes one kind of analysis",
          "Write one of DYNAMICS, KINEMATICS, STATICS, TRANSIENT, INITIAL_CONDITIONS.");
    return false;
  }

  if (c.has("INITIAL_CONDITIONS")) {
    // Phases up to the one named (velocities need assembled positions, accelerations both).
    const int last = c.has("DISPLACEMENT") ? 1 : c.has("VELOCITY") ? 2 : 3;
    for (const char* bad : {"END", "DURATION", "STEPS", "DTOUT"})
      if (c.has(bad)) {
        error(c, std::string(bad) + " has no meaning for SIMULATE/INITIAL_CONDITIONS",
              "Remove it: the initial-condition analysis writes one output step at the current "
              "time.");
        return false;
      }
    summary_.analysis = "initial conditions";
    m.analysisStatus.mode = model::AnalysisMode::InitialConditions;  // MODE = 3
    m.analysisStatus.clearIntegrator();
    if (last == 3) {
      if (!initialConditions()) return false;
      // Residual checks of the linear phases against VERROR and AERROR.
      const auto& ic = m.initialConditions;
      std::vector<int> rows;
      const Eigen::MatrixXd cj = mechanics::activeConstraintJacobian(*system_, y_.data(), &rows);
      Eigen::VectorXd u(6 * m.bodyCount());
      for (int b = 0; b < m.bodyCount(); ++b) {
        u.segment<3>(6 * b) = y_.segment<3>(system_->layout().body(b) + mechanics::StateLayout::kV);
        u.segment<3>(6 * b + 3) =
            y_.segment<3>(system_->layout().body(b) + mechanics::StateLayout::kW);
      }
      double verr = 0.0;
      for (size_t r = 0; r < rows.size(); ++r) {
        const auto& eq = system_->constraints().equations()[rows[r]];
        const double target = eq.motion >= 0 ? system_->motionJet(rows[r], t_).d1 : 0.0;
        verr = std::max(verr, std::abs(cj.row(static_cast<Eigen::Index>(r)).dot(u) - target));
      }
      Eigen::VectorXd g(y_.size());
      system_->residual(t_, y_.data(), yp_.data(), g.data());
      double aerr = 0.0;
      for (int b = 0; b < m.bodyCount(); ++b)
        for (int k = 0; k < 6; ++k)
          aerr = std::max(aerr,
                          std::abs(g(system_->layout().body(b) + mechanics::StateLayout::kV + k)));
      msg_.line("   Velocity constraint error " + fmt("%.3E", verr) + ", force balance error " +
                fmt("%.3E", aerr));
      if (verr > ic.velocityError || aerr > ic.accelerationError) {
        diags_.error({m.file, 0, 0}, "",
                     "the initial velocities or accelerations are inconsistent: velocity error " +
                         fmt("%.3E", verr) + " (VERROR " + fmt("%.3E", ic.velocityError) +
                         "), force balance error " + fmt("%.3E", aerr) + " (AERROR " +
                         fmt("%.3E", ic.accelerationError) + ")",
                     "The motions or initial velocities contradict the joints.");
        report(diags_.all().back());
        return false;
      }
    } else {
      msg_.line("");
      msg_.line(" Begin initial conditions (time " + fmt("%.6E", t_) + "), " +
                (last == 1 ? "displacements" : "displacements and velocities"));
      const mechanics::AssemblyResult r = assembleForInitialConditions();
      if (!reportAssembly(r)) return false;
      if (last == 2) mechanics::solveVelocities(*system_, t_, y_);
      // VARIABLE values and DIFF derivatives of the written step (docs/theory.md §4a).
      mechanics::solveUserAlgebraic(*system_, t_, y_);
      msg_.line(" End initial conditions: constraints satisfied to " + fmt("%.3E", r.residual));
    }
    ++summary_.steps;
    summary_.time = t_;
    return writeOutputStep(t_, y_, yp_);
  }

  // SIMULATE/STATICS [, END | DURATION, STEPS | DTOUT]: one equilibrium at the current time,
  // or a quasi-static sequence of equilibria at the output times.
  auto end = numberOf(c, "END");
  if (auto duration = numberOf(c, "DURATION"); !end && duration) end = t_ + *duration;
  long nOut = 0;
  if (end) {
    if (*end <= t_) {
      error(c, "END (or DURATION) must give a time after the current time " + fmt("%g", t_),
            "Add END=<time> greater than the current time, or leave END out for one static "
            "equilibrium.");
      return false;
    }
    const auto steps = numberOf(c, "STEPS");
    const auto dtout = numberOf(c, "DTOUT");
    if (steps && *steps >= 1)
      nOut = static_cast<long>(std::llround(*steps));
    else if (dtout && *dtout > 0)
      nOut = static_cast<long>(std::llround((*end - t_) / *dtout));
    else {
      error(c, "a quasi-static run needs the output step",
            "Add STEPS=<count> or DTOUT=<interval>.");
      return false;
    }
    nOut = std::max(1L, nOut);
  } else if (c.has("STEPS") || c.has("DTOUT")) {
    error(c, "STEPS and DTOUT need END (or DURATION) in a static analysis",
          "Add END=<time> for a quasi-static run, or remove STEPS/DTOUT for one equilibrium.");
    return false;
  }
  if (!initialized_) {
    msg_.line("");
    msg_.line(" Begin initial conditions (time " + fmt("%.6E", t_) + "), displacements");
    const mechanics::AssemblyResult r = assembleForInitialConditions();
    for (int b = 0; b < m.bodyCount(); ++b)
      if (r.partMoves[b] > 1e-9 || r.partTurns[b] > 1e-9)
        msg_.line("   PART/" + std::to_string(m.parts[m.movingParts[b]].id) + " moved by " +
                  fmt("%.6E", r.partMoves[b]) + " and turned by " + fmt("%.6E", r.partTurns[b]) +
                  " rad to satisfy the constraints");
    if (!r.converged) {
      diags_.error(
          {m.file, 0, 0}, "",
          "the model cannot be assembled: " + system_->constraints().describe(r.worstEquation, m) +
              " is still violated by " + fmt("%.6E", r.residual) + " after " +
              std::to_string(r.iterations) + " iterations",
          "Check the positions and orientations of that joint's I and J markers.");
      report(diags_.all().back());
      return false;
    }
  }
  const auto& e = m.equilibrium;
  msg_.line("");
  msg_.line(end ? " Begin quasi-static analysis" : " Begin static equilibrium analysis");
  msg_.line("   ERROR = " + fmt("%.3E", e.error) + ", IMBALANCE = " + fmt("%.3E", e.imbalance) +
            ", MAXIT = " + std::to_string(e.maxit) + ", STABILITY = " + fmt("%.3E", e.stability) +
            ", TLIMIT = " + fmt("%.3E", e.translationLimit) +
            ", ALIMIT = " + fmt("%.3E", e.angleLimit) + " rad");
  summary_.analysis = end ? "quasi-static" : "static";
  m.analysisStatus.mode = end ? model::AnalysisMode::QuasiStatics : model::AnalysisMode::Statics;
  m.analysisStatus.clearIntegrator();
  bool ok = staticEquilibriumAt(t_);
  const double t0 = t_;
  for (long i = 1; ok && i <= nOut; ++i) {
    const double t =
        (i == nOut) ? *end : t0 + static_cast<double>(i) * (*end - t0) / static_cast<double>(nOut);
    // Motions advance: close the constraints at the new time with the least change, then
    // balance the forces.
    const mechanics::AssemblyResult r = mechanics::assemblePositions(
        *system_, t, y_, m.initialConditions.error, m.initialConditions.maxit);
    if (!r.converged) {
      diags_.error({m.file, 0, 0}, "",
                   "quasi-static analysis failed at time " + fmt("%.6E", t) + ": " +
                       system_->constraints().describe(r.worstEquation, m) +
                       " cannot be satisfied (residual " + fmt("%.3E", r.residual) + ")",
                   "The mechanism may lock up or pass a singular position; check the motion "
                   "functions.");
      report(diags_.all().back());
      return false;
    }
    ok = staticEquilibriumAt(t);
  }
  summary_.time = t_;
  if (!ok) return false;
  // A later dynamic run starts from the equilibrium with velocities the motions demand.
  mechanics::solveVelocities(*system_, t_, y_);
  Eigen::VectorXd yDyn = y_, ypDyn;
  if (mechanics::solveAccelerations(*system_, t_, yDyn, ypDyn)) {
    y_ = yDyn;
    yp_ = ypDyn;
    initialized_ = true;
  }
  msg_.line(" End static analysis");
  return true;
}

}  // namespace openmss::analysis
