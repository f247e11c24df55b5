#pragma once
// A solver session: the loaded model, its state, the analysis settings and the open output
// files, driven by commands (from an .acf file, the command line, or a prompt).

#include <memory>
#include <string>

#include "analysis/message_log.hpp"
#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model.hpp"
#include "output/request_file.hpp"
#include "solvers/bdf_integrator.hpp"

namespace openmss::analysis {

struct SessionOptions {
  std::string outputDirectory = ".";
  bool progress = false;  // a progress line on the terminal (stderr)
  bool echoDiagnostics = true;  // print diagnostics on stderr
};

struct RunSummary {
  double time = 0.0;
  long steps = 0;
  long outputSteps = 0;
  long jacobians = 0;
  long residuals = 0;
  std::string analysis;
};

class Session {
 public:
  explicit Session(SessionOptions options);
  ~Session();

  // Reads, checks and loads a data set; opens <prefix>.msg (and .req on first output).
  bool loadModel(const std::string& path, const std::string& outputPrefix);
  // Executes one command; returns false when it failed (the reason is in the diagnostics).
  bool execute(const language::Statement& command);
  bool stopped() const { return stopped_; }

  const Diagnostics& diagnostics() const { return diags_; }
  const model::Model* model() const { return model_.get(); }
  const RunSummary& summary() const { return summary_; }
  std::string requestFilePath() const;
  std::string messageFilePath() const;
  int degreesOfFreedom() const { return dof_; }
  int grueblerDegreesOfFreedom() const { return gruebler_; }

  // Message-file echo of a command, as ADAMS writes it.
  void echoCommand(const std::string& text);

 private:
  // Writes what the position assembly moved to the .msg; reports and returns false when it
  // could not close the constraints.
  bool reportAssembly(const mechanics::AssemblyResult& r);
  bool simulate(const language::Statement& command);
  bool setIntegrator(const language::Statement& command);
  bool setOutput(const language::Statement& command);
  bool initialConditions();
  // Statics and initial-condition analyses (session_statics.cpp).
  bool setAnalysisParameters(const language::Statement& command);  // EQUILIBRIUM, IC commands
  bool simulateStaticsOrInitialConditions(const language::Statement& command);
  bool staticEquilibriumAt(double t);
  mechanics::AssemblyResult assembleForInitialConditions();
  // LINEAR/EIGENSOL and LINEAR/STATEMAT, and the DEBUG command (session_linear.cpp).
  bool linear(const language::Statement& command);
  bool setDebug(const language::Statement& command);
  bool writeOutputStep(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp);
  void report(const Diagnostic& d);
  void error(const language::Statement& s, const std::string& message, const std::string& hint);

  SessionOptions options_;
  Diagnostics diags_;
  MessageLog msg_;
  output::RequestFileWriter req_;
  std::string prefix_;
  std::unique_ptr<model::Model> model_;
  std::unique_ptr<mechanics::MultibodySystem> system_;
  // History of the cumulative AX/AY/AZ and DELAY (mechanics/expression_run_state.hpp), updated
  // after accepted states only; the system reads it through setRunState.
  std::unique_ptr<mechanics::ExpressionRunState> runState_;
  bool initialized_ = false;
  bool stopped_ = false;
  double t_ = 0.0;
  Eigen::VectorXd y_, yp_;
  int dof_ = 0, gruebler_ = 0;
  RunSummary summary_;
  size_t diagnosticsReported_ = 0;
};

}  // namespace openmss::analysis
