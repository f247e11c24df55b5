#include "model/material_builder.hpp"

#include <set>
#include <string>

#include "model/statement_arguments.hpp"

namespace openmss::model {
namespace {

// Young's modulus and density are positive and Poisson's ratio lies in (-1, 0.5) for every
// isotropic elastic solid (the bounds of a positive-definite elasticity tensor).
void checkProperties(StatementArguments& a, Material& m) {
  m.density = a.real("DENSITY");
  m.youngsModulus = a.real("YOUNGS_MODULUS");
  m.poissonsRatio = a.real("POISSONS_RATIO");
  if (m.density && !(*m.density > 0.0))
    a.error(*a.find("DENSITY"), "DENSITY must be positive", "Give DENSITY=<value> > 0.");
  if (m.youngsModulus && !(*m.youngsModulus > 0.0))
    a.error(*a.find("YOUNGS_MODULUS"), "YOUNGS_MODULUS must be positive",
            "Give YOUNGS_MODULUS=<value> > 0.");
  if (m.poissonsRatio && !(*m.poissonsRatio > -1.0 && *m.poissonsRatio < 0.5))
    a.error(*a.find("POISSONS_RATIO"), "POISSONS_RATIO must lie between -1 and 0.5",
            "Give the ratio of an isotropic solid (steel 0.29, rubber close to 0.5).");
}

}  // namespace

std::vector<Material> readMaterials(const language::Dataset& dataset, Diagnostics& diags) {
  std::vector<Material> materials;
  std::set<long> ids;
  for (const language::Statement& s : dataset.statements) {
    if (s.name != "MATERIAL" || !s.id || !ids.insert(*s.id).second) continue;
    StatementArguments a(s, diags);
    Material m;
    m.id = *s.id;
    m.where = s.where;
    m.name = a.word("NAME").value_or("");
    checkProperties(a, m);
    materials.push_back(m);
  }
  for (const language::Statement& s : dataset.statements) {
    if (s.name != "PART") continue;
    const language::Argument* ref = s.find("MATERIAL");
    if (!ref || ref->values.empty()) continue;
    const language::Value& v = ref->values[0];
    bool found = false;
    for (const Material& m : materials)
      found = found || (!m.name.empty() && m.name == v.text) ||
              (v.kind == language::Value::Kind::Number && v.number == static_cast<double>(m.id));
    // A warning: the reference has no effect on a rigid part, so nothing is lost.
    if (!found)
      diags.warning(ref->where, s.subject(),
                    "MATERIAL=" + v.text +
                        " names no MATERIAL statement; it has no effect (the "
                        "part's mass and inertia come from MASS and IP)",
                    "Add MATERIAL/<id>, NAME=" + v.text + ", or remove MATERIAL=.");
  }
  return materials;
}

}  // namespace openmss::model
