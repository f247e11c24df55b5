#include "expr/expression.hpp"

#include <utility>

#include "expr/compiler.hpp"
#include "expr/parser.hpp"
#include "expr/program.hpp"
#include "expr/user_function.hpp"

namespace openmss::expr {
namespace {

// The DELAY nodes of a tree by their delayIndex.
void collectDelays(const SyntaxNode& node, std::vector<const SyntaxNode*>& out) {
  if (node.kind == NodeKind::Delay) {
    if (out.size() <= node.delayIndex) out.resize(node.delayIndex + 1, nullptr);
    out[node.delayIndex] = &node;
  }
  for (const SyntaxNode& child : node.children) collectDelays(child, out);
}

}  // namespace

Expression::Expression() = default;
Expression::~Expression() = default;
Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;

Expression::Expression(const Expression& other)
    : program_(other.program_ ? std::make_unique<Program>(*other.program_) : nullptr) {}

Expression& Expression::operator=(const Expression& other) {
  if (this != &other) {
    program_ = other.program_ ? std::make_unique<Program>(*other.program_) : nullptr;
  }
  return *this;
}

bool Expression::parse(const std::string& text, const SourceLocation& where,
                       const std::string& subject, Diagnostics& diags, Expression& out) {
  ParseResult parsed = parseExpression(text);
  if (!parsed.ok()) {
    for (const ExpressionError& error : parsed.errors) {
      SourceLocation at = where;
      // The file column is exact when the expression's text starts at where.column and sits
      // on one line, which is how data-set readers hand expressions over.
      if (where.column > 0) at.column = where.column + error.column - 1;
      diags.error(at, subject, error.message, error.hint);
    }
    return false;
  }
  const std::size_t hostCount = parsed.hostCalls.size();
  std::vector<const SyntaxNode*> delayNodes;
  collectDelays(parsed.root, delayNodes);
  std::vector<Program::DelayCall> delays;
  for (const SyntaxNode* node : delayNodes) {
    // e_delayed over the whole expression's host values; e_history over TIME alone.
    delays.push_back({std::make_shared<const Program>(text, parsed.hostCalls,
                                                      compileProgram(node->children[0], hostCount)),
                      std::make_shared<const Program>(text, std::vector<HostCall>{},
                                                      compileProgram(node->children[2], 0))});
  }
  out.program_ = std::make_unique<Program>(text, std::move(parsed.hostCalls),
                                           compileProgram(parsed.root, hostCount));
  out.program_->setDelayCalls(std::move(delays));
  out.program_->setDataCalls(std::move(parsed.dataCalls));
  if (parsed.user) out.program_->setUserCall(std::move(*parsed.user));
  return true;
}

void bindUserFunction(Expression& e, std::shared_ptr<const UserFunction> f,
                      std::vector<HostCall> dependencies) {
  if (!e.userCall()) return;
  e.program_->bindUser(std::move(f), std::move(dependencies));
}

const std::string& Expression::text() const {
  static const std::string kEmpty;
  return program_ ? program_->text() : kEmpty;
}

const std::vector<HostCall>& Expression::hostCalls() const {
  static const std::vector<HostCall> kNone;
  return program_ ? program_->hostCalls() : kNone;
}

bool Expression::dependsOnTime() const { return program_ && program_->dependsOnTime(); }

const std::vector<DataCall>& Expression::dataCalls() const {
  static const std::vector<DataCall> kNone;
  return program_ ? program_->dataCalls() : kNone;
}

void Expression::bindSpline(std::size_t call, std::shared_ptr<const Spline> spline) {
  if (program_) program_->bindSpline(call, std::move(spline));
}

void Expression::bindCurve(std::size_t call, std::shared_ptr<const BSplineCurve> curve) {
  if (program_) program_->bindCurve(call, std::move(curve));
}

const UserCall* Expression::userCall() const {
  return program_ ? program_->userCall() : nullptr;
}

double Expression::evaluate(const double* hostValues, double time, const RunContext* run) const {
  return program_ ? program_->evaluate(hostValues, time, run) : 0.0;
}

double Expression::evaluate(const double* hostValues, double time, double* dHost, double* dTime,
                            const RunContext* run) const {
  if (!program_) {
    if (dTime != nullptr) *dTime = 0.0;
    return 0.0;
  }
  return program_->evaluate(hostValues, time, dHost, dTime, run);
}

std::size_t Expression::delayCount() const {
  return program_ ? program_->delayCalls().size() : 0;
}

const void* Expression::delayKey(std::size_t k) const {
  return program_->delayCalls().at(k).delayed.get();
}

double Expression::delayArgument(std::size_t k, const double* hostValues, double time) const {
  return program_->delayCalls().at(k).delayed->evaluate(hostValues, time);
}

TimeJet Expression::evaluateTimeJet(double time) const {
  return program_ ? program_->evaluateTimeJet(time) : TimeJet{};
}

TimeJet Expression::evaluateJet(const TimeJet* hostJets, double time) const {
  return program_ ? program_->evaluateJet(hostJets, time) : TimeJet{};
}

}  // namespace openmss::expr
