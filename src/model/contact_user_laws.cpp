#include "model/contact_user_laws.hpp"

#include "model/user_routine_binding.hpp"
#include "model/user_subroutine_arguments.hpp"
#include "user/contact_routines.hpp"

namespace openmss::model {
namespace {

// NORMAL (CNFSUB) or FRICTION (CFFSUB): the routine of `function`/`routine` into out.
template <class Routine, class Loader>
bool bindOne(const language::Statement& s, const Model& model, const Contact& c,
             const char* function, const char* routine, const char* adamsName, Diagnostics& diags,
             std::shared_ptr<const Routine>& out, const Loader& load) {
  const auto par = userParameters(s, diags, function);
  if (!par) return false;
  user::ContactElementData e;
  e.element.subject = s.subject();
  e.element.id = c.id;
  e.element.par = *par;
  e.element.data = userModelData(model);
  for (const ContactSolid& x : c.iSolids) e.igeom.push_back(static_cast<int>(x.graphicsId));
  for (const ContactSolid& x : c.jSolids) e.jgeom.push_back(static_cast<int>(x.graphicsId));
  std::string error;
  out = load(e, elementRoutineName(s, routine), userLibraryDirectory(model), error);
  if (out) return true;
  diags.error(s.find(function)->where, s.subject(), error,
              std::string("Supply the library that defines ") + adamsName + " (" + routine +
                  "=lib::name on the statement, or openmss run --user-library LIB); "
                  "docs/user-subroutines.md says how to build one.");
  return false;
}

}  // namespace

bool bindContactUserLaws(const language::Statement& s, const Model& model, Contact& c,
                         Diagnostics& diags) {
  bool ok = true;
  if (s.has("NORMAL_FUNCTION"))
    ok = bindOne(s, model, c, "NORMAL_FUNCTION", "NORMAL_ROUTINE", "CNFSUB", diags, c.normalRoutine,
                 user::loadContactNormalRoutine) &&
         ok;
  if (s.has("FRICTION_FUNCTION"))
    ok = bindOne(s, model, c, "FRICTION_FUNCTION", "FRICTION_ROUTINE", "CFFSUB", diags,
                 c.frictionRoutine, user::loadContactFrictionRoutine) &&
         ok;
  return ok;
}

}  // namespace openmss::model
