#include "model/force_read_back_check.hpp"

#include <string>
#include <vector>

namespace openmss::model {
namespace {

// The force elements that have functions: SFORCEs (0..nS-1), then VFORCE/VTORQUE/GFORCEs.
// SPRINGDAMPER, BUSHING, FIELD and BEAM have none, so a read-back of them ends a chain.
class ReadBackGraph {
 public:
  explicit ReadBackGraph(const Model& m) : m_(m), ns_(static_cast<int>(m.sforces.size())) {
    const int n = ns_ + static_cast<int>(m.vectorForces.size());
    edges_.resize(static_cast<size_t>(n));
    for (int k = 0; k < ns_; ++k) addFunction(k, m.sforces[k].function);
    for (int k = 0; k < static_cast<int>(m.vectorForces.size()); ++k)
      for (const auto& c : m.vectorForces[k].components)
        if (c) addFunction(ns_ + k, *c);
  }

  int size() const { return static_cast<int>(edges_.size()); }
  const std::vector<int>& next(int node) const { return edges_[node]; }
  std::string name(int node) const {
    if (node < ns_) return "SFORCE/" + std::to_string(m_.sforces[node].id);
    const VectorForce& v = m_.vectorForces[node - ns_];
    const char* kind = v.kind == VectorForce::Kind::VForce    ? "VFORCE/"
                       : v.kind == VectorForce::Kind::VTorque ? "VTORQUE/"
                                                              : "GFORCE/";
    return kind + std::to_string(v.id);
  }
  const SourceLocation& where(int node) const {
    return node < ns_ ? m_.sforces[node].where : m_.vectorForces[node - ns_].where;
  }

 private:
  // FX..TM(i, j) reads every element acting on marker i (between i and j when j is given),
  // as mechanics::ForceElements::netForceActs selects them.
  bool acts(int im, int jm, const Measure& ms) const {
    return (im == ms.i && (ms.j < 0 || jm == ms.j)) || (jm == ms.i && (ms.j < 0 || im == ms.j));
  }
  void addFunction(int node, const BoundExpression& f) {
    for (const Measure& ms : f.measures) {
      // A read-back of an element that does not exist was reported while binding.
      if (ms.kind != MeasureKind::NetForce && ms.element < 0) continue;
      switch (ms.kind) {
        case MeasureKind::SForceForce:
          edges_[node].push_back(ms.element);
          break;
        case MeasureKind::VForceForce:
        case MeasureKind::VTorqueForce:
        case MeasureKind::GForceForce:
          edges_[node].push_back(ns_ + ms.element);
          break;
        case MeasureKind::NetForce:
          for (int k = 0; k < ns_; ++k)
            if (acts(m_.sforces[k].iMarker, m_.sforces[k].jMarker, ms)) edges_[node].push_back(k);
          for (int k = 0; k < static_cast<int>(m_.vectorForces.size()); ++k)
            if (acts(m_.vectorForces[k].iMarker, m_.vectorForces[k].jFloat, ms))
              edges_[node].push_back(ns_ + k);
          break;
        default:
          break;
      }
    }
  }

  const Model& m_;
  int ns_;
  std::vector<std::vector<int>> edges_;
};

}  // namespace

bool checkForceReadBackCycles(const Model& model, Diagnostics& diags) {
  const ReadBackGraph g(model);
  const int n = g.size();
  // Depth-first search with colours (0 new, 1 on the path, 2 done); iterative so that a long
  // chain of read-backs cannot exhaust the stack.
  std::vector<int> colour(static_cast<size_t>(n), 0), parent(static_cast<size_t>(n), -1);
  bool ok = true;
  for (int root = 0; root < n; ++root) {
    if (colour[root] != 0) continue;
    std::vector<std::pair<int, size_t>> stack{{root, 0}};
    colour[root] = 1;
    while (!stack.empty()) {
      auto& [node, at] = stack.back();
      if (at == g.next(node).size()) {
        colour[node] = 2;
        stack.pop_back();
        continue;
      }
      const int to = g.next(node)[at++];
      if (colour[to] == 0) {
        colour[to] = 1;
        parent[to] = node;
        stack.push_back({to, 0});
      } else if (colour[to] == 1) {
        // A cycle: to -> ... -> node -> to.
        std::vector<int> cycle{node};
        for (int c = node; c != to;) cycle.push_back(c = parent[c]);
        std::string path;
        for (auto it = cycle.rbegin(); it != cycle.rend(); ++it)
          path += g.name(*it) + (it + 1 == cycle.rend() ? "" : " reads ");
        path += " reads " + g.name(to);
        diags.error(g.where(to), g.name(to),
                    "force read-backs form a cycle that cannot be ordered: " + path +
                        (cycle.size() == 1 ? " (its own force)" : ""),
                    "Break the cycle: read a VARIABLE (an unknown solved with the rest) in one "
                    "of these functions, or compute the force from the displacements directly.");
        ok = false;
      }
    }
  }
  return ok;
}

}  // namespace openmss::model
