#include "app/api_command.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "api/model_info.hpp"
#include "api/run.hpp"
#include "output/request_file_reader.hpp"

namespace openmss::app {
namespace {

// A minimal JSON writer: strings escaped per RFC 8259, numbers with 17 significant digits
// (exact round trip of a double), non-finite numbers as null.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const unsigned char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out + "\"";
}

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string diagnostics(const std::vector<api::DiagnosticRecord>& records) {
  std::string out = "[";
  for (std::size_t k = 0; k < records.size(); ++k) {
    const auto& d = records[k];
    out += (k ? "," : "") + std::string("{\"severity\":") + quoted(d.severity) +
           ",\"file\":" + quoted(d.file) + ",\"line\":" + std::to_string(d.line) +
           ",\"column\":" + std::to_string(d.column) + ",\"statement\":" + quoted(d.statement) +
           ",\"message\":" + quoted(d.message) + ",\"hint\":" + quoted(d.hint) +
           ",\"text\":" + quoted(d.text) + "}";
  }
  return out + "]";
}

std::string json(const api::ModelInfo& m) {
  std::string parts = "[", requests = "[";
  for (std::size_t k = 0; k < m.parts.size(); ++k) {
    const auto& p = m.parts[k];
    parts += (k ? "," : "") + std::string("{\"id\":") + std::to_string(p.id) +
             ",\"name\":" + quoted(p.name) + ",\"ground\":" + (p.ground ? "true" : "false") +
             ",\"mass\":" + number(p.mass) + "}";
  }
  for (std::size_t k = 0; k < m.requests.size(); ++k) {
    const auto& r = m.requests[k];
    requests += (k ? "," : "") + std::string("{\"id\":") + std::to_string(r.id) +
                ",\"name\":" + quoted(r.name) + ",\"kind\":" + quoted(r.kind) +
                ",\"i_marker\":" + std::to_string(r.iMarker) +
                ",\"j_marker\":" + std::to_string(r.jMarker) + "}";
  }
  return std::string("{\"ok\":") + (m.ok ? "true" : "false") + ",\"path\":" + quoted(m.path) +
         ",\"title\":" + quoted(m.title) + ",\"diagnostics\":" + diagnostics(m.diagnostics) +
         ",\"dof\":" + std::to_string(m.degreesOfFreedom) +
         ",\"gruebler\":" + std::to_string(m.grueblerCount) + ",\"parts\":" + parts +
         "],\"requests\":" + requests + "]}";
}

std::string json(const api::RunResult& r) {
  const char* status = r.status == api::RunResult::Status::Completed    ? "completed"
                       : r.status == api::RunResult::Status::InputError ? "input_error"
                                                                        : "failed";
  return std::string("{\"status\":") + quoted(status) + ",\"time\":" + number(r.time) +
         ",\"steps\":" + std::to_string(r.steps) +
         ",\"output_steps\":" + std::to_string(r.outputSteps) +
         ",\"analysis\":" + quoted(r.analysis) + ",\"outdir\":" + quoted(r.outputDirectory) +
         ",\"prefix\":" + quoted(r.prefix) + ",\"msg\":" + quoted(r.messageFile) +
         ",\"req\":" + quoted(r.requestFile) + ",\"res\":" + quoted(r.resultsFile) +
         ",\"diagnostics\":" + diagnostics(r.diagnostics) + "}";
}

std::string json(const output::RequestFileData& d) {
  std::string out = "{\"ids\":[";
  for (std::size_t k = 0; k < d.entries.size(); ++k)
    out += (k ? "," : "") + std::to_string(d.entries[k].id);
  out += "],\"types\":[";
  for (std::size_t k = 0; k < d.entries.size(); ++k)
    out += (k ? "," : "") + std::to_string(d.entries[k].type);
  out += "],\"steps\":[";
  for (std::size_t s = 0; s < d.steps.size(); ++s) {
    out += (s ? ",[" : "[") + number(d.steps[s].time);
    for (const auto& row : d.steps[s].rows)
      for (double v : row) out += "," + number(v);
    out += "]";
  }
  return out + "]}";
}

int usage() {
  std::fprintf(stderr,
               "usage: openmss api load FILE.adm | run-acf FILE.acf OUTDIR | simulate FILE.adm "
               "OUTDIR END DTOUT STEPS INTEGRATOR ERROR PREFIX | read-req FILE.req\n");
  return 64;
}

}  // namespace

int apiCommand(int argc, char** argv) {
  if (argc < 4) return usage();
  const std::string what = argv[2];
  std::string out;
  if (what == "load" && argc == 4) {
    out = json(api::loadModel(argv[3]));
  } else if (what == "run-acf" && argc == 5) {
    out = json(api::runCommandFile(argv[3], argv[4]));
  } else if (what == "simulate" && argc == 11) {
    api::SimulateOptions o;
    o.end = std::strtod(argv[5], nullptr);
    o.dtout = std::strtod(argv[6], nullptr);
    o.steps = std::strtol(argv[7], nullptr, 10);
    o.integrator = argv[8];
    o.error = std::strtod(argv[9], nullptr);
    o.prefix = argv[10];
    out = json(api::simulateModel(argv[3], o, argv[4]));
  } else if (what == "read-req" && argc == 4) {
    std::string error;
    const auto data = output::readRequestFile(argv[3], &error);
    if (!data) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    out = json(*data);
  } else {
    return usage();
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  std::fputc('\n', stdout);
  return 0;
}

}  // namespace openmss::app
