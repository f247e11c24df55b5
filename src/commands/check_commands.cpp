// Session in check mode (`openmss check FILE.acf`, SessionOptions::checkOnly) when the data set
// has errors: there is no system to analyse, but the commands are still read against the data
// set as written, so that one pass reports every error of both files (docs/commands.md,
// "`openmss check FILE.acf`"). What can be checked without a built system is: ids of ACTIVATE,
// DEACTIVATE and redefining commands against the data set, the redefined arguments themselves
// (a trial build keeps only the errors at the command, model_edits.hpp), settings arguments,
// SIMULATE's arguments and END against the time the commands before it reach, LINEAR's
// arguments, and the save files of RELOAD. INFO and SHOW read a state and are passed over.

#include <filesystem>

#include "commands/linear_command.hpp"
#include "commands/save_reload_command.hpp"
#include "commands/session.hpp"
#include "commands/simulate_command.hpp"

namespace openmss::commands {

bool Session::checkWithoutSystem(const language::Statement& c) {
  if (c.name == "SIMULATE") {
    Diagnostics local;
    const auto request = readSimulate(c, checkTime_, local);
    reportAll(local);
    if (!request) return false;
    if (const auto* t = std::get_if<analysis::TransientRun>(&*request)) checkTime_ = t->end;
    if (const auto* st = std::get_if<analysis::StaticsRun>(&*request); st && st->end)
      checkTime_ = *st->end;
    return true;
  }
  if (c.name == "LINEAR") {
    Diagnostics local;
    const auto request = readLinear(c, *model_, options_.outputDirectory, prefix_, local);
    reportAll(local);
    return request.has_value();
  }
  if (c.name == "INFO" || c.name == "SHOW" || c.name == "TIME" || c.name == "MENU") return true;
  return dispatchChecked(c);
}

// SAVE and RELOAD in check mode write and restore nothing: SAVE notes its file, RELOAD checks
// that its file exists (or was named by a SAVE before it) and, when it exists, that it reads.
bool Session::checkSaveOrReload(const language::Statement& c, const std::string& path) {
  if (c.name == "SAVE") {
    checkSaved_.insert(path);
    return true;
  }
  if (checkSaved_.count(path)) return true;
  if (!std::filesystem::is_regular_file(path)) {
    error(c, "the save file " + path + " does not exist",
          "Check FILE= (no SAVE before this command names it).");
    return false;
  }
  std::string why;
  if (!analysis::decodeSaveFile(readTextFile(path), &why)) {
    if (why.rfind("line ", 0) == 0) why = why.substr(5);
    error(c, "the save file " + path + " is refused: " + path + ":" + why,
          "Reload a file SAVE wrote with this build and left unchanged.");
    return false;
  }
  return true;
}

}  // namespace openmss::commands
