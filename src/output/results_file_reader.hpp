#pragma once
// Reads a results file (.res) in ADAMS's XML layout (XRF, namespace
// http://www.mscsoftware.com/:xrf10): the files OpenMSS writes (output/results_file.hpp) and
// those ADAMS/Solver writes. The StepMap gives entities and components with their ids; every
// <Step> of every <Data> block is read into one value per id (docs/output-files.md).

#include <optional>
#include <string>
#include <vector>

namespace openmss::output {

struct ResultsFileComponent {
  std::string name;
  std::string units;  // unitsValue ("" when absent)
  long id = 0;        // 1-based position of the value in each step
};

struct ResultsFileEntity {
  std::string name;     // "PART_2_XFORM", "JOINT_1", "time", ...
  std::string entity;   // "PART_2" ("" when absent)
  std::string entType;  // "Part", "Joint", "Request", ... ("" when absent)
  long objectId = 0;
  std::vector<ResultsFileComponent> components;
};

struct ResultsFileStep {
  std::string type;  // "initialConditions", "dynamic", "input", ...
  // values[id - 1]; values[0] is the time. An ADAMS "input" step (modelInput_001) has a
  // shape of its own, not the StepMap's: its values are kept but ids do not apply.
  std::vector<double> values;
  double time() const { return values.empty() ? 0.0 : values[0]; }
};

struct ResultsFileBlock {
  std::string name;  // "dynamic_001"
  long id = 0;
  std::vector<ResultsFileStep> steps;
};

struct ResultsFileData {
  std::string title;                                          // ModelInfo title
  std::string analysisName;                                   // Analysis name
  std::string angleUnits, lengthUnits, massUnits, timeUnits;  // <Units>
  std::string runStatus;  // TerminationStatus runStatus ("" when absent)
  std::vector<ResultsFileEntity> entities;
  std::vector<ResultsFileBlock> blocks;
  long componentCount = 0;  // largest component id: the number of values of every step

  const ResultsFileEntity* findEntity(const std::string& name) const;
  // Id of entity.component, nullopt when either is absent.
  std::optional<long> componentId(const std::string& entity, const std::string& component) const;
  // Values of one component id over every step (with one value per component) of every block
  // whose name starts with `blockPrefix` ("" for all, "dynamic" for the dynamic blocks), in
  // file order.
  std::vector<double> series(long id, const std::string& blockPrefix = "") const;
};

// False with *error (file:line and what is wrong) when the file cannot be read, is not XML, is
// not an XRF results file, or a step other than an "input" step does not hold one value per
// component.
bool readResultsFile(const std::string& path, ResultsFileData& out, std::string* error);

}  // namespace openmss::output
