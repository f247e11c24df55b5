#pragma once
// What a .res (XRF) file holds and where: the StepMap's entities and components with their ids,
// and how each component's value is read from an output snapshot. Ids are allocated by
// quantity block as ADAMS does (time; all part positions; all part velocities; all part
// accelerations; joint, joint-primitive and motion reactions; applied forces; VARIABLEs and
// DIFFs; requests). Names, units and order: docs/output-files.md, "Results file (.res)".

#include <functional>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "model/results_settings.hpp"
#include "output/output_frame.hpp"

namespace openmss::output {

struct ResultsComponent {
  std::string name;   // "X", "VX", "FX", "Q", "mag", "U1", a CNAMES name, ...
  std::string units;  // unitsValue ("meter/sec"); empty: the attribute is left out
  int entity = 0;     // index into ResultsLayout::entities
  int group = 0;      // components of one group share a line of a <Step>
  std::function<double(const OutputFrame&)> value;
};

struct ResultsEntity {
  std::string name;     // "PART_2_XFORM", "JOINT_1", "REQUEST_3", "time"
  std::string entity;   // "PART_2" (empty for time: no attribute)
  std::string entType;  // "Part", "Joint", "Request", ... (empty for time)
  long objectId = 0;
  std::vector<int> components;  // indices into ResultsLayout::components, ascending
};

struct ResultsUnits {
  std::string angle = "rad", length = "meter", mass = "kg", time = "sec", force = "newton";
};

struct ResultsLayout {
  ResultsUnits units;
  std::vector<ResultsEntity> entities;
  // components[k] has id k + 1; components[0] is TIME.
  std::vector<ResultsComponent> components;
  // Element counts the snapshot must have for the layout to apply (checked at every step).
  std::size_t parts = 0, joints = 0, jprims = 0, motions = 0, sforces = 0, springDampers = 0,
              linearFields = 0, vectorForces = 0, requests = 0, variables = 0, diffs = 0,
              couplers = 0, gears = 0, gcons = 0, frictions = 0, nforces = 0, contacts = 0,
              linearStates = 0, gses = 0;
  // Empty when `frame` has the counts above, else what differs.
  std::string mismatch(const OutputFrame& frame) const;
};

// The .res units words of the model's UNITS ("meter", "kg", "sec", "newton", ...).
ResultsUnits resultsUnits(const model::Units& units);
ResultsLayout resultsLayout(const model::Model& model, const model::ResultsSettings& settings);
// The default .res names of a request's eight columns (before CNAMES).
std::vector<std::string> defaultRequestComponentNames(model::Request::Kind kind);

}  // namespace openmss::output
