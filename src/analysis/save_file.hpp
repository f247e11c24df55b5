#pragma once
// The save file of SAVE/STATES and SAVE/SYSTEM, read back by RELOAD (docs/save-format.md): the
// run state (analysis/run_state.hpp) as text, every number an exact hexadecimal float, so that
// an analysis continued after RELOAD is bit-identical to one that never stopped. SYSTEM files
// also hold the data set's text and the model-changing commands given since it was loaded.
// The file carries a magic line, a format version, the build that wrote it, a fingerprint of
// the model's structure and a checksum; decodeSaveFile refuses anything else with the line.

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/run_state.hpp"
#include "mechanics/expression_run_state.hpp"
#include "mechanics/multibody_system.hpp"

namespace openmss::analysis {

inline constexpr int kSaveFormatVersion = 3;  // 2: curve-parameters; 3: user-data

// The build identity written into and required of save files: numbers of another build may
// differ in the last bit, so continuation could not be promised bit-identical.
std::string saveBuildId();

struct SaveFile {
  bool system = false;      // SAVE/SYSTEM (model included) or SAVE/STATES
  std::string build;        // saveBuildId() of the writer
  std::string fingerprint;  // modelFingerprint() of the model the states belong to
  // The run state.
  double t = 0.0;
  Eigen::VectorXd y, yp;
  bool initialized = false, halted = false;
  RunSummary summary;
  mechanics::ExpressionRunState::Snapshot expressions;
  // SYSTEM only: the data set (its path when saved, and its text) and the commands that
  // changed the model or its settings since it was loaded, as written, in order.
  std::string datasetPath, datasetText;
  std::vector<std::string> commands;
  // What the user library's SAVSUB wrote (user/save_routines.hpp), for RELSUB; "" when none.
  std::string userData;
};

// 16 hexadecimal digits identifying the structure of the model the run state belongs to: the
// state layout's sizes and the kinds and ids of every element whose values the state holds.
std::string modelFingerprint(const mechanics::MultibodySystem& system,
                             const mechanics::ExpressionRunState& run);

// The run state of `state` (model and commands not filled in).
SaveFile captureRunState(const RunState& state, const mechanics::MultibodySystem& system);
// Puts `file`'s run state into `state`. Returns false, with *error, and changes nothing when
// the file's model fingerprint or sizes are not this model's.
bool restoreRunState(const SaveFile& file, const mechanics::MultibodySystem& system,
                     RunState& state, std::string* error);

std::string encodeSaveFile(const SaveFile& file);
// Parses and checks a save file's text: the magic line, the format version, the checksum, the
// build; *error is "line N: what is wrong" (nullopt then).
std::optional<SaveFile> decodeSaveFile(std::string_view text, std::string* error);

}  // namespace openmss::analysis
