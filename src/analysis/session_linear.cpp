// Session: LINEAR/EIGENSOL and LINEAR/STATEMAT (linear analysis about the current operating
// point, docs/theory.md "Linear analysis") and the DEBUG command (EPRINT).

#include <complex>
#include <cstdio>
#include <filesystem>

#include "analysis/eigen_analysis.hpp"
#include "analysis/linearization.hpp"
#include "analysis/session.hpp"
#include "analysis/state_matrices.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"

namespace openmss::analysis {
namespace {

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

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

bool Session::setDebug(const language::Statement& c) {
  Diagnostics local;
  model::applyDebugArguments(c, model_->debug, local);
  for (const auto& d : local.all()) {
    diags_.add(d);
    report(d);
  }
  if (c.has("LIST"))
    msg_.line(std::string(" DEBUG: EPRINT ") + (model_->debug.eprint ? "on" : "off"));
  return !local.hasErrors();
}

bool Session::linear(const language::Statement& c) {
  const model::Model& m = *model_;
  const bool eigen = c.has("EIGENSOL"), statemat = c.has("STATEMAT");
  if (eigen == statemat) {
    error(c, "LINEAR needs exactly one of EIGENSOL and STATEMAT",
          "Write LINEAR/EIGENSOL for eigenvalues and mode shapes, or LINEAR/STATEMAT for the "
          "state matrices.");
    return false;
  }
  bool ok = true;
  for (const char* unsupported :
       {"MKB", "EXPORT", "PSTATE", "COORDS", "ENERGY", "DISSIPAT", "KINETIC"})
    if (const auto* a = c.find(unsupported)) {
      diags_.error(a->where, c.subject(), std::string(unsupported) + " is not supported yet",
                   "Supported: LINEAR/EIGENSOL [, NODAMPIN] [, NOVECTOR] and LINEAR/STATEMAT "
                   "[, PINPUT=id] [, POUTPUT=id] [, FORMAT=MATLAB|MATRIXX] [, FILE=name].");
      report(diags_.all().back());
      ok = false;
    }
  std::string format = "MATLAB";
  if (const auto* a = c.find("FORMAT"); a && !a->values.empty()) format = a->values[0].text;
  if (format != "MATLAB" && format != "MATRIXX") {
    diags_.error(c.find("FORMAT")->where, c.subject(), "FORMAT=" + format + " is not known",
                 "Write FORMAT=MATLAB (ASCII flat files) or FORMAT=MATRIXX (one MATSAVE file).");
    report(diags_.all().back());
    ok = false;
  }
  if (eigen)
    for (const char* only : {"PINPUT", "POUTPUT", "FORMAT", "FILE"})
      if (const auto* a = c.find(only)) {
        diags_.error(a->where, c.subject(), std::string(only) + " belongs to LINEAR/STATEMAT",
                     "Remove it from LINEAR/EIGENSOL, or write LINEAR/STATEMAT.");
        report(diags_.all().back());
        ok = false;
      }
  LinearizationRequest request;
  request.basis = eigen ? LinearBasis::Orthonormal : LinearBasis::PartCoordinates;
  request.withoutDamping = c.has("NODAMPIN");
  Diagnostics plant;
  ok = plantVariables(c, "PINPUT", m.pinputs, request.inputs, plant) && ok;
  ok = plantVariables(c, "POUTPUT", m.poutputs, request.outputs, plant) && ok;
  for (const auto& d : plant.all()) {
    diags_.add(d);
    report(d);
  }
  if (!ok) return false;

  // The operating point: the current state, with the initial conditions run first when no
  // analysis has run yet (a following SIMULATE still writes its initial output step).
  if (!initialized_) {
    if (!initialConditions()) return false;
    initialized_ = false;
  }
  model_->analysisStatus.mode = model::AnalysisMode::Linear;  // MODE = 7
  model_->analysisStatus.clearIntegrator();
  Eigen::VectorXd y = y_, yp = yp_;
  // Multipliers and accelerations consistent with these positions and velocities: the
  // projected linearisation is exact only where the residual vanishes.
  if (!mechanics::solveAccelerations(*system_, t_, y, yp)) {
    error(c,
          "the accelerations and constraint forces at time " + fmt("%.6E", t_) +
              " cannot be determined (singular mass or constraint matrix)",
          "Check that every moving part has mass and inertia.");
    return false;
  }
  LinearSystem linear;
  std::string why;
  if (!analysis::linearize(*system_, t_, y, yp, request, linear, &why)) {
    error(c, "no linear analysis: " + why,
          linear.degreesOfFreedom == 0 && why.find("degree of freedom") != std::string::npos
              ? "Linear analysis needs a model that can move: remove a MOTION or a JOINT."
              : "See docs/theory.md, \"Linear analysis\".");
    return false;
  }
  msg_.line("");
  msg_.line(" Linear analysis at time " + fmt("%.6E", t_) + ": " +
            std::to_string(linear.degreesOfFreedom) + " degrees of freedom, " +
            std::to_string(linear.userStates) + " user states, " + std::to_string(linear.a.rows()) +
            " states");
  if (eigen) {
    const auto modes = eigenModes(linear);
    for (const auto& line : eigenReport(modes, linear, m, t_, c.has("NOVECTOR"))) msg_.line(line);
    return true;
  }
  // STATEMAT.
  std::string base = prefix_;
  if (const auto* a = c.find("FILE"); a && !a->values.empty())
    base = a->values[0].written.empty() ? a->values[0].text : a->values[0].written;
  std::filesystem::path path(base);
  if (path.is_relative()) path = std::filesystem::path(options_.outputDirectory) / path;
  std::vector<std::string> written;
  std::string err;
  const bool wrote = format == "MATLAB"
                         ? writeMatlabStateMatrices(path.string(), linear, m, written, &err)
                         : writeMatrixxStateMatrices(path.string(), linear, m, written, &err);
  if (!wrote) {
    error(c, "cannot write the state matrices: " + err,
          "Check that the output directory is writable.");
    return false;
  }
  msg_.line("   States (x' = A x + B u, y = C x + D u):");
  for (size_t s = 0; s < linear.stateNames.size(); ++s)
    msg_.line("     " + std::to_string(s + 1) + "  " + linear.stateNames[s]);
  for (size_t i = 0; i < linear.inputNames.size(); ++i)
    msg_.line("   Input " + std::to_string(i + 1) + ": " + linear.inputNames[i]);
  for (size_t o = 0; o < linear.outputNames.size(); ++o)
    msg_.line("   Output " + std::to_string(o + 1) + ": " + linear.outputNames[o]);
  for (const auto& file : written) msg_.line("   Wrote " + file);
  return true;
}

}  // namespace openmss::analysis
