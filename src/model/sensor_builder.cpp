#include "model/sensor_builder.hpp"

#include <set>

#include "model/model_builder.hpp"
#include "model/statement_arguments.hpp"
#include "model/user_routine_binding.hpp"

namespace openmss::model {

using language::Argument;
using language::Statement;

namespace {

bool isUserSubroutine(const Argument& a) { return a.expression.rfind("USER", 0) == 0; }

}  // namespace

void buildSensors(const language::Dataset& dataset, Model& model, Diagnostics& diags) {
  std::set<long> seen;
  for (const Statement& s : dataset.statements) {
    if (s.name != "SENSOR" || !s.id) continue;
    if (!seen.insert(*s.id).second) continue;  // duplicate ids: reported by the reader
    const StatementArguments args(s, diags);
    Sensor sensor;
    sensor.id = *s.id;
    sensor.where = s.where;
    bool ok = true;
    auto fail = [&](const SourceLocation& at, const std::string& what, const std::string& hint) {
      diags.error(at, s.subject(), what, hint);
      ok = false;
    };

    if (auto v = args.firstNumber("VALUE"))
      sensor.value = *v;
    else
      fail(s.where, "VALUE is missing",
           "Give VALUE=<number>: the sensor compares its FUNCTION with it.");

    int tests = 0;
    for (const auto& [name, test] : {std::pair{"EQ", Sensor::Test::Eq},
                                     std::pair{"GE", Sensor::Test::Ge},
                                     std::pair{"LE", Sensor::Test::Le}})
      if (s.has(name)) {
        sensor.test = test;
        ++tests;
      }
    if (tests > 1)
      fail(s.where, "EQ, GE and LE exclude each other", "Keep one of them (EQ is the default).");

    if (const Argument* e = s.find("ERROR")) {
      const auto v = args.firstNumber("ERROR");
      if (!v || *v <= 0) fail(e->where, "ERROR must be positive", "Give ERROR=<tolerance> > 0.");
      else sensor.error = *v;
    }
    if (const Argument* a = s.find("DT")) {
      const auto v = args.firstNumber("DT");
      if (!v || *v <= 0) fail(a->where, "DT (the new output interval) must be positive", "");
      else sensor.outputInterval = *v;
    }
    if (const Argument* a = s.find("STEPSIZE")) {
      const auto v = args.firstNumber("STEPSIZE");
      if (!v || *v <= 0) fail(a->where, "STEPSIZE (the next step size) must be positive", "");
      else sensor.stepSize = *v;
    }
    sensor.bisection = s.has("BISECTION");
    sensor.halt = s.has("HALT");
    sensor.print = s.has("PRINT");
    sensor.restart = s.has("RESTART");
    sensor.returnToCommands = s.has("RETURN");

    // Actions and escapes the solver cannot carry out: rejected, never ignored.
    if (const Argument* a = s.find("CODGEN"))
      fail(a->where,
           "CODGEN (a new pivot sequence for the Newton matrix at the event) is not supported",
           "Remove CODGEN; add RESTART if the event changes the equations abruptly.");
    if (const Argument* a = s.find("YYDUMP"))
      fail(a->where, "YYDUMP (a dump of the state vector at the event) is not supported",
           "Remove YYDUMP; add PRINT to write an output step at the event instead.");
    if (const Argument* a = s.find("ROUTINE"); a && !s.has("FUNCTION"))
      fail(a->where, "ROUTINE= without FUNCTION=USER(...)",
           "ROUTINE=lib::name names the SENSUB of FUNCTION=USER(...); add it or remove ROUTINE.");
    if (const Argument* a = s.find("EVALUATE_ROUTINE"); a && !s.has("EVALUATE"))
      fail(a->where, "EVALUATE_ROUTINE= without EVALUATE=USER(...)",
           "EVALUATE_ROUTINE=lib::name names the SEVSUB of EVALUATE=USER(...).");

    const bool acts = sensor.halt || sensor.print || sensor.restart || sensor.returnToCommands ||
                      sensor.outputInterval || sensor.stepSize || s.has("EVALUATE");
    if (ok && !acts)
      diags.warning(s.where, s.subject(),
                    "the sensor has no action: its events change nothing",
                    "Add HALT, RETURN, PRINT, RESTART, DT=, STEPSIZE= or EVALUATE=.");
    // A sensor with errors is still listed so that SENVAL(id) elsewhere is not reported
    // twice; the model is unusable anyway (the errors count).
    model.sensors.push_back(std::move(sensor));
  }
}

void bindSensorFunctions(const language::Dataset& dataset, Model& model, Diagnostics& diags) {
  size_t next = 0;
  std::set<long> seen;
  for (const Statement& s : dataset.statements) {
    if (s.name != "SENSOR" || !s.id || !seen.insert(*s.id).second) continue;
    if (next >= model.sensors.size()) break;
    Sensor& sensor = model.sensors[next++];
    // Sensor functions may read accelerations and reaction forces, as requests do: they are
    // evaluated on solved states, never inside the equations.
    user::ElementData data;
    data.sensorValue = sensor.value;
    data.sensorError = sensor.error;
    data.sensorLogic = sensor.test == Sensor::Test::Eq   ? 'E'
                       : sensor.test == Sensor::Test::Ge ? 'G'
                                                         : 'L';
    if (const Argument* f = s.find("FUNCTION"); f && isUserSubroutine(*f))
      bindUserRoutine(model, s, *f, user::RoutineKind::Sensub, data, {&sensor.function}, false,
                      diags);
    else if (f)
      bindExpression(model, f->expression, f->valueWhere, s.subject(), false, diags,
                     sensor.function);
    if (const Argument* e = s.find("EVALUATE")) {
      BoundExpression b;
      if (isUserSubroutine(*e)
              ? bindUserRoutine(model, s, *e, user::RoutineKind::Sevsub, data, {&b}, false, diags,
                                false, "EVALUATE_ROUTINE")
              : bindExpression(model, e->expression, e->valueWhere, s.subject(), false, diags, b))
        sensor.evaluate = std::move(b);
    }
  }
}

bool bindSensorMeasure(const Model& model, const expr::HostCall& call, Measure& m,
                       const BindFailure& fail) {
  if (call.name != "SENVAL") return false;
  m.kind = MeasureKind::SenVal;
  const long id = call.args.empty() ? 0 : call.args[0];
  for (size_t k = 0; k < model.sensors.size(); ++k)
    if (model.sensors[k].id == id) m.element = static_cast<int>(k);
  // A sensor without EVALUATE reads 0, as every sensor does before its first event.
  if (m.element < 0)
    fail("SENSOR/" + std::to_string(id) + " does not exist",
         "Use the id of a SENSOR statement of this data set.");
  return true;
}

}  // namespace openmss::model
