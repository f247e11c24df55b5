#include "model/user_coupler_binding.hpp"

#include "model/user_routine_binding.hpp"
#include "model/user_subroutine_arguments.hpp"
#include "user/coupler_routine.hpp"

namespace openmss::model {

bool bindUserCoupler(const language::Statement& s, const Model& model, Coupler& c,
                     Diagnostics& diags) {
  const auto par = userParameters(s, diags);
  if (!par) return false;
  user::CouplerDescription d;
  d.element.subject = s.subject();
  d.element.id = s.id ? *s.id : 0;
  d.element.par = *par;
  d.element.data = userModelData(model);
  d.count = static_cast<int>(c.joints.size());
  for (int k = 0; k < d.count; ++k) {
    d.joints[k] = static_cast<int>(model.joints[static_cast<size_t>(c.joints[k])].id);
    d.types[k] = c.rotation[static_cast<size_t>(k)] ? 'R' : 'T';
  }
  // No ROUTINE, or ROUTINE=lib::: the three routines under their default names, COUXX and
  // COUXX2 optional. ROUTINE=lib::cousub names COUSUB alone: its partials come from central
  // differences (a library's default Couxx belongs to its default Cousub, not to this one).
  // Three values name the three routines, each then required.
  user::RoutineName names[3];
  bool explicitly[3] = {false, false, false};
  bool partialRoutines = true;
  if (const language::Argument* r = s.find("ROUTINE")) {
    if (r->values.size() == 2) {
      diags.error(r->valueWhere, s.subject(), "ROUTINE has 2 values",
                  "Give ROUTINE=lib::cousub (COUXX and COUXX2 by their default names from the "
                  "same library) or ROUTINE=lib::cousub, lib::couxx, lib::couxx2.");
      return false;
    }
    for (size_t k = 0; k < r->values.size() && k < 3; ++k) {
      const auto& v = r->values[k];
      names[k] = user::splitRoutineName(v.written.empty() ? v.text : v.written);
      explicitly[k] = k > 0;
    }
    if (r->values.size() == 1) {
      names[1].library = names[2].library = names[0].library;
      partialRoutines = names[0].name.empty();
    }
  }
  std::string error;
  c.user = user::loadCouplerRoutine(d, names, explicitly, partialRoutines,
                                    userLibraryDirectory(model), error);
  if (!c.user) {
    diags.error(s.find("FUNCTION")->where, s.subject(), error,
                "Supply the library that defines COUSUB (ROUTINE=lib::name on the statement, or "
                "openmss run --user-library LIB); docs/user-subroutines.md says how to build one.");
    return false;
  }
  return true;
}

}  // namespace openmss::model
