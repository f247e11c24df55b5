#include "analysis/analysis_context.hpp"

#include <cstdio>

#include "analysis/output_frame_builder.hpp"
#include "mechanics/redundancy_check.hpp"

namespace openmss::analysis {
namespace {

Diagnostic located(Severity severity, const model::Model& m, const RunOrigin* origin,
                   std::string message, std::string hint) {
  Diagnostic d;
  d.severity = severity;
  d.where = origin ? origin->where : SourceLocation{m.file, 0, 0};
  d.subject = origin ? origin->subject : std::string();
  d.message = std::move(message);
  d.hint = std::move(hint);
  return d;
}

}  // namespace

std::string formatNumber(const char* format, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, value);
  return buf;
}

void AnalysisContext::error(const RunOrigin* origin, std::string message, std::string hint) const {
  report.diagnostic(located(Severity::Error, model, origin, std::move(message), std::move(hint)));
}

void AnalysisContext::warning(const RunOrigin* origin, std::string message,
                              std::string hint) const {
  report.diagnostic(located(Severity::Warning, model, origin, std::move(message), std::move(hint)));
}

bool AnalysisContext::writeOutputStep(double t, const Eigen::VectorXd& y,
                                      const Eigen::VectorXd& yp, output::OutputKind kind) const {
  const model::Model& m = model;
  if (const auto bad = mechanics::violatedRedundantEquation(system, t, y.data(),
                                                            mechanics::redundantTolerance(m))) {
    error(nullptr, mechanics::describeViolation(system, *bad, t),
          "Make the duplicated constraints agree (coaxial hinges stay coaxial, a motion "
          "must not drive the mechanism where a removed equation cannot follow), or "
          "replace the redundant joint by a joint primitive. Outputs up to the last good "
          "step are written.");
    return false;
  }
  const bool frames = report.wantsFrames();
  const bool tabular = report.wantsTabular();
  if (!m.output.reqsave && !frames && !tabular) return true;
  // The request columns are computed once, for the .req and the snapshot alike.
  OutputFrame frame;
  frame.kind = kind;
  fillRequestColumns(system, t, y, yp, frame);
  if (m.output.reqsave) {
    if (!report.openRequests()) return false;
    std::vector<std::array<double, 6>> rows;
    rows.reserve(m.requests.size());
    constexpr double kDeg = 180.0 / 3.14159265358979323846;
    for (std::size_t k = 0; k < m.requests.size(); ++k) {
      const auto& c = frame.requests[k];
      std::array<double, 6> row = {c[1], c[2], c[3], c[5], c[6], c[7]};
      // The request file holds displacement angles in degrees.
      if (m.requests[k].kind == model::Request::Kind::Displacement)
        for (int j = 3; j < 6; ++j) row[j] *= kDeg;
      rows.push_back(row);
    }
    report.writeRequests(t, rows);
  }
  if (tabular && !report.writeTabular(frame)) return false;
  if (frames) {
    fillStateOutputs(system, t, y, yp, frame);
    if (!report.writeFrame(frame)) return false;
  }
  ++state.summary.outputSteps;
  return true;
}

}  // namespace openmss::analysis
