#include "analysis/sensor_monitor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/request_values.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/user_state_solve.hpp"

namespace openmss::analysis {
namespace {

using model::Sensor;

double evaluateOn(const mechanics::MultibodySystem& system, const model::BoundExpression& b,
                  double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
  std::vector<double> host(b.measures.size());
  for (size_t k = 0; k < host.size(); ++k) host[k] = measureValue(system, b.measures[k], t, y, yp);
  return b.expression.evaluate(host.empty() ? nullptr : host.data(), t, system.runState());
}

// How a sensor's test is reached inside a step (see SensorMonitor::distance).
enum Mode : int {
  kPlain = 0,          // GE, LE
  kCrossFromAbove = 1, // EQ: f - VALUE changes sign, positive before
  kCrossFromBelow = -1,
  kBandFromAbove = 2,  // EQ: f enters [VALUE - ERROR, VALUE + ERROR] without crossing VALUE
  kBandFromBelow = -2,
};

}  // namespace

SensorMonitor::SensorMonitor(const mechanics::MultibodySystem& system,
                             mechanics::ExpressionRunState& run)
    : system_(system), run_(run) {
  const model::Model& m = system.model();
  for (size_t k = 0; k < m.sensors.size(); ++k) {
    sensors_.push_back(static_cast<int>(k));
    for (const auto& ms : m.sensors[k].function.measures) needsDynamics_ |= ms.needsDynamics();
  }
}

double SensorMonitor::functionValue(int k, double t, const Eigen::VectorXd& y,
                                    const Eigen::VectorXd& yp) const {
  return evaluateOn(system_, system_.model().sensors[k].function, t, y, yp);
}

std::vector<double> SensorMonitor::functionValues(double t, const Eigen::VectorXd& y,
                                                  const Eigen::VectorXd& yp) const {
  std::vector<double> f(sensors_.size());
  for (int k : sensors_) f[k] = functionValue(k, t, y, yp);
  return f;
}

bool SensorMonitor::holds(int k, double f) const {
  const Sensor& s = system_.model().sensors[k];
  switch (s.test) {
    case Sensor::Test::Ge: return f >= s.value;
    case Sensor::Test::Le: return f <= s.value;
    case Sensor::Test::Eq: break;
  }
  return std::abs(f - s.value) <= s.error;
}

// A continuous function of the sensor's value, positive before the event and zero at it:
// the event time is its first root. For EQ the root is where f crosses VALUE when it does
// inside the step (then |f - VALUE| is far below ERROR at the event), otherwise where f enters
// the ERROR band.
double SensorMonitor::distance(int k, double f, int mode) const {
  const Sensor& s = system_.model().sensors[k];
  const double g = f - s.value;
  if (s.test == Sensor::Test::Ge) return -g;
  if (s.test == Sensor::Test::Le) return g;
  switch (mode) {
    case kCrossFromAbove: return g;
    case kCrossFromBelow: return -g;
    case kBandFromAbove: return g - s.error;
    default: return -g - s.error;
  }
}

void SensorMonitor::stateAt(const solvers::Integrator& integrator, double s, Eigen::VectorXd& y,
                            Eigen::VectorXd& yp) const {
  integrator.interpolate(s, y, yp);
  // The interpolant's y' is the method's; functions of accelerations and reaction forces get
  // them solved from the interpolated positions and velocities, as output steps do.
  if (needsDynamics_) mechanics::solveAccelerations(system_, s, y, yp);
}

void SensorMonitor::consistentState(double t, Eigen::VectorXd& y, Eigen::VectorXd& yp) const {
  // The interpolant satisfies the constraints to the integration error only; the event state
  // is output and may restart the integrator, so it is made consistent as at the start of a
  // run (positions, velocities, user algebraic states, accelerations and forces). Should a
  // projection fail, the interpolated state is kept.
  Eigen::VectorXd yc = y, ypc = yp;
  if (!mechanics::assemblePositions(system_, t, yc, 1e-12, 25).converged) return;
  mechanics::solveVelocities(system_, t, yc);
  if (!mechanics::solveUserAlgebraic(system_, t, yc).converged) return;
  if (!mechanics::solveAccelerations(system_, t, yc, ypc)) return;
  mechanics::userStateRates(system_, t, yc, ypc);
  y = std::move(yc);
  yp = std::move(ypc);
}

void SensorMonitor::start(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
  checkedTime_ = t;
  values_ = functionValues(t, y, yp);
  holds_.assign(sensors_.size(), false);
  for (int k : sensors_) holds_[k] = holds(k, values_[k]);
  event_.reset();
}

bool SensorMonitor::advanceTo(solvers::Integrator& integrator, double tout) {
  event_.reset();
  const double eps = 1e-12 * std::max(1.0, std::abs(tout));
  for (;;) {
    if (active() && checkedTime_ < integrator.t() && checkLastStep(integrator)) return true;
    if (integrator.t() >= tout - eps) return true;
    if (!integrator.step(tout)) return false;
  }
}

bool SensorMonitor::checkLastStep(solvers::Integrator& integrator) {
  const model::Model& m = system_.model();
  const double a = checkedTime_, b = integrator.t();
  Eigen::VectorXd y = integrator.y(), yp = integrator.yp();
  if (needsDynamics_) mechanics::solveAccelerations(system_, b, y, yp);
  const std::vector<double> fb = functionValues(b, y, yp);

  // Sensors whose test starts to hold in (a, b], with how it is reached.
  std::vector<std::pair<int, int>> triggered;
  for (int k : sensors_) {
    if (holds_[k]) continue;
    const Sensor& s = m.sensors[k];
    if (s.test != Sensor::Test::Eq) {
      if (holds(k, fb[k])) triggered.push_back({k, kPlain});
      continue;
    }
    const double ga = values_[k] - s.value, gb = fb[k] - s.value;
    if ((ga > 0) != (gb > 0) || gb == 0.0)
      triggered.push_back({k, ga > 0 ? kCrossFromAbove : kCrossFromBelow});
    else if (std::abs(gb) <= s.error)
      triggered.push_back({k, ga > 0 ? kBandFromAbove : kBandFromBelow});
  }
  if (triggered.empty()) {
    checkedTime_ = b;
    values_ = fb;
    for (int k : sensors_) holds_[k] = holds(k, fb[k]);
    return false;
  }

  // Each triggered sensor's event time: the first root of its distance on the interpolant,
  // bracketed by a (distance > 0) and b (<= 0). Illinois-modified regula falsi (or bisection):
  // it stops when the function is within ERROR/1000 of the threshold on the after side, or
  // when the bracket is down to rounding.
  Eigen::VectorXd ys, yps;
  double eventTime = b;
  std::vector<std::pair<int, double>> located;
  for (const auto& [k, mode] : triggered) {
    const Sensor& s = m.sensors[k];
    double lo = a, hi = b;
    double dLo = distance(k, values_[k], mode), dHi = distance(k, fb[k], mode);
    const double tolF = 1e-3 * s.error;
    int retained = 0;
    for (int it = 0; it < 200; ++it) {
      if (-dHi <= tolF || hi - lo <= 4e-16 * std::max(1.0, std::abs(hi))) break;
      double t = s.bisection || dLo <= 0 ? 0.5 * (lo + hi) : (lo * dHi - hi * dLo) / (dHi - dLo);
      if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
      stateAt(integrator, t, ys, yps);
      const double d = distance(k, functionValue(k, t, ys, yps), mode);
      if (d <= 0) {
        hi = t;
        dHi = d;
        if (retained == -1) dLo *= 0.5;  // lo kept twice: Illinois halving
        retained = -1;
      } else {
        lo = t;
        dLo = d;
        if (retained == 1) dHi *= 0.5;
        retained = 1;
      }
    }
    located.push_back({k, hi});
    eventTime = std::min(eventTime, hi);
  }

  // The event state, made consistent; every triggered sensor whose test is reached by then
  // fires with the earliest.
  SensorEvent ev;
  ev.time = eventTime;
  stateAt(integrator, eventTime, ev.y, ev.yp);
  consistentState(eventTime, ev.y, ev.yp);
  const std::vector<double> fe = functionValues(eventTime, ev.y, ev.yp);
  for (const auto& [k, mode] : triggered) {
    const double tk = std::find_if(located.begin(), located.end(),
                                   [&](const auto& p) { return p.first == k; })->second;
    if (tk > eventTime && distance(k, fe[k], mode) > 1e-3 * m.sensors[k].error) continue;
    ev.sensors.push_back(k);
  }
  std::sort(ev.sensors.begin(), ev.sensors.end());
  bool restart = false;
  for (int k : ev.sensors) {
    const Sensor& s = m.sensors[k];
    ev.functionValues.push_back(fe[k]);
    ev.halt |= s.halt;
    ev.returnToCommands |= s.returnToCommands;
    ev.print |= s.print;
    if (s.outputInterval)
      ev.outputInterval = std::min(ev.outputInterval.value_or(*s.outputInterval),
                                   *s.outputInterval);
    if (s.stepSize) ev.stepSize = std::min(ev.stepSize.value_or(*s.stepSize), *s.stepSize);
    // A new SENVAL changes the equations that read it abruptly: the integrator restarts.
    restart |= s.restart || s.stepSize || s.outputInterval || s.evaluate || s.halt ||
               s.returnToCommands;
  }
  for (int k : ev.sensors)
    if (const Sensor& s = m.sensors[k]; s.evaluate)
      run_.setSensorValue(k, evaluateOn(system_, *s.evaluate, eventTime, ev.y, ev.yp));

  if (restart) {
    // Restart at order 1 from the consistent event state (solvers::Integrator::start).
    integrator.start(eventTime, ev.y, ev.yp);
    if (ev.stepSize) ev.stepSizeHonoured = integrator.setNextStepSize(*ev.stepSize);
    ev.restarted = true;
  }
  checkedTime_ = eventTime;
  values_ = functionValues(eventTime, ev.y, ev.yp);  // after EVALUATE: SENVAL may be read
  for (int k : sensors_) holds_[k] = holds(k, values_[k]);
  // A sensor that fired holds now, even if the consistent state moved it by a rounding.
  for (int k : ev.sensors) holds_[k] = true;
  event_ = std::move(ev);
  return true;
}

std::vector<std::string> describeSensorEvent(const model::Model& m, const SensorEvent& ev,
                                             const mechanics::ExpressionRunState& run) {
  auto fmt = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6E", v);
    return std::string(buf);
  };
  std::vector<std::string> lines;
  for (size_t q = 0; q < ev.sensors.size(); ++q) {
    const Sensor& s = m.sensors[ev.sensors[q]];
    const char* test = s.test == Sensor::Test::Ge ? "GE" : s.test == Sensor::Test::Le ? "LE" : "EQ";
    std::string actions;
    auto add = [&](bool on, const std::string& name) {
      if (on) actions += (actions.empty() ? "" : ", ") + name;
    };
    add(s.halt, "HALT");
    add(s.returnToCommands, "RETURN");
    add(s.print, "PRINT");
    add(s.restart, "RESTART");
    add(s.outputInterval.has_value(), "DT=" + (s.outputInterval ? fmt(*s.outputInterval) : ""));
    add(s.stepSize.has_value(), "STEPSIZE=" + (s.stepSize ? fmt(*s.stepSize) : ""));
    add(s.evaluate.has_value(), "EVALUATE (SENVAL = " + fmt(run.sensorValue(ev.sensors[q])) + ")");
    lines.push_back("   SENSOR/" + std::to_string(s.id) + " event at time " + fmt(ev.time) +
                    ": FUNCTION = " + fmt(ev.functionValues[q]) + " (" + test + " VALUE = " +
                    fmt(s.value) + ", ERROR = " + fmt(s.error) + "); actions: " +
                    (actions.empty() ? "none" : actions));
  }
  const std::string who = "SENSOR/" + std::to_string(m.sensors[ev.sensors.front()].id);
  if (ev.halt)
    lines.push_back("   The simulation is halted by " + who + " at time " + fmt(ev.time) +
                    " (output written at the event)");
  else if (ev.returnToCommands)
    lines.push_back("   " + who + " returns to command level at time " + fmt(ev.time) +
                    " (output written at the event)");
  if (ev.stepSize && !ev.stepSizeHonoured)
    lines.push_back("   Warning: this integrator takes no step size from outside; STEPSIZE had "
                    "no effect beyond the restart");
  return lines;
}

double OutputGrid::time(long i) const {
  if (i >= count) return end;
  return base + static_cast<double>(i - first) * step;
}

void OutputGrid::reschedule(long next, double event, double dt) {
  base = event;
  step = dt;
  first = next - 1;
  // The last regular output lands on END when within 1e-9 of an interval.
  const double n = std::ceil((end - event) / dt - 1e-9);
  count = first + std::max(1L, static_cast<long>(n));
}

}  // namespace openmss::analysis
