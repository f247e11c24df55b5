#include "model/user_constraint_builder.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "model/user_routine_binding.hpp"
#include "model/user_subroutine_arguments.hpp"
#include "user/ucon_routine.hpp"

namespace openmss::model {
namespace {

using language::Statement;

// 11..13 (CM x, y, z), 111..113, 211..213, 311..313 (axis components); docs/user-subroutines.md.
bool knownCode(int code) {
  if (code >= 11 && code <= 13) return true;
  const int axis = code / 100, rest = code % 100;
  return axis >= 1 && axis <= 3 && rest >= 11 && rest <= 13;
}

std::string codeAdvice(int code) {
  if ((code >= 14 && code <= 16) || (code >= 21 && code <= 26))
    return "Codes 14-16 (Euler angles of the principal axes) and 21-26 (velocities) of ADAMS/"
           "Solver (FORTRAN) are not supported: ADAMS permutes its internal Euler angles and "
           "velocity (non-holonomic) constraints are not supported yet. Use 11-13 (CM x, y, z) "
           "and 111..313 (the ground components of the part's x, y, z axes).";
  return "Use 11, 12, 13 (CM x, y, z in ground) or 100a+10+c with a, c = 1..3 (component c in "
         "ground of the part's axis a), docs/user-subroutines.md \"UCON\".";
}

// A marker of part `p` at its body frame (origin at the CM, CM-marker axes): its CM marker, or
// any marker placed exactly there. -1: none.
int bodyFrameMarker(const Model& model, int p) {
  for (int m = 0; m < static_cast<int>(model.markers.size()); ++m) {
    const Marker& mk = model.markers[m];
    if (mk.part == p && !mk.floating && mk.position.isZero(0.0) && mk.orientation.isIdentity(0.0))
      return m;
  }
  return -1;
}

// Whether UCOSUB reads TIME: F at the data set's configuration q0, at TIME = 0 and 1e-3, must
// be the same to the bit (docs/user-subroutines.md, "UCON": rheonomic UCONs are refused, as
// no time partials are asked of the routine). A value that is not finite is left to the run,
// which stops on it naming the routine.
bool dependsOnTime(const Model& model, const UserConstraint& u) {
  const int n = static_cast<int>(u.codes.size());
  double q[user::kMaxUconVariables] = {};
  for (int k = 0; k < n; ++k) {
    const Part& part = model.parts[model.markers[u.markers[k]].part];
    const int code = u.codes[k];
    q[k] = code < 100 ? part.position[code - 11] : part.orientation(code % 10 - 1, code / 100 - 1);
  }
  double f0 = 0.0, f1 = 0.0;
  u.user->evaluate(0.0, q, n, 0, &f0, nullptr, nullptr);
  u.user->evaluate(1e-3, q, n, 0, &f1, nullptr, nullptr);
  return std::isfinite(f0) && std::isfinite(f1) && f0 != f1;
}

void buildOne(const Statement& s, Model& model, Diagnostics& diags) {
  if (const language::Argument* v = s.find("VARIABLES")) {
    diags.error(v->where, s.subject(), "VARIABLES is not supported",
                "Remove it: UCOSUB declares the constraint's variables by calling UCOVAR "
                "when IFLAG = 3 (docs/user-subroutines.md, \"UCON\").");
    return;
  }
  const language::Argument* fn = s.find("FUNCTION");
  if (!fn) {
    diags.error(s.where, s.subject(), "FUNCTION is missing",
                "Give FUNCTION=USER(r1, ..., r30): the constants UCOSUB receives as PAR.");
    return;
  }
  const auto par = userParameters(s, diags);
  if (!par) return;
  user::ElementData element;
  element.subject = s.subject();
  element.id = *s.id;
  element.par = *par;
  element.data = userModelData(model);
  user::UconVariables declared;
  std::string error;
  UserConstraint u;
  u.id = *s.id;
  u.where = s.where;
  u.user = user::loadUserConstraintRoutine(element, elementRoutineName(s),
                                           userLibraryDirectory(model), declared, error);
  if (!u.user) {
    diags.error(fn->where, s.subject(), error,
                "Supply the library that defines UCOSUB (ROUTINE=lib::name on the statement, or "
                "openmss run --user-library LIB), and call UCOVAR from it when IFLAG = 3; "
                "docs/user-subroutines.md says how.");
    return;
  }
  std::vector<int> parts;
  bool ok = true;
  for (size_t k = 0; k < declared.codes.size(); ++k) {
    const int id = declared.parts[k], code = declared.codes[k];
    const std::string which = "UCOVAR's variable " + std::to_string(k + 1) + " (PART " +
                              std::to_string(id) + ", code " + std::to_string(code) + ")";
    const auto it = model.partIndex.find(id);
    if (it == model.partIndex.end() || model.parts[it->second].ground) {
      diags.error(fn->where, s.subject(), which + ": no moving PART has id " + std::to_string(id),
                  "Declare parts of this data set other than ground in UCOVAR's LPARTS.");
      ok = false;
      continue;
    }
    if (!knownCode(code)) {
      diags.error(fn->where, s.subject(),
                  which + ": code " + std::to_string(code) + " is not supported", codeAdvice(code));
      ok = false;
      continue;
    }
    const Part& part = model.parts[it->second];
    const Eigen::Matrix3d& j = part.inertia;
    if (code > 100 && (j(0, 1) != 0.0 || j(0, 2) != 0.0 || j(1, 2) != 0.0)) {
      diags.error(fn->where, s.subject(),
                  which + ": PART/" + std::to_string(id) +
                      " has products of inertia, so its principal axes (ADAMS's UCON axes) "
                      "are not its CM marker's",
                  "Orient the CM marker along the principal axes and give IP without products "
                  "of inertia, or use the CM codes 11-13 only.");
      ok = false;
      continue;
    }
    const int marker = bodyFrameMarker(model, it->second);
    if (marker < 0) {
      diags.error(fn->where, s.subject(),
                  which + ": PART/" + std::to_string(id) + " has no marker at its body frame",
                  "Give the PART a CM marker (CM=id).");
      ok = false;
      continue;
    }
    if (std::find(parts.begin(), parts.end(), it->second) == parts.end())
      parts.push_back(it->second);
    u.markers.push_back(marker);
    u.codes.push_back(code);
  }
  if (ok && static_cast<int>(parts.size()) > UserConstraint::kMaxParts) {
    diags.error(fn->where, s.subject(),
                "UCOVAR declares variables of " + std::to_string(parts.size()) + " parts",
                "A UCON may read at most " + std::to_string(UserConstraint::kMaxParts) +
                    " parts; split the constraint.");
    ok = false;
  }
  if (ok && dependsOnTime(model, u)) {
    diags.error(fn->where, s.subject(),
                "UCOSUB's value at the data set's configuration changes between TIME = 0 and "
                "TIME = 1e-3: a constraint depending on TIME explicitly is not supported yet",
                "Write the time-dependent part as a MOTION or a JPRIM/JOINT driven by one; a "
                "UCON must depend on the part variables only (docs/user-subroutines.md, "
                "\"UCON\").");
    ok = false;
  }
  if (ok) model.ucons.push_back(std::move(u));
}

}  // namespace

void buildUserConstraints(const std::vector<const Statement*>& statements, Model& model,
                          Diagnostics& diags) {
  for (const Statement* s : statements) {
    if (!s->id) continue;  // the reader reports a statement without an id
    buildOne(*s, model, diags);
  }
}

}  // namespace openmss::model
