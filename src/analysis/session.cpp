#include "analysis/session.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "analysis/eprint_log.hpp"
#include "analysis/integrator_factory.hpp"
#include "analysis/multibody_dae.hpp"
#include "analysis/request_values.hpp"
#include "analysis/run_state_integrator.hpp"
#include "analysis/sensor_monitor.hpp"
#include "analysis/discrete_sampler.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/loop_count.hpp"
#include "mechanics/user_state_solve.hpp"
#include "mechanics/redundancy_check.hpp"
#include "model/model_builder.hpp"

namespace openmss::analysis {
namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

const language::Argument* arg(const language::Statement& s, const char* name) {
  return s.find(name);
}

std::optional<double> number(const language::Statement& s, const char* name) {
  const language::Argument* a = arg(s, name);
  if (!a || a->values.empty() || a->values[0].kind != language::Value::Kind::Number)
    return std::nullopt;
  return a->values[0].number;
}

// "SFORCE/104", "BUSHING/3", ... for diagnostics.
std::string forceElementName(const model::Model& m, const mechanics::ForceElementRef& e) {
  using K = mechanics::ForceElementKind;
  switch (e.kind) {
    case K::SForce:
      return "SFORCE/" + std::to_string(m.sforces[e.index].id);
    case K::SpringDamper:
      return "SPRINGDAMPER/" + std::to_string(m.springDampers[e.index].id);
    case K::LinearField: {
      const auto& f = m.linearFields[e.index];
      const char* name = f.kind == model::LinearField::Kind::Bushing ? "BUSHING"
                         : f.kind == model::LinearField::Kind::Beam  ? "BEAM"
                                                                      : "FIELD";
      return std::string(name) + "/" + std::to_string(f.id);
    }
    case K::VectorForce: {
      const auto& f = m.vectorForces[e.index];
      const char* name = f.kind == model::VectorForce::Kind::VTorque  ? "VTORQUE"
                         : f.kind == model::VectorForce::Kind::GForce ? "GFORCE"
                                                                       : "VFORCE";
      return std::string(name) + "/" + std::to_string(f.id);
    }
  }
  return "?";
}

}  // namespace

Session::Session(SessionOptions options) : options_(std::move(options)) {}
Session::~Session() = default;

std::string Session::requestFilePath() const {
  return (std::filesystem::path(options_.outputDirectory) / (prefix_ + ".req")).string();
}
std::string Session::messageFilePath() const {
  return (std::filesystem::path(options_.outputDirectory) / (prefix_ + ".msg")).string();
}

void Session::report(const Diagnostic& d) {
  msg_.diagnostic(d);
  if (options_.echoDiagnostics) std::fprintf(stderr, "%s\n", format(d).c_str());
}

void Session::error(const language::Statement& s, const std::string& message,
                    const std::string& hint) {
  diags_.error(s.where, s.subject(), message, hint);
  report(diags_.all().back());
}

void Session::echoCommand(const std::string& text) { msg_.line(" command: " + text); }

bool Session::loadModel(const std::string& path, const std::string& outputPrefix) {
  prefix_ = outputPrefix;
  std::filesystem::create_directories(options_.outputDirectory);
  if (!msg_.open(messageFilePath())) {
    diags_.error({path, 0, 0}, "", "cannot create the message file " + messageFilePath(),
                 "Check that the output directory exists and is writable.");
    report(diags_.all().back());
    return false;
  }
  msg_.line("OpenMSS " + std::string(OPENMSS_VERSION) +
            " -- mechanical system simulation (ADAMS/Solver data sets)");
  msg_.line("");
  msg_.line(" command: FILE/MODEL=" + path + ", OUTPUT_PREFIX=" + prefix_);

  language::Dataset dataset;
  Diagnostics readDiags;
  language::readDatasetFile(path, dataset, readDiags);
  model_ = std::make_unique<model::Model>();
  model::buildModel(dataset, *model_, readDiags);  // model checks even after read errors
  for (const auto& d : readDiags.all()) {
    diags_.add(d);
    report(d);
  }
  msg_.line("");
  msg_.line(" Model title: " + dataset.title);
  // Only this data set's errors count: at the prompt, earlier commands may have failed.
  if (readDiags.hasErrors()) {
    msg_.line(" The data set has " + std::to_string(readDiags.errorCount()) +
              " error(s); no analysis is possible.");
    system_.reset();  // it refers to the model just replaced
    return false;
  }
  system_ = std::make_unique<mechanics::MultibodySystem>(*model_);
  // Cumulative angles and DELAY histories of this model's run (docs/theory.md §11a).
  runState_ = std::make_unique<mechanics::ExpressionRunState>(*model_);
  system_->setRunState(runState_.get());
  y_ = system_->initialState();
  yp_ = Eigen::VectorXd::Zero(y_.size());
  t_ = 0.0;
  initialized_ = false;  // a model loaded at the prompt after a run starts afresh

  // Model summary and degree-of-freedom analysis at the data set's configuration.
  const model::Model& m = *model_;
  gruebler_ = mechanics::ConstraintSet::grueblerCount(m);
  auto redundancy = mechanics::removeRedundantConstraints(*system_, y_);
  dof_ = 6 * m.bodyCount() - redundancy.rank;
  msg_.line("");
  msg_.line(" Model summary");
  msg_.line("   Units:                " + m.units.description + ", UCF = " +
            fmt("%.10g", m.units.ucf));
  msg_.line("   Moving parts:         " + std::to_string(m.bodyCount()) + " (plus ground)");
  msg_.line("   Markers:              " + std::to_string(m.markers.size()));
  msg_.line("   Joints:               " + std::to_string(m.joints.size()));
  msg_.line("   Motions:              " + std::to_string(m.motions.size()));
  msg_.line("   SFORCEs:              " + std::to_string(m.sforces.size()));
  msg_.line("   Other force elements: " +
            std::to_string(m.springDampers.size() + m.linearFields.size() +
                           m.vectorForces.size()) +
            " (SPRINGDAMPER, BUSHING, FIELD, BEAM, VFORCE, VTORQUE, GFORCE)");
  if (m.userDifferentialCount() + m.userAlgebraicCount() > 0)  // docs/theory.md §4a
    msg_.line("   User equations:       " + std::to_string(m.variables.size()) + " VARIABLE, " +
              std::to_string(m.diffs.size()) + " DIFF, " + std::to_string(m.linearStates.size()) +
              " LSE/TFSISO, " + std::to_string(m.generalStates.size()) + " GSE; " +
              std::to_string(m.userDifferentialCount()) +
              " user states integrated");
  msg_.line("   Requests:             " + std::to_string(m.requests.size()));
  msg_.line("   Constraint equations: " + std::to_string(system_->constraints().size()));
  msg_.line("   Gruebler count:       " + std::to_string(gruebler_) + " degrees of freedom");
  msg_.line("   Degrees of freedom:   " + std::to_string(dof_) +
            " (from the rank of the constraint Jacobian)");
  if (const auto loops = mechanics::countLoops(m); true)
    msg_.line("   Loops:                " + std::to_string(loops.independent) + " independent, " +
              (loops.enumerated ? std::to_string(loops.dependent) : "(not enumerated)") +
              " dependent");
  for (int k : redundancy.removed) {
    const std::string text = "redundant constraint equation removed: " +
                             system_->constraints().describe(k, m) +
                             " (its reaction is carried by the equations kept)";
    diags_.warning({m.file, 0, 0}, "", text);
    report(diags_.all().back());
  }
  return true;
}

bool Session::execute(const language::Statement& c) {
  if (c.name == "STOP") {
    stopped_ = true;
    msg_.line("");
    msg_.line(" Finished -----");
    req_.close();
    return true;
  }
  if (!system_) {
    error(c, "no model is loaded", "Load a data set first (line 1 of the .acf, or FILE/MODEL=).");
    return false;
  }
  if (c.name == "SIMULATE") return simulate(c);
  if (c.name == "INTEGRATOR" || c.name == "GSTIFF" || c.name == "WSTIFF" || c.name == "DSTIFF")
    return setIntegrator(c);
  if (c.name == "OUTPUT") return setOutput(c);
  if (c.name == "EQUILIBRIUM" || c.name == "IC") return setAnalysisParameters(c);
  if (c.name == "LINEAR") return linear(c);
  if (c.name == "DEBUG") return setDebug(c);
  error(c, c.name + " is not supported yet by the solver",
        "README.md lists the supported commands; remove this one or run it elsewhere.");
  return false;
}

bool Session::setOutput(const language::Statement& c) {
  for (const auto& a : c.args) {
    if (a.name == "NOSEPARATOR") model_->output.noseparator = true;
    else if (a.name == "SEPARATOR") model_->output.noseparator = false;
    else if (a.name == "REQSAVE") model_->output.reqsave = true;
    else {
      diags_.warning(a.where, c.subject(), a.name + " is not supported yet and has no effect",
                     "Remove it to silence this warning.");
      report(diags_.all().back());
    }
  }
  return true;
}

// INTEGRATOR command, and the FORTRAN-era GSTIFF/WSTIFF/DSTIFF commands that select their
// method: the same arguments as the statement (model/analysis_settings.cpp). A rejected
// command leaves the settings as they were.
bool Session::setIntegrator(const language::Statement& c) {
  Diagnostics local;
  model::IntegratorSettings next = model_->integrator;
  const bool ok = model::applyIntegratorArguments(
      c, next, local, c.name == "INTEGRATOR" ? nullptr : c.name.c_str());
  for (const auto& d : local.all()) {
    diags_.add(d);
    report(d);
  }
  if (!ok) return false;
  if (const auto why = integratorUnavailable(next)) {
    error(c, *why, "Choose another integrator (docs/integrators.md).");
    return false;
  }
  model_->integrator = next;
  return true;
}

bool Session::reportAssembly(const mechanics::AssemblyResult& r) {
  const model::Model& m = *model_;
  for (int b = 0; b < m.bodyCount(); ++b)
    if (r.partMoves[b] > 1e-9 || r.partTurns[b] > 1e-9)
      msg_.line("   PART/" + std::to_string(m.parts[m.movingParts[b]].id) + " moved by " +
                fmt("%.6E", r.partMoves[b]) + " and turned by " + fmt("%.6E", r.partTurns[b]) +
                " rad to satisfy the constraints");
  if (r.converged) return true;
  diags_.error({m.file, 0, 0}, "",
               "the model cannot be assembled: " +
                   system_->constraints().describe(r.worstEquation, m) + " is still violated by " +
                   fmt("%.6E", r.residual) + " after " + std::to_string(r.iterations) +
                   " iterations",
               "Check the positions and orientations of that joint's I and J markers.");
  report(diags_.all().back());
  return false;
}

bool Session::initialConditions() {
  const model::Model& m = *model_;
  msg_.line("");
  msg_.line(" Begin initial conditions (time " + fmt("%.6E", t_) + ")");
  m.analysisStatus.mode = model::AnalysisMode::InitialConditions;  // MODE = 3
  auto asm_ = assembleForInitialConditions();  // IC parameters and EXACT (session_statics.cpp)
  if (!reportAssembly(asm_)) return false;
  mechanics::solveVelocities(*system_, t_, y_, /*holdJointInitialConditions=*/true);
  // VARIABLE values and DIFF derivatives (docs/theory.md §4a): a loop without a solution is
  // named here rather than reported as a singular acceleration problem.
  if (const auto user = mechanics::solveUserAlgebraic(*system_, t_, y_); !user.converged) {
    diags_.error({m.file, 0, 0}, "",
                 "the user equations cannot be solved at the initial state: " +
                     MultibodyDae(*system_).equationName(
                         system_->layout().userAlg(std::max(0, user.worstRow))) +
                     " is still violated by " + fmt("%.3E", user.residual) +
                     (user.singular ? " (their Jacobian is singular)"
                                    : " after " + std::to_string(user.iterations) +
                                          " Newton iterations"),
                 "Check the VARIABLE and DIFF functions for an algebraic loop without a solution "
                 "(VARIABLE/1, FUNCTION=VARVAL(1)+1 has none), or give IC= starting values.");
    report(diags_.all().back());
    return false;
  }
  if (!mechanics::solveAccelerations(*system_, t_, y_, yp_)) {
    diags_.error({m.file, 0, 0}, "",
                 "the accelerations and constraint forces at the initial state cannot be "
                 "determined (singular mass or constraint matrix)",
                 "Check that every moving part has mass and inertia, or is fully constrained.");
    report(diags_.all().back());
    return false;
  }
  msg_.line(" End initial conditions: constraints satisfied to " + fmt("%.3E", asm_.residual));
  initialized_ = true;
  return true;
}

bool Session::writeOutputStep(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
  const model::Model& m = *model_;
  // Every output step of every analysis passes here: a redundant equation that has come
  // apart stops the run before the step is written (mechanics/redundancy_check.hpp).
  if (const auto bad = mechanics::violatedRedundantEquation(
          *system_, t, y.data(), mechanics::redundantTolerance(m))) {
    diags_.error({m.file, 0, 0}, "", mechanics::describeViolation(*system_, *bad, t),
                 "Make the duplicated constraints agree (coaxial hinges stay coaxial, a motion "
                 "must not drive the mechanism where a removed equation cannot follow), or "
                 "replace the redundant joint by a joint primitive. Outputs up to the last good "
                 "step are written.");
    report(diags_.all().back());
    return false;
  }
  if (!m.output.reqsave) return true;
  if (!req_.isOpen()) {
    output::RequestFileHeader h;
    h.title = m.title;
    if (auto u = output::requestFileUnits(m.units.length, m.units.mass, m.units.time,
                                          m.units.force)) {
      h.unitsToken = u->token;
      h.lengthScale = u->lengthScale;
    } else {
      diags_.warning({m.file, 0, 0}, "UNITS",
                     "the request-file units tag of " + m.units.description +
                         " is not known; the .req header says " + h.unitsToken +
                         " although the values are in the model's units",
                     "Post-processors must be told the units of this run.");
      report(diags_.all().back());
    }
    std::vector<output::RequestEntry> entries;
    for (const auto& r : m.requests) {
      output::RequestEntry e;
      e.id = r.id;
      using RK = model::Request::Kind;
      e.type = r.kind == RK::Displacement ? 1 : r.kind == RK::Velocity ? 2
             : r.kind == RK::Acceleration ? 3 : r.kind == RK::Force ? 4 : 5;
      if (r.kind != RK::Expressions) {
        e.iMarker = m.markers[r.iMarker].id;
        e.jMarker = r.jMarker >= 0 ? m.markers[r.jMarker].id : 0;
      }
      e.comment = r.comment;
      entries.push_back(e);
    }
    std::string err;
    if (!req_.open(requestFilePath(), h, entries, &err)) {
      diags_.error({m.file, 0, 0}, "", "cannot write the request file: " + err, "");
      report(diags_.all().back());
      return false;
    }
  }
  std::vector<std::array<double, 6>> rows;
  rows.reserve(m.requests.size());
  constexpr double kDeg = 180.0 / 3.14159265358979323846;
  for (const auto& r : m.requests) {
    const auto c = requestColumns(*system_, r, t, y, yp);
    std::array<double, 6> row = {c[1], c[2], c[3], c[5], c[6], c[7]};
    // The request file holds displacement angles in degrees.
    if (r.kind == model::Request::Kind::Displacement)
      for (int k = 3; k < 6; ++k) row[k] *= kDeg;
    rows.push_back(row);
  }
  req_.writeStep(t, rows);
  ++summary_.outputSteps;
  return true;
}

bool Session::simulate(const language::Statement& c) {
  const model::Model& m = *model_;
  const bool kin = c.has("KINEMATICS");
  const bool dyn = c.has("DYNAMICS");
  const bool trans = c.has("TRANSIENT");
  if (c.has("STATICS") || c.has("INITIAL_CONDITIONS")) return simulateStaticsOrInitialConditions(c);
  if (!kin && !dyn && !trans) {
    error(c, "the kind of simulation is missing",
          "Write SIMULATE/TRANSIENT (or DYNAMICS, KINEMATICS), END=..., DTOUT=... or STEPS=....");
    return false;
  }
  auto end = number(c, "END");
  auto duration = number(c, "DURATION");
  if (!end && duration) end = t_ + *duration;
  if (!end || *end <= t_) {
    error(c, "END (or DURATION) must give a time after the current time " + fmt("%g", t_),
          "Add END=<time> greater than the current time.");
    return false;
  }
  auto steps = number(c, "STEPS");
  auto dtout = number(c, "DTOUT");
  long nOut = 0;
  if (steps && *steps >= 1) nOut = static_cast<long>(std::llround(*steps));
  else if (dtout && *dtout > 0) nOut = static_cast<long>(std::llround((*end - t_) / *dtout));
  else {
    error(c, "the output step is missing", "Add STEPS=<count> or DTOUT=<interval>.");
    return false;
  }
  nOut = std::max(1L, nOut);
  const double t0 = t_, outStep = (*end - t0) / static_cast<double>(nOut);

  // DIFF, LSE and TFSISO states must be integrated: a 0-DOF model with them runs dynamics.
  const bool userStates =
      system_->layout().userDifferential > 0 || DiscreteSampler(*system_).active();
  // SENSORs are monitored on the integrator's steps: a 0-DOF model with them runs dynamics.
  const bool kinematic = kin || (trans && dof_ == 0 && !userStates && m.sensors.empty());
  if (kin && !m.sensors.empty()) {
    error(c, "SENSOR events are detected in dynamic analyses only; this model has " +
                 std::to_string(m.sensors.size()) + " sensor(s)",
          "Use SIMULATE/TRANSIENT or SIMULATE/DYNAMICS.");
    return false;
  }
  if (kin && userStates) {
    error(c, "a kinematic analysis does not integrate DIFF, LSE or TFSISO states; this model "
             "has " + std::to_string(system_->layout().userDifferential),
          "Use SIMULATE/TRANSIENT or SIMULATE/DYNAMICS.");
    return false;
  }
  if (kin && dof_ != 0) {
    error(c, "a kinematic analysis needs a model with zero degrees of freedom; this one has " +
                 std::to_string(dof_),
          "Add motions or joints until the model is fully determined, or use "
          "SIMULATE/DYNAMICS.");
    return false;
  }
  if (dyn && dof_ == 0 && !userStates) {
    diags_.warning(c.where, c.subject(),
                   "the model has zero degrees of freedom; a kinematic analysis "
                   "(SIMULATE/KINEMATICS) would be more efficient. As requested, the simulation "
                   "goes on with a dynamic analysis");
    report(diags_.all().back());
  }
  // MODE of this analysis (its first output step included); HSIZE, ORDER, NJAC and NRHS count
  // from zero for each SIMULATE, as the integrator's statistics do.
  const auto enterAnalysisMode = [&]() {
    m.analysisStatus.mode =
        kinematic ? model::AnalysisMode::Kinematics : model::AnalysisMode::Dynamics;
    m.analysisStatus.clearIntegrator();
  };
  if (!initialized_) {
    runState_->reset();  // a new run: no turns counted, no DELAY history
    if (!initialConditions()) return false;
    runState_->accept(*system_, t_, y_, yp_);
    enterAnalysisMode();
    if (!writeOutputStep(t_, y_, yp_)) return false;
  }
  enterAnalysisMode();
  msg_.line("");
  msg_.line(" Begin Simulation");
  summary_.analysis = kinematic ? "kinematic" : "dynamic";
  const auto wallStart = std::chrono::steady_clock::now();
  auto lastProgress = wallStart;
  auto progress = [&](double t, long stepCount) {
    if (!options_.progress) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - lastProgress < std::chrono::milliseconds(500) && t < *end) return;
    lastProgress = now;
    const double elapsed = std::chrono::duration<double>(now - wallStart).count();
    const double frac = (t - t0) / (*end - t0);
    const double eta = frac > 0 ? elapsed * (1.0 - frac) / frac : 0.0;
    std::fprintf(stderr, "\r  t = %.5g / %.5g   steps %ld   ETA %.1f s   ", t, *end, stepCount, eta);
    std::fflush(stderr);
  };

  bool halted = false;  // by a SENSOR with HALT
  if (kinematic) {
    msg_.line("  ****** Performing Kinematic Analysis ******");
    for (long i = 1; i <= nOut; ++i) {
      const double t = (i == nOut) ? *end : t0 + static_cast<double>(i) * outStep;
      // First-order prediction of the positions, then Newton on the constraints.
      const double dt = t - t_;
      y_ += dt * yp_;
      auto r = mechanics::assemblePositions(*system_, t, y_, 1e-12, 25);
      if (!r.converged) {
        diags_.error({m.file, 0, 0}, "",
                     "kinematic analysis failed at time " + fmt("%.6E", t) + ": " +
                         system_->constraints().describe(r.worstEquation, m) +
                         " cannot be satisfied (residual " + fmt("%.3E", r.residual) + ")",
                     "The mechanism may lock up or pass a singular position; check the motion "
                     "functions.");
        report(diags_.all().back());
        return false;
      }
      mechanics::solveVelocities(*system_, t, y_);
      if (!mechanics::solveAccelerations(*system_, t, y_, yp_)) {
        diags_.error({m.file, 0, 0}, "", "singular constraint matrix at time " + fmt("%.6E", t),
                     "The mechanism passes a singular configuration.");
        report(diags_.all().back());
        return false;
      }
      t_ = t;
      ++summary_.steps;
      runState_->accept(*system_, t_, y_, yp_);  // each kinematic output is an accepted state
      if (!writeOutputStep(t_, y_, yp_)) return false;
      progress(t_, summary_.steps);
    }
  } else {
    // INTEGRATOR statement/command (analysis/integrator_factory.hpp, docs/integrators.md).
    if (const auto why = integratorUnavailable(m.integrator)) {
      error(c, "the dynamic analysis cannot start: " + *why, "Change the INTEGRATOR setting.");
      return false;
    }
    const IntegratorPlan plan = resolveIntegrator(m.integrator, outStep);
    msg_.line("  ****** Performing Dynamic Simulation using " + integratorBanner(plan) +
              " Integrator ******");
    msg_.line(integratorParameters(plan));
    msg_.line("");
    msg_.line("   Simulation      Step        Function    Cumulative   Integration");
    msg_.line("      Time         Size       Evaluations  Steps Taken    Order");
    MultibodyDae dae(*system_);
    const std::unique_ptr<solvers::Integrator> integrator =
        makeIntegrator(plan, *system_, dae, *end);
    // Accepted steps and restarts update the expression run state (run_state_integrator.hpp).
    RunStateIntegrator tracked(*integrator, *runState_, *system_);
    solvers::Integrator& bdf = tracked;
    // Advice from the method as it appears (ABAM's stiffness warning), each line once.
    std::size_t warningsShown = 0;
    auto showIntegratorWarnings = [&]() {
      const std::vector<std::string> lines = bdf.warnings();
      for (; warningsShown < lines.size(); ++warningsShown) {
        diags_.warning({m.file, 0, 0}, "", lines[warningsShown]);
        report(diags_.all().back());
      }
    };
    EprintLog eprint(msg_, dae);  // DEBUG/EPRINT: per step and iteration, to the .msg
    if (m.debug.eprint) eprint.attach(*integrator);  // observers live on the method itself
    bdf.start(t_, y_, yp_);
    // SENSOR events (analysis/sensor_monitor.hpp) are checked after every step; a sensor's
    // DT= moves the output grid.
    SensorMonitor sensors(*system_);
    sensors.start(t_, y_, yp_);
    OutputGrid grid{t0, outStep, *end, 0, nOut};
    const long logEvery = std::max(1L, nOut / 10);
    // GSE discrete states (analysis/discrete_sampler.hpp): the integrator stops at each sample.
    const DiscreteSampler sampler(*system_);
    for (long i = 1; i <= grid.count; ++i) {
      const double t = grid.time(i);
      const double sampleTime = sampler.active() ? sampler.nextTime() : t + 1.0;
      const bool sampleFirst = sampleTime <= t + 1e-12 * std::max(1.0, std::abs(t));
      const double target = sampleFirst ? std::min(t, sampleTime) : t;
      const bool ok = sensors.advanceTo(bdf, target);
      const auto& st = bdf.statistics();
      // HSIZE, ORDER, NJAC, NRHS read by REQUEST functions: the numbers the .msg prints.
      m.analysisStatus.stepSize = st.stepSize;
      m.analysisStatus.order = st.order;
      m.analysisStatus.jacobianEvaluations = st.jacobianEvaluations;
      m.analysisStatus.residualEvaluations = st.residualEvaluations;
      showIntegratorWarnings();
      if (!ok) {
        const auto& f = bdf.failure();
        std::string text =
            "the dynamic analysis failed at time " + fmt("%.6E", f.time) + " (step size " +
            fmt("%.3E", f.stepSize) + "): " + f.reason + ". The equation with the largest "
            "error is " + dae.equationName(f.worstEquation) + " (" +
            fmt("%.3E", f.worstResidual) + "); the variable changing most is " +
            dae.variableName(f.worstVariable) + " (" + fmt("%.3E", f.worstChange) + ")";
        // Name the applied force that dominates at the last accepted state: a force that
        // blows up is the usual cause (seed: "avoid IFs like the plague").
        std::string forces;
        double biggest = -1.0;
        for (const auto& e : system_->forceElements().elements()) {
          Eigen::Vector3d fk, tk;
          system_->forceElements().action(e, false, bdf.t(), bdf.y().data(), fk, tk);
          const double size = std::max(fk.norm(), tk.norm());
          if (!std::isfinite(size) || size > biggest) {
            biggest = size;
            forces = "; the largest applied force at t = " + fmt("%.6E", bdf.t()) + " is " +
                     forceElementName(m, e) + " (" + fmt("%.3E", size) + ")";
            if (!std::isfinite(size)) break;
          }
        }
        text += forces;
        // Name the request file only when one was written (OUTPUT/REQSAVE and at least one
        // output step).
        const std::string where =
            req_.isOpen() ? "Outputs up to the last successful output step are in " + prefix_ +
                                ".req. "
                          : "";
        diags_.error({m.file, 0, 0}, "", text,
                     where +
                         "Look for a discontinuous force or motion near that time, or tighten "
                         "HMAX.");
        report(diags_.all().back());
        t_ = bdf.t();
        summary_.time = t_;
        return false;
      }
      if (const SensorEvent* ev = sensors.event()) {
        for (const auto& line : describeSensorEvent(m, *ev)) msg_.line(line);
        if (ev->print || ev->endsSimulation())
          if (!writeOutputStep(ev->time, ev->y, ev->yp)) return false;
        if (ev->endsSimulation()) {  // the integrator was restarted at the event
          t_ = ev->time;
          y_ = ev->y;
          halted = ev->halt;
          break;
        }
        if (ev->outputInterval) grid.reschedule(i, ev->time, *ev->outputInterval);
        --i;  // output i is still ahead
        continue;
      }
      if (sampleFirst) {  // new discrete states, then a restart from the consistent state
        Eigen::VectorXd ys = bdf.y(), yps = bdf.yp();
        sampler.sample(bdf.t(), ys, yps);
        bdf.start(bdf.t(), ys, yps);
        if (target < t) {
          --i;  // output i is still ahead
          continue;
        }
      }
      t_ = t;
      y_ = bdf.y();
      Eigen::VectorXd yOut = y_, ypOut = bdf.yp();
      // Accelerations and reaction forces consistent with the converged positions and
      // velocities (not differenced from the integrator's history).
      mechanics::solveAccelerations(*system_, t_, yOut, ypOut);
      if (!writeOutputStep(t_, yOut, ypOut)) return false;
      summary_.steps = st.steps;
      summary_.jacobians = st.jacobianEvaluations;
      summary_.residuals = st.residualEvaluations;
      if (i % logEvery == 0 || i == grid.count) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "   %12.5E %12.5E %12ld %12ld %8d", t_, st.stepSize,
                      st.residualEvaluations, st.steps, st.order);
        msg_.line(buf);
      }
      progress(t_, st.steps);
    }
    yp_ = bdf.yp();
    {  // integrator statistics (docs/integrators.md compares the integrators by these)
      const auto& st = bdf.statistics();
      msg_.line("   Integrator statistics: " + std::to_string(st.steps) + " steps, " +
                std::to_string(st.rejectedSteps) + " rejected, " +
                std::to_string(st.newtonFailures) + " corrector failures, " +
                std::to_string(st.jacobianEvaluations) + " Jacobian evaluations, " +
                std::to_string(st.residualEvaluations) + " residual evaluations");
    }
  }
  if (options_.progress) std::fprintf(stderr, "\n");
  summary_.time = t_;
  msg_.line(" End Simulation");
  if (halted) {  // SENSOR/HALT ends the run as STOP does
    stopped_ = true;
    msg_.line("");
    msg_.line(" Finished -----");
    req_.close();
  }
  return true;
}

}  // namespace openmss::analysis
