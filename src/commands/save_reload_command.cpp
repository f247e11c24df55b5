// SAVE/{STATES | SYSTEM}, FILE=  and  RELOAD/{STATES | SYSTEM}, FILE= [, OUTPUT_PREFIX=]
// (docs/save-format.md). SAVE writes the run state (analysis/save_file.hpp); SYSTEM adds the
// data set's text and the model-changing commands given since it was loaded. RELOAD reads the
// whole file and checks it (format, checksum, build, model fingerprint) before anything
// changes, so a refused RELOAD leaves the session exactly as it was. Every SIMULATE starts its
// integrator afresh from the run state (analysis/dynamic_run.cpp), so between two commands
// there is no integrator history to keep: the run state alone continues bit-identically.

#include "commands/save_reload_command.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "analysis/model_summary.hpp"
#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "language/reader.hpp"
#include "model/model_builder.hpp"
#include "output/request_header.hpp"
#include "user/save_routines.hpp"

namespace openmss::commands {
namespace {

namespace fs = std::filesystem;

std::string argumentWord(const language::Statement& c, const char* name) {
  const language::Argument* a = c.find(name);
  // `written` keeps a file name's case; `text` is upper-cased.
  return a && !a->values.empty() ? a->values[0].written.str() : std::string();
}

// Commands that change neither the model nor its settings: not replayed by RELOAD/SYSTEM.
bool changesModel(const std::string& name) {
  // CONTROL: its CONSUB's MODIFY commands are recorded one by one.
  for (const char* n : {"SIMULATE", "LINEAR", "SAVE", "RELOAD", "STOP", "HELP", "INFO", "SHOW",
                        "TIME", "MENU", "FILE", "CONTROL"})
    if (name == n) return false;
  return true;
}

bool sameRequestDirectory(const model::Model& a, const model::Model& b) {
  const auto ea = output::requestEntries(a), eb = output::requestEntries(b);
  if (ea.size() != eb.size()) return false;
  for (std::size_t k = 0; k < ea.size(); ++k)
    if (ea[k].id != eb[k].id || ea[k].type != eb[k].type || ea[k].iMarker != eb[k].iMarker ||
        ea[k].jMarker != eb[k].jMarker || ea[k].comment != eb[k].comment)
      return false;
  return true;
}

// Relative FILE= names are taken in the output directory, next to <prefix>.req.
std::string saveFilePath(const std::string& written, const std::string& outputDirectory) {
  const fs::path p = written;
  return p.is_absolute() ? p.string() : (fs::path(outputDirectory) / p).string();
}

}  // namespace

std::string Session::modelDirectory() const {
  return model_ ? fs::path(model_->file).parent_path().string() : std::string(".");
}

std::string readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void Session::recordCommand(const language::Statement& c, const std::vector<std::string>& echo) {
  if (!changesModel(c.name) || echo.empty()) return;
  std::string text;
  for (const auto& line : echo) text += line + "\n";
  commandHistory_.push_back(std::move(text));
}

bool Session::saveOrReload(const language::Statement& c) {
  const bool states = c.has("STATES"), system = c.has("SYSTEM");
  if (states == system) {
    error(c, "give exactly one of STATES and SYSTEM",
          "SAVE/STATES, FILE=name saves the states only.");
    return false;
  }
  if (argumentWord(c, "FILE").empty()) {
    error(c, "FILE= is missing", "Name the save file, e.g. FILE=run1.sav (no default extension).");
    return false;
  }
  if (const language::Argument* title = c.find("TITLE")) {
    Diagnostic d;
    d.where = title->where;
    d.subject = c.subject();
    d.message = "TITLE is not supported yet";
    d.hint = "Remove TITLE=; the request file keeps the data set's title.";
    diagnostic(d);
    return false;
  }
  if (options_.checkOnly)  // no file written, no state restored
    return checkSaveOrReload(c, saveFilePath(argumentWord(c, "FILE"), options_.outputDirectory));
  return c.name == "SAVE" ? save(c) : reload(c);
}

bool Session::save(const language::Statement& c) {
  const std::string path = saveFilePath(argumentWord(c, "FILE"), options_.outputDirectory);
  analysis::SaveFile f = analysis::captureRunState(*state_, *system_);
  f.system = c.has("SYSTEM");
  if (f.system) {
    f.datasetPath = model_->file;
    f.datasetText = datasetText_;
    f.commands = commandHistory_;
  }
  // The user library's own data (user/save_routines.hpp).
  const user::UserSaveData own = user::callSavsub(modelDirectory());
  if (!own.error.empty()) {
    error(c, "SAVSUB failed, nothing was saved: " + own.error,
          "Fix the user library's Savsub (docs/user-subroutines.md, \"SAVSUB and RELSUB\").");
    return false;
  }
  f.userData = own.bytes;
  const std::string bytes = analysis::encodeSaveFile(f);
  // Written beside the target and renamed: a failed SAVE never leaves half a file under it.
  const std::string partial = path + ".partial";
  {
    std::ofstream out(partial, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      error(c, "cannot write the save file " + partial, "Check that the folder is writable.");
      return false;
    }
  }
  std::error_code ec;
  fs::rename(partial, path, ec);
  if (ec) {
    error(c, "cannot write the save file " + path + ": " + ec.message(),
          "Check that the folder is writable.");
    return false;
  }
  msg_.line(" " + std::string(f.system ? "System" : "States") + " at time " +
            analysis::formatNumber("%.6E", f.t) + " saved to " + path);
  return true;
}

bool Session::reload(const language::Statement& c) {
  const std::string path = saveFilePath(argumentWord(c, "FILE"), options_.outputDirectory);
  if (!fs::is_regular_file(path)) {
    error(c, "the save file " + path + " does not exist", "Check FILE= (SAVE wrote it).");
    return false;
  }
  std::string why;
  const auto file = analysis::decodeSaveFile(readTextFile(path), &why);
  if (!file) {
    // "line N: what" from the reader becomes "file:N: what".
    if (why.rfind("line ", 0) == 0) why = why.substr(5);
    error(c, "the save file " + path + " is refused, nothing was reloaded: " + path + ":" + why,
          "Reload a file SAVE wrote with this build and left unchanged.");
    return false;
  }
  if (c.has("SYSTEM")) {
    if (!file->system) {
      error(c, "the save file " + path + " holds states only (SAVE/STATES)",
            "Use RELOAD/STATES, or write the file with SAVE/SYSTEM.");
      return false;
    }
    if (!reloadSystem(c, *file)) return false;
  } else if (!analysis::restoreRunState(*file, *system_, *state_, &why)) {
    error(c, "the save file " + path + " is refused, nothing was reloaded: " + why,
          "RELOAD/STATES needs the model the states were saved from; RELOAD/SYSTEM brings it.");
    return false;
  }
  if (c.has("OUTPUT_PREFIX") && !switchOutputPrefix(c)) return false;
  msg_.line(" " + std::string(c.has("SYSTEM") ? "System" : "States") + " reloaded from " + path +
            ": time " + analysis::formatNumber("%.6E", state_->t));
  // The user library's own data, after the states (user/save_routines.hpp).
  const user::UserSaveData own = user::callRelsub(file->userData, modelDirectory());
  if (!own.error.empty()) {
    error(c, "RELSUB failed: " + own.error + "; the states are reloaded",
          "Fix the user library's Relsub (docs/user-subroutines.md, \"SAVSUB and RELSUB\").");
    return false;
  }
  return true;
}

bool Session::reloadSystem(const language::Statement& c, const analysis::SaveFile& file) {
  language::Dataset dataset;
  Diagnostics d;
  language::readDatasetText(file.datasetText, file.datasetPath, dataset, d);
  auto model = std::make_unique<model::Model>();
  model::buildModel(dataset, *model, d);
  if (d.hasErrors()) {
    error(c, "the data set in the save file does not build: " + d.all().front().message,
          "The data set refers to files that have moved, or the file is not from SAVE/SYSTEM.");
    return false;
  }
  if (req_.isOpen() && !c.has("OUTPUT_PREFIX") && !sameRequestDirectory(*model, *model_)) {
    error(c, "the saved model's requests differ from those of the open " + prefix_ + ".req",
          "Give OUTPUT_PREFIX= to start new output files.");
    return false;
  }
  auto system = std::make_unique<mechanics::MultibodySystem>(*model);
  auto state = std::make_unique<analysis::RunState>(*system);
  const analysis::DegreeOfFreedomCount dof = analysis::countDegreesOfFreedom(*system, state->y);
  state->degreesOfFreedom = dof.degreesOfFreedom;
  state->grueblerCount = dof.gruebler;
  state->outputPrefix = prefix_;
  // Install the new model, replay its commands and restore its states; any failure puts the
  // old session back untouched.
  std::swap(model_, model);
  std::swap(system_, system);
  std::swap(state_, state);
  // The element commands among those replayed edit this data set (model_edits.hpp); the
  // edits are applied before the states are restored, so that the states meet the model
  // they were saved from.
  this->dataset();  // the loaded tree, if released, is put back as it was on a refusal
  language::Dataset oldDataset = std::exchange(dataset_, dataset);
  const ModelEdits oldPending = std::exchange(pendingEdits_, ModelEdits{});
  const ModelEdits oldApplied = std::exchange(appliedEdits_, ModelEdits{});
  const bool oldEditsPending = std::exchange(editsPending_, false);
  bool ok = true;
  std::string why;
  for (const std::string& text : file.commands) {
    language::CommandReader reader("<save file command>", 1);
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) reader.feedLine(line);
    reader.finish();
    auto commands = reader.takeCommands();
    // The echo may hold lines of commands handled outside the session (FILE, HELP) before
    // the command itself: the last statement is the one that was recorded.
    if (commands.empty() || !dispatch(commands.back())) {
      ok = false;
      why = "the saved command \"" + text.substr(0, text.find('\n')) + "\" fails on it";
      break;
    }
  }
  if (ok && editsPending_ && !applyEdits(c)) {
    ok = false;
    why = "the model changes of the saved commands do not build";
  }
  if (ok && !analysis::restoreRunState(file, *system_, *state_, &why)) ok = false;
  if (!ok) {
    std::swap(model_, model);
    std::swap(system_, system);
    std::swap(state_, state);
    dataset_ = std::move(oldDataset);
    pendingEdits_ = oldPending;
    appliedEdits_ = oldApplied;
    editsPending_ = oldEditsPending;
    error(c, "RELOAD/SYSTEM refused, nothing was reloaded: " + why, "");
    return false;
  }
  datasetText_ = file.datasetText;
  commandHistory_ = file.commands;
  return true;
}

bool Session::switchOutputPrefix(const language::Statement& c) {
  const std::string prefix = argumentWord(c, "OUTPUT_PREFIX");
  req_.close();  // the next output step opens <prefix>.req with its header
  closeResults();  // and <prefix>.res
  msg_.line(" Output continues in " + prefix + ".msg and " + prefix + ".req");
  msg_.close();
  prefix_ = prefix;
  state_->outputPrefix = prefix_;
  if (!msg_.open(messageFilePath())) {
    error(c, "cannot create the message file " + messageFilePath(),
          "Check that the output directory is writable.");
    return false;
  }
  msg_.line("OpenMSS " + std::string(OPENMSS_VERSION) + " -- continued after RELOAD");
  return true;
}

}  // namespace openmss::commands
