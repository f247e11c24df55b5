#include "output/results_layout.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

#include "common/ascii_case.hpp"

namespace openmss::output {
namespace {

// Adds components and entities, numbering ids in the order of the calls.
class Builder {
 public:
  explicit Builder(ResultsLayout& l) : l_(l) {}

  int entity(std::string name, std::string entity, std::string entType, long objectId) {
    ResultsEntity e;
    e.name = std::move(name);
    e.entity = std::move(entity);
    e.entType = std::move(entType);
    e.objectId = objectId;
    l_.entities.push_back(std::move(e));
    return static_cast<int>(l_.entities.size()) - 1;
  }
  void newGroup() { ++group_; }
  void add(int entity, std::string name, std::string units,
           std::function<double(const OutputFrame&)> value) {
    ResultsComponent c;
    c.name = std::move(name);
    c.units = std::move(units);
    c.entity = entity;
    c.group = group_;
    c.value = std::move(value);
    l_.entities[entity].components.push_back(static_cast<int>(l_.components.size()));
    l_.components.push_back(std::move(c));
  }

 private:
  ResultsLayout& l_;
  int group_ = 0;
};

using Vec3Of = Eigen::Vector3d PartOutput::*;

// Three components of one part vector (X Y Z, VX VY VZ, ...).
void addVector(Builder& b, int entity, std::size_t part, Vec3Of member, const char* const names[3],
               const std::string& units) {
  for (int k = 0; k < 3; ++k)
    b.add(entity, names[k], units,
          [part, member, k](const OutputFrame& f) { return (f.parts[part].*member)(k); });
}

using ForceList = std::vector<ElementForceOutput> OutputFrame::*;

// FX FY FZ TX TY TZ of each element of one list, one entity and one line each.
template <class Element, class Namer>
void addForces(Builder& b, const std::vector<Element>& elements, ForceList list, Namer&& namer,
               const ResultsUnits& u) {
  static const char* const names[6] = {"FX", "FY", "FZ", "TX", "TY", "TZ"};
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto [name, type] = namer(elements[e]);
    const int ent = b.entity(name, name, type, elements[e].id);
    b.newGroup();
    for (int k = 0; k < 6; ++k)
      b.add(ent, names[k], k < 3 ? u.force : u.force + "-" + u.length,
            [list, e, k](const OutputFrame& f) {
              const ElementForceOutput& o = (f.*list)[e];
              return k < 3 ? o.force(k) : o.torque(k - 3);
            });
  }
}

std::pair<std::string, std::string> named(const std::string& prefix, long id,
                                          const std::string& type) {
  return {prefix + "_" + std::to_string(id), type};
}

// unitsValue of request column c (0..7) of a request kind.
std::string requestUnits(model::Request::Kind kind, int c, const ResultsUnits& u) {
  using K = model::Request::Kind;
  const bool lin = c < 4;
  switch (kind) {
    case K::Displacement:
      return lin ? u.length : u.angle;
    case K::Velocity:
      return (lin ? u.length : u.angle) + "/" + u.time;
    case K::Acceleration:
      return (lin ? u.length : u.angle) + "/" + u.time + "**2";
    case K::Force:
      return lin ? u.force : u.force + "-" + u.length;
    case K::Expressions:
      break;
  }
  return "";
}

void addParts(Builder& b, const model::Model& m, const model::ResultsSettings& rs,
              ResultsLayout& l) {
  const ResultsUnits& u = l.units;
  std::vector<int> partEntities;
  for (const model::Part& p : m.parts) {
    if (p.body < 0) continue;
    const std::string name = "PART_" + std::to_string(p.id);
    partEntities.push_back(b.entity(name + "_XFORM", name, "Part", p.id));
  }
  l.parts = partEntities.size();
  static const char *const pos[3] = {"X", "Y", "Z"}, *ang[3] = {"PSI", "THETA", "PHI"};
  static const char *const vel[3] = {"VX", "VY", "VZ"}, *avel[3] = {"WX", "WY", "WZ"};
  static const char *const acc[3] = {"ACCX", "ACCY", "ACCZ"}, *aacc[3] = {"WDX", "WDY", "WDZ"};
  struct Block {
    bool on;
    const char* const* names[2];
    Vec3Of members[2];
    std::string units[2];
  };
  const Block blocks[3] = {{!rs.noDisplacements,
                            {pos, ang},
                            {&PartOutput::position, &PartOutput::angles},
                            {u.length, u.angle}},
                           {!rs.noVelocities,
                            {vel, avel},
                            {&PartOutput::velocity, &PartOutput::angularVelocity},
                            {u.length + "/" + u.time, u.angle + "/" + u.time}},
                           {!rs.noAccelerations,
                            {acc, aacc},
                            {&PartOutput::acceleration, &PartOutput::angularAcceleration},
                            {u.length + "/" + u.time + "**2", u.angle + "/" + u.time + "**2"}}};
  for (const Block& block : blocks) {
    if (!block.on) continue;
    for (std::size_t p = 0; p < partEntities.size(); ++p) {
      b.newGroup();
      for (int h = 0; h < 2; ++h)
        addVector(b, partEntities[p], p, block.members[h], block.names[h], block.units[h]);
    }
  }
}

void addElements(Builder& b, const model::Model& m, const model::ResultsSettings& rs,
                 ResultsLayout& l) {
  const ResultsUnits& u = l.units;
  if (!rs.noReactionForces) {
    addForces(
        b, m.joints, &OutputFrame::joints,
        [](const model::Joint& j) { return named("JOINT", j.id, "Joint"); }, u);
    addForces(
        b, m.jprims, &OutputFrame::jprims,
        [](const model::JPrim& j) { return named("JPRIM", j.id, "Joint_Primitive"); }, u);
    addForces(
        b, m.motions, &OutputFrame::motions,
        [](const model::Motion& j) { return named("MOTION", j.id, "Motion"); }, u);
    // Entity types of the elements below were not observed in a file ADAMS wrote
    // (docs/output-files.md).
    addForces(
        b, m.couplers, &OutputFrame::couplers,
        [](const model::Coupler& e) { return named("COUPLER", e.id, "Coupler"); }, u);
    addForces(
        b, m.gears, &OutputFrame::gears,
        [](const model::Gear& e) { return named("GEAR", e.id, "Gear"); }, u);
    addForces(
        b, m.gcons, &OutputFrame::gcons,
        [](const model::GeneralConstraint& e) { return named("GCON", e.id, "User_Constraint"); },
        u);
  }
  if (!rs.noAppliedForces) {
    addForces(
        b, m.sforces, &OutputFrame::sforces,
        [](const model::SForce& e) { return named("SFORCE", e.id, "Single_Component_Force"); }, u);
    addForces(
        b, m.springDampers, &OutputFrame::springDampers,
        [](const model::SpringDamper& e) { return named("SPRINGDAMPER", e.id, "Spring_Damper"); },
        u);
    addForces(
        b, m.linearFields, &OutputFrame::linearFields,
        [](const model::LinearField& e) {
          using K = model::LinearField::Kind;
          return e.kind == K::Bushing ? named("BUSHING", e.id, "Bushing")
                 : e.kind == K::Beam  ? named("BEAM", e.id, "Beam")
                                      : named("FIELD", e.id, "Field");
        },
        u);
    addForces(
        b, m.vectorForces, &OutputFrame::vectorForces,
        [](const model::VectorForce& e) {
          using K = model::VectorForce::Kind;
          return e.kind == K::VForce    ? named("VFORCE", e.id, "Vector_Force")
                 : e.kind == K::VTorque ? named("VTORQUE", e.id, "Vector_Torque")
                                        : named("GFORCE", e.id, "General_Force");
        },
        u);
    addForces(
        b, m.frictions, &OutputFrame::frictions,
        [](const model::Friction& e) { return named("FRICTION", e.id, "Friction"); }, u);
    addForces(
        b, m.nforces, &OutputFrame::nforces,
        [](const model::MultiPointForce& e) { return named("NFORCE", e.id, "Multi_Point_Force"); },
        u);
    addForces(
        b, m.contacts, &OutputFrame::contacts,
        [](const model::Contact& e) { return named("CONTACT", e.id, "Contact"); }, u);
  }
}

using StateList = std::vector<std::vector<double>> OutputFrame::*;

// Components prefix1..prefixN of element k's entry in a state list, on one line.
void addStates(Builder& b, int entity, StateList list, std::size_t k, int count,
               const std::string& prefix) {
  b.newGroup();
  for (int i = 0; i < count; ++i)
    b.add(entity, prefix + std::to_string(i + 1), "",
          [list, k, i](const OutputFrame& f) { return (f.*list)[k][static_cast<std::size_t>(i)]; });
}

// LSE/TFSISO states X1..Xn, GSE states X1..Xn and outputs Y1..Ym, PINPUT IN1..INn and POUTPUT
// OUT1..OUTn (the values of their VARIABLEs).
void addSystemElements(Builder& b, const model::Model& m) {
  for (std::size_t k = 0; k < m.linearStates.size(); ++k) {
    const model::LinearStateElement& ls = m.linearStates[k];
    const bool lse = ls.kind == model::LinearStateElement::Kind::Lse;
    const auto [name, type] = lse ? named("LSE", ls.id, "Linear_State_Equation")
                                  : named("TFSISO", ls.id, "Transfer_Function");
    const int e = b.entity(name, name, type, ls.id);
    addStates(b, e, &OutputFrame::linearStates, k, static_cast<int>(ls.a.rows()), "X");
  }
  for (std::size_t k = 0; k < m.generalStates.size(); ++k) {
    const model::GeneralStateElement& g = m.generalStates[k];
    const std::string name = "GSE_" + std::to_string(g.id);
    const int e = b.entity(name, name, "General_State_Equation", g.id);
    addStates(b, e, &OutputFrame::gseStates, k, g.ns, "X");
    addStates(b, e, &OutputFrame::gseOutputs, k, g.no, "Y");
  }
  const auto plant = [&](const std::vector<model::PlantVariables>& list, const char* prefix,
                         const char* type, const char* component) {
    for (const model::PlantVariables& p : list) {
      const std::string name = std::string(prefix) + "_" + std::to_string(p.id);
      const int e = b.entity(name, name, type, p.id);
      b.newGroup();
      for (std::size_t i = 0; i < p.variables.size(); ++i) {
        const auto v = static_cast<std::size_t>(p.variables[i]);
        b.add(e, component + std::to_string(i + 1), "",
              [v](const OutputFrame& f) { return f.variables[v]; });
      }
    }
  };
  plant(m.pinputs, "PINPUT", "Plant_Input", "IN");
  plant(m.poutputs, "POUTPUT", "Plant_Output", "OUT");
}

void addStatesAndRequests(Builder& b, const model::Model& m, const model::ResultsSettings& rs,
                          ResultsLayout& l) {
  if (!rs.noSystemElements) {
    for (std::size_t k = 0; k < m.variables.size(); ++k) {
      const std::string name = "VARIABLE_" + std::to_string(m.variables[k].id);
      const int e = b.entity(name, name, "ADAMS_Variable", m.variables[k].id);
      b.newGroup();
      b.add(e, "Q", "", [k](const OutputFrame& f) { return f.variables[k]; });
    }
    for (std::size_t k = 0; k < m.diffs.size(); ++k) {
      const std::string name = "DIFF_" + std::to_string(m.diffs[k].id);
      const int e = b.entity(name, name, "Differential_Equation", m.diffs[k].id);
      b.newGroup();
      b.add(e, "Q", "", [k](const OutputFrame& f) { return f.diffs[k]; });
    }
    addSystemElements(b, m);
  }
  if (rs.noRequests) return;
  for (std::size_t r = 0; r < m.requests.size(); ++r) {
    const model::Request& req = m.requests[r];
    const std::string name = "REQUEST_" + std::to_string(req.id);
    const int e = b.entity(name, name, "Request", req.id);
    b.newGroup();
    std::vector<std::string> names = defaultRequestComponentNames(req.kind);
    if (const auto it = rs.requestNames.find(req.id); it != rs.requestNames.end())
      for (std::size_t c = 0; c < it->second.size() && c < 8; ++c) names[c] = it->second[c];
    for (int c = 0; c < 8; ++c) {
      if (names[c].empty()) continue;  // CNAMES "" leaves the column out (ADAMS does)
      b.add(e, names[c], requestUnits(req.kind, c, l.units),
            [r, c](const OutputFrame& f) { return f.requests[r][c]; });
    }
  }
}

}  // namespace

std::string ResultsLayout::mismatch(const OutputFrame& f) const {
  const std::pair<const char*, std::pair<std::size_t, std::size_t>> counts[] = {
      {"parts", {parts, f.parts.size()}},
      {"joints", {joints, f.joints.size()}},
      {"joint primitives", {jprims, f.jprims.size()}},
      {"motions", {motions, f.motions.size()}},
      {"SFORCEs", {sforces, f.sforces.size()}},
      {"SPRINGDAMPERs", {springDampers, f.springDampers.size()}},
      {"BUSHING/FIELD/BEAMs", {linearFields, f.linearFields.size()}},
      {"VFORCE/VTORQUE/GFORCEs", {vectorForces, f.vectorForces.size()}},
      {"requests", {requests, f.requests.size()}},
      {"VARIABLEs", {variables, f.variables.size()}},
      {"DIFFs", {diffs, f.diffs.size()}},
      {"COUPLERs", {couplers, f.couplers.size()}},
      {"GEARs", {gears, f.gears.size()}},
      {"GCONs", {gcons, f.gcons.size()}},
      {"FRICTIONs", {frictions, f.frictions.size()}},
      {"NFORCEs", {nforces, f.nforces.size()}},
      {"CONTACTs", {contacts, f.contacts.size()}},
      {"LSE/TFSISOs", {linearStates, f.linearStates.size()}},
      {"GSEs", {gses, f.gseStates.size()}}};
  for (const auto& [what, n] : counts)
    if (n.first != n.second)
      return "the step has " + std::to_string(n.second) + " " + what + ", the file's map " +
             std::to_string(n.first);
  return "";
}

ResultsUnits resultsUnits(const model::Units& units) {
  ResultsUnits u;
  u.length = toLowerAscii(units.length);
  u.mass = units.mass == "KILOGRAM" ? "kg" : toLowerAscii(units.mass);
  u.time = units.time == "SECOND" ? "sec" : toLowerAscii(units.time);
  u.force = toLowerAscii(units.force);
  return u;
}

std::vector<std::string> defaultRequestComponentNames(model::Request::Kind kind) {
  if (kind == model::Request::Kind::Expressions)
    return {"U1", "U2", "U3", "U4", "U5", "U6", "U7", "U8"};
  return {"mag", "x", "y", "z", "rmag", "r1", "r2", "r3"};
}

ResultsLayout resultsLayout(const model::Model& m, const model::ResultsSettings& rs) {
  ResultsLayout l;
  l.units = resultsUnits(m.units);
  Builder b(l);
  const int time = b.entity("time", "", "", 0);
  b.add(time, "TIME", l.units.time, [](const OutputFrame& f) { return f.time; });
  addParts(b, m, rs, l);
  addElements(b, m, rs, l);
  addStatesAndRequests(b, m, rs, l);
  l.joints = m.joints.size();
  l.jprims = m.jprims.size();
  l.motions = m.motions.size();
  l.sforces = m.sforces.size();
  l.springDampers = m.springDampers.size();
  l.linearFields = m.linearFields.size();
  l.vectorForces = m.vectorForces.size();
  l.requests = m.requests.size();
  l.variables = m.variables.size();
  l.diffs = m.diffs.size();
  l.couplers = m.couplers.size();
  l.gears = m.gears.size();
  l.gcons = m.gcons.size();
  l.frictions = m.frictions.size();
  l.nforces = m.nforces.size();
  l.contacts = m.contacts.size();
  l.linearStates = m.linearStates.size();
  l.gses = m.generalStates.size();
  return l;
}

}  // namespace openmss::output
