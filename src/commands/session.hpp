#pragma once
// A solver session: the loaded model, its run state, and the open output files, driven by
// commands (from an .acf file, the command line, or a prompt). The session reads each command
// into a typed request (simulate_command.hpp, linear_command.hpp) and hands it to the analysis
// drivers (analysis/*_run.hpp); it writes what they report to <prefix>.msg and <prefix>.req
// (docs/architecture.md).

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "analysis/analysis_context.hpp"
#include "analysis/model_summary.hpp"
#include "analysis/run_report.hpp"
#include "analysis/run_state.hpp"
#include "analysis/save_file.hpp"
#include "commands/model_edits.hpp"
#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model.hpp"
#include "model/results_arguments.hpp"
#include "output/graphics_file.hpp"
#include "output/message_log.hpp"
#include "output/request_file.hpp"
#include "output/results_file.hpp"
#include "output/results_formatted_file.hpp"
#include "output/tabular_file.hpp"
#include "solvers/pivot_order.hpp"

namespace openmss::commands {

struct SessionOptions {
  std::string outputDirectory = ".";
  bool progress = false;         // a progress line on the terminal (stderr)
  bool echoDiagnostics = true;   // print diagnostics on stderr
  bool printInformation = true;  // INFO, SHOW, TIME, MENU also print on stdout
  // `openmss check FILE.acf`: every command is read and checked against the model (ids,
  // arguments, the model each change leaves) but no analysis runs and no file is written;
  // SIMULATE only advances the time to its END.
  bool checkOnly = false;
  // `openmss run … --set STATEMENT/id.ARGUMENT=value`: laid over every data set loaded
  // (dataset_overrides.hpp).
  std::vector<std::string> overrides;
  // `openmss run … --pivot-order NAME` (diagnostics): KLU's pivot order for the multistep
  // integrators, for tests and benches only (solvers/pivot_order.hpp).
  solvers::PivotOrder pivotOrder = solvers::PivotOrder::Default;
};

class Session final : private analysis::RunReport {
 public:
  explicit Session(SessionOptions options);
  ~Session() override;

  // Reads, checks and loads a data set; opens <prefix>.msg (and .req on first output).
  bool loadModel(const std::string& path, const std::string& outputPrefix);
  // Executes one command; returns false when it failed (the reason is in the diagnostics).
  bool execute(const language::Statement& command);
  bool stopped() const { return stopped_; }

  const Diagnostics& diagnostics() const { return diags_; }
  const model::Model* model() const { return model_.get(); }
  const analysis::RunSummary& summary() const;
  // The state after the last analysis (null before a model is loaded), for callers that read
  // results beyond the printed request file (tests against closed forms).
  const analysis::RunState* state() const { return state_.get(); }
  const mechanics::MultibodySystem* system() const { return system_.get(); }
  std::string requestFilePath() const;
  std::string messageFilePath() const;
  std::string resultsFilePath() const;
  std::string tabularFilePath() const;
  int degreesOfFreedom() const { return state_ ? state_->degreesOfFreedom : 0; }
  int grueblerDegreesOfFreedom() const { return state_ ? state_->grueblerCount : 0; }

  // Message-file echo of a command, as ADAMS writes it.
  void echoCommand(const std::string& text);

  // Embedding (docs/embedding.md; plant_inputs.cpp): VARIABLEs (indices into
  // Model::variables, each listed by a PINPUT and without DELAY; the caller checks) hold the
  // values given: their FUNCTION becomes that constant in the model at hand (a rebuilt or
  // reloaded model has the data set's again). When the initial conditions hold, the user
  // algebraic unknowns, the accelerations and the user state rates are made consistent at the
  // current time, as at a GSE sample; positions, velocities and user differential states do
  // not move. False when that fails.
  bool setPlantInputs(const std::vector<std::pair<int, double>>& values);

 private:
  analysis::AnalysisContext context();
  bool dispatch(const language::Statement& command);
  // Every command but STOP, once a model is there (or, in check mode, its data set).
  bool dispatchChecked(const language::Statement& command);
  // Check mode with a data set that has errors (check_commands.cpp): no system, the commands
  // are checked against the data set; checkTime_ is the time SIMULATEs so far reach.
  bool checkWithoutSystem(const language::Statement& command);
  bool checkSaveOrReload(const language::Statement& command, const std::string& path);
  double checkTime_ = 0.0;
  std::set<std::string> checkSaved_;  // save files named by SAVE in check mode
  // SAVE/STATES, SAVE/SYSTEM, RELOAD/STATES, RELOAD/SYSTEM (save_reload_command.cpp).
  bool saveOrReload(const language::Statement& command);
  bool save(const language::Statement& command);
  bool reload(const language::Statement& command);
  bool reloadSystem(const language::Statement& command, const analysis::SaveFile& file);
  bool switchOutputPrefix(const language::Statement& command);
  std::string modelDirectory() const;  // where ROUTINE= and user libraries are looked for
  void recordCommand(const language::Statement& command, const std::vector<std::string>& echo);
  bool simulate(const language::Statement& command);
  bool linear(const language::Statement& command);
  void stop();
  // Settings commands (settings_commands.cpp): INTEGRATOR (and GSTIFF, WSTIFF, DSTIFF),
  // OUTPUT, EQUILIBRIUM, IC and KINEMATICS, DEBUG. Each changes the model's settings for
  // later analyses.
  bool setIntegrator(const language::Statement& command);
  bool setOutput(const language::Statement& command);
  bool setAnalysisParameters(const language::Statement& command);
  bool setDebug(const language::Statement& command);
  // Element commands (element_commands.cpp): ACTIVATE, DEACTIVATE and the commands that
  // redefine a statement. They change pendingEdits_; applyEdits builds the model of the next
  // analysis from the Dataset and the edits and carries the state over.
  static bool isElementCommand(const std::string& name);
  bool elementCommand(const language::Statement& command);
  bool switchElements(const language::Statement& command);
  bool redefine(const language::Statement& command);
  bool acceptEdits(const language::Statement& command, const ModelEdits& next);
  bool applyEdits(const language::Statement& command);
  // Information and environment commands (info_commands.cpp): INFO, SHOW, TIME, MENU,
  // PREFERENCES, LSOLVER, ENVIRONMENT, CONTROL, ACCGRAV/LIST.
  static bool isInformationCommand(const std::string& name);
  bool informationCommand(const language::Statement& command);
  bool info(const language::Statement& command);
  // CONTROL and the utilities of its CONSUB (control_command.cpp); each utility returns istat.
  bool control(const language::Statement& command);
  int controlAnalys(const language::Statement& command, const std::string& antype,
                    const std::string& cid, double timbeg, double timend, bool init);
  int controlDatout(const language::Statement& command);
  int controlModify(const language::Statement& command, const std::string& text);
  bool outputSuppressed_ = false;  // an ANALYS of CONSUB runs: no output step is written
  bool show(const language::Statement& command);
  bool preferences(const language::Statement& command);
  void inform(const std::string& text, bool messageFile = true);
  // Reports (and keeps) diagnostics gathered while reading a command.
  void reportAll(const Diagnostics& local);
  // The model summary and the redundant equations removed, into the .msg (the model as
  // loaded, and again after every reprocessing).
  void reportModelSummary(const analysis::DegreeOfFreedomCount& dof);
  void error(const language::Statement& s, const std::string& message, const std::string& hint);

  // analysis::RunReport: the .msg, the diagnostics and the .req of the analyses.
  void line(const std::string& text) override { msg_.line(text); }
  void diagnostic(const Diagnostic& d) override;
  bool openRequests() override;
  bool requestsWritten() const override { return req_.isOpen(); }
  void writeRequests(double t, const std::vector<std::array<double, 6>>& rows) override;
  // The .res of a RESULTS statement (output/results_file.hpp): opened at the first step,
  // closed (valid XML, with the run's status) by STOP, a new model or the destructor.
  bool wantsFrames() const override;
  bool writeFrame(const analysis::OutputFrame& frame) override;
  // The .out of a model with REQUESTs (output/tabular_file.hpp), unless OUTPUT/NOPRINT: opened
  // at the first step, closed with the .res.
  bool wantsTabular() const override;
  bool writeTabular(const analysis::OutputFrame& frame) override;
  void closeResults();
  void progressStart() override;
  void progress(double t, double t0, double end, long steps) override;
  void progressDone() override;

  SessionOptions options_;
  Diagnostics diags_;
  output::MessageLog msg_;
  output::RequestFileWriter req_;
  output::ResultsFileWriter res_;
  // RESULTS and CNAMES of the data set (results_arguments.hpp); resFailed_: the .res could not
  // be written, not tried again for this model; analysisFailed_: an analysis of this model
  // failed (the .res says "Failed").
  model::ResultsSettings results_;
  bool resFailed_ = false;
  bool analysisFailed_ = false;
  // The .gra of OUTPUT/GRSAVE (output/graphics_file.hpp), written from the same frames.
  output::GraphicsFileWriter gra_;
  bool graFailed_ = false;
  // The .res of RESULTS/FORMATTED (output/results_formatted_file.hpp), instead of res_.
  output::FormattedResultsWriter formattedRes_;
  bool writeFormattedResults(const analysis::OutputFrame& frame);
  output::TabularFileWriter out_;
  bool outFailed_ = false;
  bool writeGraphicsFrame(const analysis::OutputFrame& frame);
  std::string prefix_;
  // The data set as read; never edited (model_edits.hpp). A loaded model's statement tree is
  // released once the model is built and read again from datasetText_ by dataset() when a
  // command needs it (element commands, GRSAVE's graphics, RELOAD/SYSTEM's fallback): a run of
  // a large data set does not hold it (docs/performance.md, "Memory of a parsed data set").
  const language::Dataset& dataset();
  language::Dataset dataset_;
  bool datasetReleased_ = false;  // dataset_ is empty; dataset() reads datasetText_ again
  std::string datasetPath_;       // the file datasetText_ was read from
  ModelEdits pendingEdits_;       // as the commands so far leave the model
  ModelEdits appliedEdits_;       // as the model_ of the last analysis was built
  bool editsPending_ = false;     // pendingEdits_ differ from appliedEdits_
  std::unique_ptr<model::Model> model_;
  std::unique_ptr<mechanics::MultibodySystem> system_;
  std::unique_ptr<analysis::RunState> state_;
  bool stopped_ = false;
  // For SAVE/SYSTEM (save_reload_command.cpp): the data set's text as loaded, and the
  // model-changing commands since, as echoed (pendingEcho_: the echo of the command at hand).
  std::string datasetText_;
  std::vector<std::string> commandHistory_, pendingEcho_;
  std::set<std::string> warnedOptions_;  // PREFERENCES/LSOLVER/ENVIRONMENT warnings given
  double progressStart_ = 0.0, progressLast_ = 0.0;  // steady-clock seconds
};

}  // namespace openmss::commands
