// LSE and TFSISO statements (docs/theory.md §4a): the linear state equations x' = A x + B u,
// y = C x + D u with their X, U, Y and IC arrays; a TFSISO becomes its controllable canonical
// form.

#include <string>

#include "model/user_equation_context.hpp"

namespace openmss::model {

using language::Argument;
using language::Statement;

void UserEquationBuilder::lse(const Statement& s) {
  LinearStateElement e;
  e.id = *s.id;
  e.where = s.where;
  e.kind = LinearStateElement::Kind::Lse;
  e.staticHold = s.has("STATIC_HOLD");
  bool ok = true;
  e.xArray = arrayRef(s, "X", DataArray::Kind::X, true, ok);
  const Eigen::MatrixXd* a = matrixRef(s, "A", true, ok);
  const bool hasB = s.has("B"), hasU = s.has("U"), hasC = s.has("C"), hasY = s.has("Y");
  if (hasB != hasU) {
    diags_.error(s.where, s.subject(), "B and U go together",
                 hasB ? "Add U=<id of an ARRAY/U> (the inputs B multiplies)."
                      : "Add B=<id of a MATRIX> (the input matrix).");
    ok = false;
  }
  if (hasC != hasY || (s.has("D") && !hasY)) {
    diags_.error(s.where, s.subject(), "C (or D) and Y go together",
                 hasY ? "Add C=<id of a MATRIX> (the output matrix)."
                      : "Add Y=<id of an ARRAY/Y> (the outputs).");
    ok = false;
  }
  if (s.has("D") && !hasU) {
    diags_.error(s.find("D")->where, s.subject(), "D needs inputs",
                 "Add U=<id of an ARRAY/U> and B=, or remove D.");
    ok = false;
  }
  e.uArray = arrayRef(s, "U", DataArray::Kind::U, false, ok);
  e.yArray = arrayRef(s, "Y", DataArray::Kind::Y, false, ok);
  const int icArray = arrayRef(s, "IC", DataArray::Kind::IC, false, ok);
  const Eigen::MatrixXd* b = matrixRef(s, "B", false, ok);
  const Eigen::MatrixXd* c = matrixRef(s, "C", false, ok);
  const Eigen::MatrixXd* d = matrixRef(s, "D", false, ok);
  if (!ok || !a) return;
  const Eigen::Index n = a->rows();
  if (!shape(s, "A", *a, n, n, "A is square")) return;
  if (!claimSize(s, "X", e.xArray, n)) return;
  e.a = *a;
  const Eigen::Index nu = e.uArray >= 0 ? model_.arrays[e.uArray].size : 0;
  e.b = Eigen::MatrixXd::Zero(n, nu);
  if (b) {
    if (!shape(s, "B", *b, n, nu, "states x inputs")) return;
    e.b = *b;
  }
  Eigen::Index ny = c ? c->rows() : (d ? d->rows() : 0);
  if (e.yArray >= 0 && model_.arrays[e.yArray].size >= 0) ny = model_.arrays[e.yArray].size;
  e.c = Eigen::MatrixXd::Zero(ny, n);
  e.d = Eigen::MatrixXd::Zero(ny, nu);
  if (c) {
    if (!shape(s, "C", *c, ny, n, "outputs x states")) return;
    e.c = *c;
  }
  if (d) {
    if (!shape(s, "D", *d, ny, nu, "outputs x inputs")) return;
    e.d = *d;
  }
  if (e.yArray >= 0 && !claimSize(s, "Y", e.yArray, ny)) return;
  e.ic = Eigen::VectorXd::Zero(n);
  if (icArray >= 0) {
    const DataArray& ic = model_.arrays[icArray];
    if (ic.size != n) {
      diags_.error(s.find("IC")->where, s.subject(),
                   "ARRAY/" + std::to_string(ic.id) + " has " + std::to_string(ic.size) +
                       " numbers; the LSE has " + std::to_string(n) + " states",
                   "Give one initial value per state.");
      return;
    }
    for (Eigen::Index i = 0; i < n; ++i) e.ic(i) = ic.numbers[static_cast<size_t>(i)];
  }
  add(e);
}

void UserEquationBuilder::tfsiso(const Statement& s) {
  LinearStateElement e;
  e.id = *s.id;
  e.where = s.where;
  e.kind = LinearStateElement::Kind::Tfsiso;
  e.staticHold = s.has("STATIC_HOLD");
  bool ok = true;
  e.xArray = arrayRef(s, "X", DataArray::Kind::X, true, ok);
  e.uArray = arrayRef(s, "U", DataArray::Kind::U, true, ok);
  e.yArray = arrayRef(s, "Y", DataArray::Kind::Y, true, ok);
  const Argument* num = s.find("NUMERATOR");
  const Argument* den = s.find("DENOMINATOR");
  for (const char* name : {"NUMERATOR", "DENOMINATOR"})
    if (!s.has(name)) {
      diags_.error(s.where, s.subject(), std::string("missing required argument ") + name,
                   std::string("Add ") + name + "=c0,c1,... (ascending powers of s).");
      ok = false;
    }
  if (!num || !den) return;
  std::vector<double> bn = numbersOf(*num), an = numbersOf(*den);
  if (an.size() < 2) {
    diags_.error(den->where, s.subject(),
                 "the DENOMINATOR must be at least of degree 1 (two coefficients)",
                 "A pure gain needs no TFSISO: multiply the input VARIABLE instead.");
    ok = false;
  } else if (an.back() == 0.0) {
    diags_.error(den->where, s.subject(),
                 "the last DENOMINATOR coefficient (highest power of s) is zero",
                 "Drop trailing zero coefficients: the degree is that of the last nonzero one.");
    ok = false;
  }
  if (bn.size() > an.size()) {
    diags_.error(num->where, s.subject(),
                 "the NUMERATOR has more coefficients than the DENOMINATOR (improper transfer "
                 "function)",
                 "Give at most " + std::to_string(an.size()) + " numerator coefficients.");
    ok = false;
  }
  if (e.uArray >= 0 && model_.arrays[e.uArray].size != 1) {
    diags_.error(s.find("U")->where, s.subject(), "the U array of a TFSISO must hold one VARIABLE",
                 "Name an ARRAY/U with VARIABLES=<one id>.");
    ok = false;
  }
  if (!ok) return;
  // Controllable canonical form of H(s) = (b0 + ... + bn s^n) / (a0 + ... + an s^n):
  // x_i' = x_{i+1}, x_n' = u - sum a_i/a_n x_{i+1}; y = sum (b_i - b_n a_i) / a_n x_{i+1}
  // + b_n/a_n u.
  const Eigen::Index n = static_cast<Eigen::Index>(an.size()) - 1;
  const double lead = an.back();
  bn.resize(an.size(), 0.0);
  e.a = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i + 1 < n; ++i) e.a(i, i + 1) = 1.0;
  for (Eigen::Index i = 0; i < n; ++i) e.a(n - 1, i) = -an[static_cast<size_t>(i)] / lead;
  e.b = Eigen::MatrixXd::Zero(n, 1);
  e.b(n - 1, 0) = 1.0;
  const double bLead = bn[static_cast<size_t>(n)] / lead;
  e.c = Eigen::MatrixXd::Zero(1, n);
  for (Eigen::Index i = 0; i < n; ++i)
    e.c(0, i) = bn[static_cast<size_t>(i)] / lead - bLead * an[static_cast<size_t>(i)] / lead;
  e.d = Eigen::MatrixXd::Constant(1, 1, bLead);
  e.ic = Eigen::VectorXd::Zero(n);
  if (!claimSize(s, "X", e.xArray, n) || !claimSize(s, "Y", e.yArray, 1)) return;
  add(e);
}

void UserEquationBuilder::add(LinearStateElement& e) {
  for (const auto& o : model_.linearStates)
    if (o.id == e.id && o.kind == e.kind) return;
  const int index = toInt(model_.linearStates.size());
  model_.arrays[e.xArray].owner = index;
  if (e.yArray >= 0) model_.arrays[e.yArray].owner = index;
  model_.linearStates.push_back(e);
}

}  // namespace openmss::model
