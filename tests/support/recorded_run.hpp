#pragma once
// An analysis driven without the Session (tests/analysis): a data set built into a model, its
// equations and a run state as the Session loads one, and a report that keeps in memory what
// the Session would write to the .msg and .req.

#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "analysis/analysis_context.hpp"
#include "analysis/model_summary.hpp"
#include "analysis/run_report.hpp"
#include "analysis/run_state.hpp"
#include "common/diagnostics.hpp"
#include "language/reader.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"

namespace openmss::testing {

// Everything an analysis reports, kept in memory.
class RecordingReport final : public analysis::RunReport {
 public:
  struct Step {
    double t;
    std::vector<std::array<double, 6>> rows;
  };
  void line(const std::string& text) override { lines.push_back(text); }
  void diagnostic(const Diagnostic& d) override { diagnostics.push_back(d); }
  bool openRequests() override { return true; }
  bool requestsWritten() const override { return false; }
  void writeRequests(double t, const std::vector<std::array<double, 6>>& rows) override {
    steps.push_back({t, rows});
  }
  std::vector<std::string> lines;
  std::vector<Diagnostic> diagnostics;
  std::vector<Step> steps;
};

// A data set built into a model, its equations and a run state, as the Session loads one.
struct Loaded {
  model::Model model;
  std::unique_ptr<mechanics::MultibodySystem> system;
  std::unique_ptr<analysis::RunState> state;
  RecordingReport report;
  analysis::AnalysisContext context() {
    return analysis::AnalysisContext{model, *system, *state, report};
  }
};

// Any diagnostic of the data set fails the calling test.
inline std::unique_ptr<Loaded> load(const std::string& text) {
  auto l = std::make_unique<Loaded>();
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "model.adm", ds, d);
  EXPECT_TRUE(model::buildModel(ds, l->model, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  l->model.output.reqsave = true;  // OUTPUT/REQSAVE: the request rows reach the report
  l->system = std::make_unique<mechanics::MultibodySystem>(l->model);
  l->state = std::make_unique<analysis::RunState>(*l->system);
  const auto dof = analysis::countDegreesOfFreedom(*l->system, l->state->y);
  l->state->degreesOfFreedom = dof.degreesOfFreedom;
  l->state->grueblerCount = dof.gruebler;
  return l;
}

}  // namespace openmss::testing
