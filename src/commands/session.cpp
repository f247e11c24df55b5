#include "commands/session.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "analysis/initial_conditions_run.hpp"
#include "analysis/linear_run.hpp"
#include "analysis/model_summary.hpp"
#include "analysis/statics_run.hpp"
#include "analysis/transient_run.hpp"
#include "commands/dataset_overrides.hpp"
#include "commands/linear_command.hpp"
#include "commands/save_reload_command.hpp"
#include "commands/simulate_command.hpp"
#include "language/reader.hpp"
#include "model/graphics_builder.hpp"
#include "model/model_builder.hpp"
#include "model/releasing_build.hpp"
#include "output/request_header.hpp"

namespace openmss::commands {
namespace {

double steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

Session::Session(SessionOptions options) : options_(std::move(options)) {}
Session::~Session() { closeResults(); }

std::string Session::requestFilePath() const {
  return (std::filesystem::path(options_.outputDirectory) / (prefix_ + ".req")).string();
}
std::string Session::resultsFilePath() const {
  return (std::filesystem::path(options_.outputDirectory) / (prefix_ + ".res")).string();
}
std::string Session::tabularFilePath() const {
  return (std::filesystem::path(options_.outputDirectory) / (prefix_ + ".out")).string();
}
std::string Session::messageFilePath() const {
  return (std::filesystem::path(options_.outputDirectory) / (prefix_ + ".msg")).string();
}

const analysis::RunSummary& Session::summary() const {
  static const analysis::RunSummary kNone;
  return state_ ? state_->summary : kNone;
}

analysis::AnalysisContext Session::context() {
  return analysis::AnalysisContext{*model_, *system_, *state_, *this, options_.pivotOrder};
}

void Session::diagnostic(const Diagnostic& d) {
  diags_.add(d);
  msg_.diagnostic(d);
  if (options_.echoDiagnostics) std::fprintf(stderr, "%s\n", format(d).c_str());
}

void Session::reportAll(const Diagnostics& local) {
  for (const auto& d : local.all()) diagnostic(d);
}

void Session::error(const language::Statement& s, const std::string& message,
                    const std::string& hint) {
  Diagnostic d;
  d.where = s.where;
  d.subject = s.subject();
  d.message = message;
  d.hint = hint;
  diagnostic(d);
}

void Session::echoCommand(const std::string& text) {
  msg_.line(" command: " + text);
  pendingEcho_.push_back(text);  // SAVE/SYSTEM's command history (save_reload_command.cpp)
}

bool Session::loadModel(const std::string& path, const std::string& outputPrefix) {
  closeResults();  // the previous model's .res (the map is the model's)
  resFailed_ = analysisFailed_ = false;
  graFailed_ = outFailed_ = false;
  prefix_ = outputPrefix;
  if (!options_.checkOnly) std::filesystem::create_directories(options_.outputDirectory);
  if (!options_.checkOnly && !msg_.open(messageFilePath())) {
    Diagnostic d;
    d.where = {path, 0, 0};
    d.message = "cannot create the message file " + messageFilePath();
    d.hint = "Check that the output directory exists and is writable.";
    diagnostic(d);
    return false;
  }
  msg_.line("OpenMSS " + std::string(OPENMSS_VERSION) +
            " -- mechanical system simulation (ADAMS/Solver data sets)");
  msg_.line("");
  msg_.line(" command: FILE/MODEL=" + path + ", OUTPUT_PREFIX=" + prefix_);

  language::Dataset dataset;
  Diagnostics readDiags;
  language::readDatasetFile(path, dataset, readDiags);
  for (const auto& o : options_.overrides) msg_.line(" override: --set " + o);
  applyOverrides(options_.overrides, dataset, readDiags);
  datasetText_ = readTextFile(path);  // SAVE/SYSTEM (save_reload_command.hpp)
  commandHistory_.clear();
  // A model loaded at the prompt after a run starts afresh; the old run state and system
  // refer to the model about to be replaced.
  state_.reset();
  system_.reset();
  pendingEdits_ = appliedEdits_ = ModelEdits{};
  editsPending_ = false;
  model_ = std::make_unique<model::Model>();
  // Model checks even after read errors. The CONTACTs' arguments are released as they are
  // built, and the rest of the tree below: dataset() reads it again when a command needs it.
  model::buildModelReleasingContacts(dataset, *model_, readDiags);
  // The .res of RESULTS, with REQUEST's CNAMES (model/results_arguments.hpp).
  results_ = model::readResultsSettings(dataset, readDiags);
  reportAll(readDiags);
  msg_.line("");
  msg_.line(" Model title: " + dataset.title);
  // Released: the element commands build their model from dataset(), read again.
  dataset = language::Dataset();
  dataset_ = language::Dataset();
  datasetPath_ = path;
  datasetReleased_ = true;
  // Only this data set's errors count: at the prompt, earlier commands may have failed.
  if (readDiags.hasErrors()) {
    msg_.line(" The data set has " + std::to_string(readDiags.errorCount()) +
              " error(s); no analysis is possible.");
    return false;
  }
  system_ = std::make_unique<mechanics::MultibodySystem>(*model_);
  // Cumulative angles and DELAY histories of this model's run (docs/theory.md §11a).
  state_ = std::make_unique<analysis::RunState>(*system_);
  state_->outputPrefix = prefix_;
  // Model summary and degree-of-freedom analysis at the data set's configuration.
  const analysis::DegreeOfFreedomCount dof = analysis::countDegreesOfFreedom(*system_, state_->y);
  state_->degreesOfFreedom = dof.degreesOfFreedom;
  state_->grueblerCount = dof.gruebler;
  reportModelSummary(dof);
  return true;
}

// The same text with the same --set overrides gives the same tree; its diagnostics were
// reported when the model was loaded.
const language::Dataset& Session::dataset() {
  if (datasetReleased_) {
    Diagnostics again;
    language::readDatasetText(datasetText_, datasetPath_, dataset_, again);
    applyOverrides(options_.overrides, dataset_, again);
    datasetReleased_ = false;
  }
  return dataset_;
}

void Session::reportModelSummary(const analysis::DegreeOfFreedomCount& dof) {
  for (const auto& l : analysis::modelSummaryLines(*system_, dof)) msg_.line(l);
  for (int k : dof.removed)
    context().warning(nullptr, "redundant constraint equation removed: " +
                                   system_->constraints().describe(k, *model_) +
                                   " (its reaction is carried by the equations kept)");
}

void Session::stop() {
  stopped_ = true;
  msg_.line("");
  msg_.line(" Finished -----");
  req_.close();
  closeResults();
}

bool Session::execute(const language::Statement& c) {
  const std::vector<std::string> echo = std::exchange(pendingEcho_, {});
  const bool ok = dispatch(c);
  if (ok) recordCommand(c, echo);  // SAVE/SYSTEM replays model-changing commands
  return ok;
}

bool Session::dispatch(const language::Statement& c) {
  if (c.name == "STOP") {
    stop();
    return true;
  }
  if (!system_) {
    // `openmss check` of a data set with errors: the commands are checked all the same.
    if (options_.checkOnly && model_) return checkWithoutSystem(c);
    error(c, "no model is loaded", "Load a data set first (line 1 of the .acf, or FILE/MODEL=).");
    return false;
  }
  return dispatchChecked(c);
}

bool Session::dispatchChecked(const language::Statement& c) {
  if (c.name == "SIMULATE") return simulate(c);
  if (c.name == "INTEGRATOR" || c.name == "GSTIFF" || c.name == "WSTIFF" || c.name == "DSTIFF")
    return setIntegrator(c);
  if (c.name == "OUTPUT") return setOutput(c);
  if (c.name == "EQUILIBRIUM" || c.name == "IC" || c.name == "KINEMATICS")
    return setAnalysisParameters(c);
  if (c.name == "LINEAR") return linear(c);
  if (c.name == "DEBUG") return setDebug(c);
  if (c.name == "SAVE" || c.name == "RELOAD") return saveOrReload(c);
  if (isElementCommand(c.name)) return elementCommand(c);
  if (isInformationCommand(c.name)) return informationCommand(c);
  error(c, c.name + " is not supported yet by the solver",
        "README.md lists the supported commands; remove this one or run it elsewhere.");
  return false;
}

bool Session::simulate(const language::Statement& c) {
  if (!applyEdits(c)) return false;
  Diagnostics local;
  const auto request = readSimulate(c, state_->t, local);
  reportAll(local);
  if (!request) return false;
  if (options_.checkOnly) {  // the time the analysis would reach, for the next END= checks
    if (const auto* t = std::get_if<analysis::TransientRun>(&*request)) state_->t = t->end;
    if (const auto* st = std::get_if<analysis::StaticsRun>(&*request); st && st->end)
      state_->t = *st->end;
    return true;
  }
  const analysis::AnalysisContext run = context();
  res_.beginAnalysis();  // each SIMULATE is a new <Data> block of the .res
  out_.beginAnalysis();  // and a new analysis block of the .out
  bool ok = false;
  if (const auto* ic = std::get_if<analysis::InitialConditionsRun>(&*request))
    ok = analysis::runInitialConditions(run, *ic);
  else if (const auto* statics = std::get_if<analysis::StaticsRun>(&*request))
    ok = analysis::runStatics(run, *statics);
  else
    ok = analysis::runTransient(run, std::get<analysis::TransientRun>(*request));
  if (!ok) {
    analysisFailed_ = true;
    res_.markFailed();  // TerminationStatus runStatus="Failed" (every step so far is kept)
    out_.markFailed();
    return false;
  }
  if (state_->halted) stop();  // SENSOR/HALT ends the run as STOP does
  return true;
}

bool Session::linear(const language::Statement& c) {
  if (!applyEdits(c)) return false;
  Diagnostics local;
  const auto request = readLinear(c, *model_, options_.outputDirectory, prefix_, local);
  reportAll(local);
  if (!request) return false;
  if (options_.checkOnly) return true;
  return analysis::runLinear(context(), *request);
}

bool Session::openRequests() {
  if (req_.isOpen()) return true;
  const model::Model& m = *model_;
  bool unitsKnown = true;
  const output::RequestFileHeader h = output::requestFileHeader(m, &unitsKnown);
  if (!unitsKnown) {
    Diagnostic d;
    d.severity = Severity::Warning;
    d.where = {m.file, 0, 0};
    d.subject = "UNITS";
    d.message = "the request-file units tag of " + m.units.description +
                " is not known; the .req header says " + h.unitsToken +
                " although the values are in the model's units";
    d.hint = "Post-processors must be told the units of this run.";
    diagnostic(d);
  }
  std::string err;
  if (!req_.open(requestFilePath(), h, output::requestEntries(m), &err)) {
    context().error(nullptr, "cannot write the request file: " + err, "");
    return false;
  }
  return true;
}

void Session::writeRequests(double t, const std::vector<std::array<double, 6>>& rows) {
  if (outputSuppressed_) return;  // CONSUB's ANALYS: DATOUT writes (control_command.cpp)
  req_.writeStep(t, rows);
}

bool Session::wantsFrames() const {
  return model_ && !options_.checkOnly && !outputSuppressed_ &&
         ((results_.enabled && !resFailed_) || (model_->output.grsave && !graFailed_));
}

// The .gra of OUTPUT/GRSAVE: opened at the first frame with the data set's drawn GRAPHICS.
bool Session::writeGraphicsFrame(const analysis::OutputFrame& frame) {
  if (!gra_.isOpen()) {
    const std::string path =
        (std::filesystem::path(options_.outputDirectory) / (prefix_ + ".gra")).string();
    Diagnostics checked;  // the model build reported them already
    const std::vector<model::Graphic> graphics = model::buildGraphics(dataset(), *model_, checked);
    std::string err;
    if (!gra_.open(path, output::requestFileHeader(*model_, nullptr), *model_, graphics, &err)) {
      graFailed_ = true;
      context().error(nullptr, err, "Check that the output directory is writable.");
      return false;
    }
  }
  std::vector<output::GraphicsPose> poses;
  for (const output::PartOutput& p : frame.parts) poses.push_back({p.position, p.angles});
  gra_.writeStep(frame.time, poses);
  if (gra_.error().empty()) return true;
  graFailed_ = true;
  context().error(nullptr, "graphics file: " + gra_.error(),
                  "The steps before this one are in it.");
  gra_.close();
  return false;
}

bool Session::writeFrame(const analysis::OutputFrame& frame) {
  if (model_->output.grsave && !graFailed_ && !writeGraphicsFrame(frame)) return false;
  if (!results_.enabled || resFailed_) return true;
  if (results_.formatted) return writeFormattedResults(frame);
  if (!res_.isOpen()) {
    output::ResultsFileHeader h;
    h.analysisName = prefix_;
    h.version = OPENMSS_VERSION;
    h.stamp = output::RequestFileHeader{}.stamp;  // the .req's fixed stamp (docs)
    std::string err;
    if (!res_.open(resultsFilePath(), *model_, results_, h, &err)) {
      resFailed_ = true;
      context().error(nullptr, err, "Check that the output directory is writable.");
      return false;
    }
    if (analysisFailed_) res_.markFailed();  // an earlier analysis failed before any step
  }
  if (res_.writeStep(frame)) return true;
  resFailed_ = true;
  context().error(nullptr, res_.error(), "The steps before this one are in the file.");
  res_.markFailed();
  res_.close();  // the .out and .gra stay open: reopening would truncate them
  return false;
}

bool Session::writeFormattedResults(const analysis::OutputFrame& frame) {
  if (!formattedRes_.isOpen()) {
    std::string err;
    if (!formattedRes_.open(resultsFilePath(), *model_, results_, prefix_, &err)) {
      resFailed_ = true;
      context().error(nullptr, err, "Check that the output directory is writable.");
      return false;
    }
  }
  if (formattedRes_.writeStep(frame)) return true;
  resFailed_ = true;
  context().error(nullptr, formattedRes_.error(), "The steps before this one are in the file.");
  formattedRes_.close();
  return false;
}

bool Session::wantsTabular() const {
  return model_ && !options_.checkOnly && !outputSuppressed_ && !model_->requests.empty() &&
         !results_.noPrint && !outFailed_;
}

bool Session::writeTabular(const analysis::OutputFrame& frame) {
  if (!out_.isOpen()) {
    std::string err;
    if (!out_.open(tabularFilePath(), *model_, &err)) {
      outFailed_ = true;
      context().error(nullptr, err, "Check that the output directory is writable.");
      return false;
    }
    if (analysisFailed_) out_.markFailed();  // an earlier analysis failed before any step
  }
  if (out_.writeStep(frame, *model_, results_)) return true;
  outFailed_ = true;
  context().error(nullptr, out_.error(), "The steps before this one's page are in the file.");
  out_.close();
  return false;
}

void Session::closeResults() {
  out_.close();
  formattedRes_.close();
  gra_.close();
  if (!res_.isOpen()) return;
  if (resFailed_) res_.markFailed();
  res_.close();
}

void Session::progressStart() { progressStart_ = progressLast_ = steadySeconds(); }

void Session::progress(double t, double t0, double end, long steps) {
  if (!options_.progress) return;
  const double now = steadySeconds();
  if (now - progressLast_ < 0.5 && t < end) return;
  progressLast_ = now;
  const double elapsed = now - progressStart_;
  const double frac = (t - t0) / (end - t0);
  const double eta = frac > 0 ? elapsed * (1.0 - frac) / frac : 0.0;
  std::fprintf(stderr, "\r  t = %.5g / %.5g   steps %ld   ETA %.1f s   ", t, end, steps, eta);
  std::fflush(stderr);
}

void Session::progressDone() {
  if (options_.progress) std::fprintf(stderr, "\n");
}

}  // namespace openmss::commands
