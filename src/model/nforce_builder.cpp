// NFORCE (docs/theory.md §6b): a linear force among up to 350 I markers and J, its matrices
// from MATRIX statements: KMATRIX and CMATRIX 6n x 6n, LENGTH and FORCE 6n x 1 (n I markers),
// all in J's axes, the markers in IMARKERS order, each marker's six entries x, y, z, a, b, c.

#include <string>

#include "model/force_element_builder.hpp"
#include "model/part_builder.hpp"
#include "model/statement_arguments.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// MATRIX `name`= of s, checked to be rows x cols; nullptr after a diagnostic (or when absent).
const Eigen::MatrixXd* matrixArgument(const Statement& s, const char* name, int rows, int cols,
                                      const Model& model, Diagnostics& diags) {
  const Argument* a = s.find(name);
  if (!a || a->values.empty()) return nullptr;
  const long id = static_cast<long>(a->values[0].number);
  const auto it = model.matrixIndex.find(id);
  if (it == model.matrixIndex.end()) {
    diags.error(a->where, s.subject(),
                std::string(name) + "=" + std::to_string(id) + ": MATRIX/" + std::to_string(id) +
                    " does not exist",
                "Add a MATRIX statement with that id, or name an existing one.");
    return nullptr;
  }
  const Eigen::MatrixXd& m = model.matrices[static_cast<size_t>(it->second)].values;
  if (m.rows() != rows || m.cols() != cols) {
    diags.error(a->where, s.subject(),
                std::string(name) + ": MATRIX/" + std::to_string(id) + " is " +
                    std::to_string(m.rows()) + "x" + std::to_string(m.cols()) + " but must be " +
                    std::to_string(rows) + "x" + std::to_string(cols) + " (6 rows per I marker)",
                "Give a MATRIX of that size, markers in IMARKERS order.");
    return nullptr;
  }
  return &m;
}

}  // namespace

void buildNForce(const Statement& s, Model& model, Diagnostics& diags) {
  MultiPointForce f;
  f.id = *s.id;
  f.where = s.where;
  bool ok = true;
  if (const Argument* a = s.find("IMARKERS")) {
    for (const language::Value& v : a->values) {
      const long id = static_cast<long>(v.number);
      const auto it = model.markerIndex.find(id);
      if (it == model.markerIndex.end() || model.markers[it->second].floating) {
        diags.error(a->where, s.subject(),
                    "IMARKERS: marker " + std::to_string(id) +
                        (it == model.markerIndex.end() ? " does not exist" : " is FLOATING"),
                    "List fixed markers of this data set.");
        ok = false;
        continue;
      }
      f.iMarkers.push_back(it->second);
    }
  } else {
    diags.error(s.where, s.subject(), "missing required argument IMARKERS",
                "Add IMARKERS=id1,...,idn (the markers the force acts on besides J).");
    ok = false;
  }
  f.jMarker = markerReference(model, s, "J", diags);
  if (!s.has("KMATRIX"))
    diags.error(s.where, s.subject(), "missing required argument KMATRIX",
                "Add KMATRIX=<MATRIX id> (the 6n x 6n stiffness, n I markers).");
  if (s.has("CMATRIX") && s.has("CRATIO")) {
    diags.error(s.find("CRATIO")->where, s.subject(), "give CMATRIX or CRATIO, not both",
                "Keep CMATRIX (the damping matrix) or CRATIO (damping = CRATIO * stiffness).");
    ok = false;
  }
  if (!ok || f.jMarker < 0 || f.iMarkers.empty() || !s.has("KMATRIX")) return;
  const int n6 = 6 * static_cast<int>(f.iMarkers.size());
  const Eigen::MatrixXd* k = matrixArgument(s, "KMATRIX", n6, n6, model, diags);
  if (!k) return;
  f.stiffness = *k;
  f.damping = Eigen::MatrixXd::Zero(n6, n6);  // neither CMATRIX nor CRATIO: undamped
  if (s.has("CMATRIX")) {
    const Eigen::MatrixXd* c = matrixArgument(s, "CMATRIX", n6, n6, model, diags);
    if (!c) return;
    f.damping = *c;
  } else if (s.has("CRATIO")) {
    StatementArguments a(s, diags);
    const double ratio = a.real("CRATIO").value_or(0.0);
    if (ratio < 0.0) {
      a.error(*s.find("CRATIO"), "CRATIO must not be negative", "Give CRATIO >= 0.");
      return;
    }
    f.damping = ratio * f.stiffness;
  }
  // LENGTH absent: zero (the reference gives no default; FORCE's documented default is zero).
  f.length = Eigen::VectorXd::Zero(n6);
  f.preload = Eigen::VectorXd::Zero(n6);
  if (s.has("LENGTH")) {
    const Eigen::MatrixXd* l = matrixArgument(s, "LENGTH", n6, 1, model, diags);
    if (!l) return;
    f.length = l->col(0);
  }
  if (s.has("FORCE")) {
    const Eigen::MatrixXd* p = matrixArgument(s, "FORCE", n6, 1, model, diags);
    if (!p) return;
    f.preload = p->col(0);
  }
  for (int i : f.iMarkers)
    if (model.markers[i].part == model.markers[f.jMarker].part)
      diags.warning(s.where, s.subject(),
                    "an I marker is on J's part: its force and reaction cancel",
                    "List markers of the other parts in IMARKERS.");
  model.nforces.push_back(std::move(f));
}

}  // namespace openmss::model
