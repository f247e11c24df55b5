#include "commands/linear_command.hpp"

#include <filesystem>

namespace openmss::commands {
namespace {

// The plant-input or -output list `name`=id of the command, as VARIABLE indices. Returns false
// (after an error) when the id names no such statement.
bool plantVariables(const language::Statement& c, const char* name,
                    const std::vector<model::PlantVariables>& lists, std::vector<int>& out,
                    Diagnostics& diags) {
  const language::Argument* a = c.find(name);
  if (!a || a->values.empty()) return true;
  const long id = static_cast<long>(a->values[0].number);
  for (const auto& list : lists)
    if (list.id == id) {
      out = list.variables;
      return true;
    }
  diags.error(a->where, c.subject(),
              std::string(name) + "=" + std::to_string(id) + " names no " + name +
                  " statement in the data set",
              std::string("Add ") + name + "/" + std::to_string(id) +
                  ", VARIABLES=... to the data set, or give the id of an existing one.");
  return false;
}

}  // namespace

std::optional<analysis::LinearRun> readLinear(const language::Statement& c, const model::Model& m,
                                              const std::string& outputDirectory,
                                              const std::string& outputPrefix, Diagnostics& diags) {
  const bool eigen = c.has("EIGENSOL"), statemat = c.has("STATEMAT");
  if (eigen == statemat) {
    diags.error(c.where, c.subject(), "LINEAR needs exactly one of EIGENSOL and STATEMAT",
                "Write LINEAR/EIGENSOL for eigenvalues and mode shapes, or LINEAR/STATEMAT for "
                "the state matrices.");
    return std::nullopt;
  }
  bool ok = true;
  for (const char* unsupported :
       {"MKB", "EXPORT", "PSTATE", "COORDS", "ENERGY", "DISSIPAT", "KINETIC"})
    if (const auto* a = c.find(unsupported)) {
      diags.error(a->where, c.subject(), std::string(unsupported) + " is not supported yet",
                  "Supported: LINEAR/EIGENSOL [, NODAMPIN] [, NOVECTOR] and LINEAR/STATEMAT "
                  "[, PINPUT=id] [, POUTPUT=id] [, FORMAT=MATLAB|MATRIXX] [, FILE=name].");
      ok = false;
    }
  std::string format = "MATLAB";
  if (const auto* a = c.find("FORMAT"); a && !a->values.empty()) format = a->values[0].text;
  if (format != "MATLAB" && format != "MATRIXX") {
    diags.error(c.find("FORMAT")->where, c.subject(), "FORMAT=" + format + " is not known",
                "Write FORMAT=MATLAB (ASCII flat files) or FORMAT=MATRIXX (one MATSAVE file).");
    ok = false;
  }
  if (eigen)
    for (const char* only : {"PINPUT", "POUTPUT", "FORMAT", "FILE"})
      if (const auto* a = c.find(only)) {
        diags.error(a->where, c.subject(), std::string(only) + " belongs to LINEAR/STATEMAT",
                    "Remove it from LINEAR/EIGENSOL, or write LINEAR/STATEMAT.");
        ok = false;
      }
  analysis::LinearRun r;
  r.eigen = eigen;
  r.withoutShapes = c.has("NOVECTOR");
  r.format = format == "MATLAB" ? analysis::StateMatrixFormat::Matlab
                                : analysis::StateMatrixFormat::Matrixx;
  r.request.basis =
      eigen ? analysis::LinearBasis::Orthonormal : analysis::LinearBasis::PartCoordinates;
  r.request.withoutDamping = c.has("NODAMPIN");
  ok = plantVariables(c, "PINPUT", m.pinputs, r.request.inputs, diags) && ok;
  ok = plantVariables(c, "POUTPUT", m.poutputs, r.request.outputs, diags) && ok;
  if (!ok) return std::nullopt;
  // STATEMAT's files: FILE= (as written, keeping its case) or the output prefix, in the
  // output directory unless absolute.
  std::string base = outputPrefix;
  if (const auto* a = c.find("FILE"); a && !a->values.empty())
    base = a->values[0].written.empty() ? a->values[0].text : a->values[0].written;
  std::filesystem::path path(base);
  if (path.is_relative()) path = std::filesystem::path(outputDirectory) / path;
  r.fileBase = path.string();
  r.origin = {c.where, c.subject()};
  return r;
}

}  // namespace openmss::commands
