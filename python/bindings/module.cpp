// openmss._native: the optional pybind11 binding of the embeddable C++ API (src/api). It only
// converts the API's plain structs to Python objects; the user-facing classes (Model, Run, the
// exceptions) are pure Python in python/openmss (docs/python.md).

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <mutex>

#include "api/model_info.hpp"
#include "api/run.hpp"
#include "variant_run.hpp"

namespace py = pybind11;
using namespace openmss::api;

namespace {

// The solver keeps some process-wide state (the default user library, the first fatal error
// of a user subroutine), so runs from several Python threads take turns; other Python threads
// go on meanwhile (the GIL is released). Parallel studies use processes (docs/python.md).
std::mutex runMutex;

py::dict toDict(const DiagnosticRecord& d) {
  py::dict out;
  out["severity"] = d.severity;
  out["file"] = d.file;
  out["line"] = d.line;
  out["column"] = d.column;
  out["statement"] = d.statement;
  out["message"] = d.message;
  out["hint"] = d.hint;
  out["text"] = d.text;
  return out;
}

py::list toList(const std::vector<DiagnosticRecord>& records) {
  py::list out;
  for (const auto& d : records) out.append(toDict(d));
  return out;
}

py::dict toDict(const ModelInfo& m) {
  py::dict out;
  out["ok"] = m.ok;
  out["path"] = m.path;
  out["title"] = m.title;
  out["diagnostics"] = toList(m.diagnostics);
  out["dof"] = m.degreesOfFreedom;
  out["gruebler"] = m.grueblerCount;
  py::list parts, requests;
  for (const auto& p : m.parts) {
    py::dict d;
    d["id"] = p.id;
    d["name"] = p.name;
    d["ground"] = p.ground;
    d["mass"] = p.mass;
    parts.append(d);
  }
  for (const auto& r : m.requests) {
    py::dict d;
    d["id"] = r.id;
    d["name"] = r.name;
    d["kind"] = r.kind;
    d["i_marker"] = r.iMarker;
    d["j_marker"] = r.jMarker;
    requests.append(d);
  }
  out["parts"] = parts;
  out["requests"] = requests;
  return out;
}

py::dict toDict(const RunResult& r) {
  py::dict out;
  out["status"] = r.status == RunResult::Status::Completed    ? "completed"
                  : r.status == RunResult::Status::InputError ? "input_error"
                                                              : "failed";
  out["time"] = r.time;
  out["steps"] = r.steps;
  out["output_steps"] = r.outputSteps;
  out["analysis"] = r.analysis;
  out["outdir"] = r.outputDirectory;
  out["prefix"] = r.prefix;
  out["msg"] = r.messageFile;
  out["req"] = r.requestFile;
  out["res"] = r.resultsFile;
  out["diagnostics"] = toList(r.diagnostics);
  return out;
}

}  // namespace

PYBIND11_MODULE(_native, m) {
  m.doc() = "OpenMSS embeddable API (src/api); use the classes of the openmss package";
  m.attr("version") = OPENMSS_VERSION;
  m.def(
      "load_model",
      [](const std::string& path) {
        ModelInfo info;
        {
          py::gil_scoped_release release;
          std::lock_guard<std::mutex> lock(runMutex);
          info = loadModel(path);
        }
        return toDict(info);
      },
      py::arg("path"), "Read and check a data set: diagnostics, dof, parts, requests (a dict)");
  m.def(
      "run_acf",
      [](const std::string& path, const std::string& outdir) {
        RunResult r;
        {
          py::gil_scoped_release release;
          std::lock_guard<std::mutex> lock(runMutex);
          r = runCommandFile(path, outdir);
        }
        return toDict(r);
      },
      py::arg("path"), py::arg("outdir"), "Run an ADAMS command file into outdir (a dict)");
  m.def(
      "simulate",
      [](const std::string& path, const std::string& outdir, double end, double dtout, long steps,
         const std::string& integrator, double error, const std::string& prefix) {
        SimulateOptions o;
        o.end = end;
        o.dtout = dtout;
        o.steps = steps;
        o.integrator = integrator;
        o.error = error;
        o.prefix = prefix;
        RunResult r;
        {
          py::gil_scoped_release release;
          std::lock_guard<std::mutex> lock(runMutex);
          r = simulateModel(path, o, outdir);
        }
        return toDict(r);
      },
      py::arg("path"), py::arg("outdir"), py::arg("end"), py::arg("dtout"), py::arg("steps"),
      py::arg("integrator"), py::arg("error"), py::arg("prefix"),
      "Simulate a data set (SIMULATE/TRANSIENT) into outdir (a dict)");
  m.def(
      "run_variant",
      [](const std::string& model, const std::string& outdir,
         const std::vector<std::string>& overrides, double end, long steps, double dtout) {
        openmss::pybind::VariantRun r;
        {
          py::gil_scoped_release release;
          std::lock_guard<std::mutex> lock(runMutex);
          r = openmss::pybind::runVariant(model, outdir, overrides, end, steps, dtout);
        }
        return py::make_tuple(r.exitStatus, r.errorText);
      },
      py::arg("model"), py::arg("outdir"), py::arg("overrides"), py::arg("end") = 1.0,
      py::arg("steps") = 100, py::arg("dtout") = 0.0,
      "As `openmss run MODEL --quiet --outdir DIR --set ...` in this process, for a design "
      "study's variant: (exit status, standard error text)");
}
