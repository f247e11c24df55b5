// Session: the commands that change the model's elements: ACTIVATE, DEACTIVATE and the
// commands that redefine a statement of the same name (SFORCE/id, FUNCTION=..., ACCGRAV/ ...,
// PART/id, MASS=...). They are recorded as ModelEdits over the Dataset (model_edits.hpp); the
// next analysis builds the model again from both and starts from the last state
// (state_carry_over.hpp; docs/commands.md, "How commands change the model").

#include <algorithm>
#include <set>

#include "analysis/model_summary.hpp"
#include "commands/session.hpp"
#include "commands/state_carry_over.hpp"
#include "model/model_builder.hpp"

namespace openmss::commands {
namespace {

// Elements ACTIVATE and DEACTIVATE switch (the command table's flags, language/command_table.cpp).
const std::vector<std::string>& switchableKinds() {
  static const std::vector<std::string> k = {
      "BEAM",     "BUSHING", "CONTACT",  "CLEARANCE", "COUPLER", "CVCV",   "DIFF",   "FIELD",
      "FRICTION", "GCON",    "GEAR",     "GFORCE",    "GSE",     "JOINT",  "JPRIM",  "LSE",
      "MFORCE",   "MOTION",  "NFORCE",   "PTCV",      "REQUEST", "SENSOR", "SFORCE", "SPRINGDAMPER",
      "TFSISO",   "UCON",    "VARIABLE", "VFORCE",    "VTORQUE"};
  return k;
}

// The arguments a redefining command may change, where the command form allows fewer than the
// statement: a PART keeps its place and a MARKER its part, a JOINT its markers and type (the
// ADAMS/Solver commands PART, MARKER and JOINT; docs/commands.md).
const std::vector<std::string>* redefinableArguments(const std::string& kind) {
  static const std::vector<std::string> part = {"MASS", "IP", "CM", "LIST"};
  static const std::vector<std::string> marker = {"QP", "REULER", "XP", "ZP", "USEXP", "LIST"};
  static const std::vector<std::string> joint = {"IC", "ICTRAN", "ICROT", "LIST"};
  if (kind == "PART") return &part;
  if (kind == "MARKER") return &marker;
  if (kind == "JOINT") return &joint;
  return nullptr;
}

// A statement written back in the data-set language, for LIST.
std::string statementText(const language::Statement& s) {
  std::string out = " " + s.subject();
  bool first = true;
  for (const auto& a : s.args) {
    out += first && !s.id ? "" : ",";
    out += " " + a.name;
    first = false;
    if (a.isExpression) {
      out += "=" + a.expression;
      continue;
    }
    for (size_t k = 0; k < a.values.size(); ++k)
      out += (k == 0 ? "=" : std::string(1, a.separators.size() >= k ? a.separators[k - 1] : ',')) +
             a.values[k].text;
  }
  return out;
}

std::string where(const SourceLocation& w) { return w.file + ":" + std::to_string(w.line); }

}  // namespace

bool Session::isElementCommand(const std::string& name) {
  static const std::set<std::string> s = {
      "ACTIVATE", "DEACTIVATE", "PART",   "MARKER",   "JOINT",  "MOTION",       "GCON",   "ACCGRAV",
      "BEAM",     "BUSHING",    "FIELD",  "GFORCE",   "SFORCE", "SPRINGDAMPER", "VFORCE", "VTORQUE",
      "ARRAY",    "SPLINE",     "STRING", "VARIABLE", "DIFF",   "SENSOR",       "REQUEST"};
  return s.count(name) > 0;
}

bool Session::elementCommand(const language::Statement& c) {
  if (c.name == "ACTIVATE" || c.name == "DEACTIVATE") return switchElements(c);
  return redefine(c);
}

bool Session::switchElements(const language::Statement& c) {
  const bool activate = c.name == "ACTIVATE";
  std::vector<std::string> kinds;
  for (const auto& k : switchableKinds())
    if (c.has(k)) kinds.push_back(k);
  if (kinds.size() != 1) {
    error(c, kinds.empty() ? "the kind of element is missing" : "one kind of element per command",
          "Write e.g. " + c.name + "/JOINT, ID=12 or " + c.name + "/SFORCE, RANGE=1,9.");
    return false;
  }
  const std::string& kind = kinds[0];
  const language::Argument* ids = c.find("ID");
  const language::Argument* range = c.find("RANGE");
  if ((ids != nullptr) == (range != nullptr)) {
    error(c, ids ? "ID and RANGE exclude each other" : "the elements are missing",
          "Give ID=id[,id...] or RANGE=first,last.");
    return false;
  }
  const std::vector<long> present = statementIds(dataset(), kind);
  std::vector<long> chosen;
  if (ids) {
    for (const auto& v : ids->values) {
      const long id = static_cast<long>(v.number);
      if (std::find(present.begin(), present.end(), id) == present.end()) {
        Diagnostic d;
        d.where = v.where;
        d.subject = c.subject();
        d.message = kind + "/" + std::to_string(id) + " does not exist in the data set";
        d.hint = "Check the id; nothing was " +
                 std::string(activate ? "activated" : "deactivated") + ".";
        diagnostic(d);
        return false;
      }
      chosen.push_back(id);
    }
  } else {
    const long lo = static_cast<long>(range->values[0].number);
    const long hi = static_cast<long>(range->values[1].number);
    for (long id : present)
      if (id >= lo && id <= hi) chosen.push_back(id);
    if (chosen.empty()) {
      error(c, "no " + kind + " has an id from " + std::to_string(lo) + " to " + std::to_string(hi),
            "Check the range; nothing was changed.");
      return false;
    }
  }
  if (kind == "REQUEST" && req_.isOpen()) {
    error(c, "the request file is already written with every REQUEST as a column",
          "Switch REQUESTs before the first output step (a .req keeps its columns).");
    return false;
  }
  ModelEdits next = pendingEdits_;
  for (long id : chosen) {
    if (activate)
      next.inactive.erase({kind, id});
    else
      next.inactive.insert({kind, id});
  }
  // Switching elements to the state they are in changes nothing: no reprocessing follows.
  if (next.inactive == pendingEdits_.inactive) return true;
  return acceptEdits(c, next);
}

bool Session::redefine(const language::Statement& c) {
  const bool needsId = !isSingletonStatement(c.name);
  if (needsId && !c.id) {
    error(c, c.name + " needs the id of the statement it redefines",
          "Write " + c.name + "/id, followed by the arguments to change.");
    return false;
  }
  if (const auto* allowed = redefinableArguments(c.name))
    for (const auto& a : c.args)
      if (std::find(allowed->begin(), allowed->end(), a.name) == allowed->end()) {
        Diagnostic d;
        d.where = a.where;
        d.subject = c.subject();
        d.message = a.name + " cannot be changed by the " + c.name + " command";
        std::string list;
        for (const auto& n : *allowed) list += (list.empty() ? "" : ", ") + n;
        d.hint = "The command changes " + list + "; nothing was changed.";
        diagnostic(d);
        return false;
      }
  if (needsId) {
    const auto ids = statementIds(dataset(), c.name);
    if (std::find(ids.begin(), ids.end(), *c.id) == ids.end()) {
      error(c, c.subject() + " does not exist in the data set",
            "A command changes a statement of the data set; nothing was changed.");
      return false;
    }
  }
  const bool onlyList = std::all_of(c.args.begin(), c.args.end(),
                                    [](const language::Argument& a) { return a.name == "LIST"; });
  if (!onlyList) {
    ModelEdits next = pendingEdits_;
    next.redefinitions.push_back(c);
    if (!acceptEdits(c, next)) return false;
  }
  if (c.has("LIST")) {
    // Listed as redefined even while deactivated (the listing then says so).
    ModelEdits listing = pendingEdits_;
    const bool inactive = listing.inactive.erase({c.name, c.id.value_or(0)}) > 0;
    const language::Dataset edited = editedDataset(dataset(), listing);
    bool listed = false;
    for (const auto& s : edited.statements)
      if (s.name == c.name && s.id.value_or(0) == c.id.value_or(0)) {
        msg_.line(statementText(s));
        listed = true;
      }
    if (!listed) msg_.line(" " + c.subject() + ": not in the data set (defaults apply)");
    if (inactive) msg_.line(" " + c.subject() + " is deactivated");
  }
  return true;
}

// A trial build of the data set with `next` over it. Errors at the command's own arguments
// (an expression that does not parse, a value out of range) reject the command; errors in the
// relations between elements (a MOTION on a deactivated JOINT) may be mended by a later
// command and are reported by the next analysis (applyEdits).
bool Session::acceptEdits(const language::Statement& c, const ModelEdits& next) {
  Diagnostics local;
  model::Model trial;
  model::buildModel(editedDataset(dataset(), next), trial, local);
  Diagnostics own;
  for (const auto& d : local.all())
    if (d.severity == Severity::Error && d.where.file == c.where.file) own.add(d);
  if (own.hasErrors()) {
    reportAll(own);
    return false;
  }
  pendingEdits_ = next;
  editsPending_ = true;
  return true;
}

bool Session::applyEdits(const language::Statement& c) {
  if (!editsPending_) return true;
  Diagnostics local;
  auto m = std::make_unique<model::Model>();
  model::buildModel(editedDataset(dataset(), pendingEdits_), *m, local);
  if (local.hasErrors()) {
    const Diagnostic* first = nullptr;
    for (const auto& d : local.all())
      if (d.severity == Severity::Error) {
        first = &d;
        break;
      }
    error(c,
          "the model changed by the commands since the last analysis does not build: " +
              first->subject + " (" + where(first->where) + "): " + first->message,
          "Those commands are withdrawn (ACTIVATE, DEACTIVATE, redefinitions); " + first->hint);
    pendingEdits_ = appliedEdits_;
    editsPending_ = false;
    return false;
  }
  // Settings the commands own (INTEGRATOR, EQUILIBRIUM, IC, KINEMATICS, OUTPUT, DEBUG) stay.
  m->integrator = model_->integrator;
  m->equilibrium = model_->equilibrium;
  m->initialConditions = model_->initialConditions;
  m->kinematics = model_->kinematics;
  m->output = model_->output;
  m->debug = model_->debug;
  std::vector<long> oldRequests, newRequests;
  for (const auto& r : model_->requests) oldRequests.push_back(r.id);
  for (const auto& r : m->requests) newRequests.push_back(r.id);
  if (req_.isOpen() && oldRequests != newRequests) {
    error(c, "the request file is already written with other REQUESTs as columns",
          "Switch REQUESTs before the first output step; the commands are withdrawn.");
    pendingEdits_ = appliedEdits_;
    editsPending_ = false;
    return false;
  }
  auto sys = std::make_unique<mechanics::MultibodySystem>(*m);
  auto st = std::make_unique<analysis::RunState>(*sys);
  carryOverState(*system_, *state_, *sys, *st);
  const analysis::DegreeOfFreedomCount dof = analysis::countDegreesOfFreedom(*sys, st->y);
  st->degreesOfFreedom = dof.degreesOfFreedom;
  st->grueblerCount = dof.gruebler;
  state_ = std::move(st);
  system_ = std::move(sys);
  model_ = std::move(m);
  appliedEdits_ = pendingEdits_;
  editsPending_ = false;
  msg_.line("");
  msg_.line(" The model is reprocessed (ACTIVATE, DEACTIVATE or redefined statements) at time " +
            analysis::formatNumber("%g", state_->t) + ":");
  reportModelSummary(dof);
  return true;
}

}  // namespace openmss::commands
