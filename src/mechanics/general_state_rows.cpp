#include "mechanics/general_state_rows.hpp"

#include <algorithm>
#include <cmath>

namespace openmss::mechanics {

int gseStateColumn(const model::Model& m, const StateLayout& l, int k, int c) {
  return l.userDiff(m.generalStates[k].firstState + c);
}
int gseInputColumn(const model::Model& m, const StateLayout& l, int k, int c) {
  const model::GeneralStateElement& e = m.generalStates[k];
  return l.userAlg(m.arrays[e.uArray].variables[c]);
}
int gseOutputColumn(const model::Model& m, const StateLayout& l, int k, int j) {
  return l.userAlg(m.generalStates[k].firstOutput + j);
}

const double* GeneralStateRows::discrete(int k) const {
  return run_ ? run_->gseDiscrete(k).data() : model_->generalStates[k].icd.data();
}

void GeneralStateRows::evaluate(int k, double t, const double* x, const double* u, double* xdot,
                                double* outputs) const {
  const model::GeneralStateElement& e = model_->generalStates[k];
  user::GseArguments a{t, x, discrete(k), u, false};
  if (xdot && e.ns > 0) e.routines->derivatives(a, xdot, nullptr);
  if (outputs && e.no > 0) e.routines->outputs(a, outputs, nullptr);
}

const GeneralStateRows::Linearization& GeneralStateRows::linearize(int k, double t, const double* x,
                                                                   const double* u) const {
  const model::GeneralStateElement& e = model_->generalStates[k];
  const size_t ns = static_cast<size_t>(e.ns), ni = static_cast<size_t>(e.ni),
               no = static_cast<size_t>(e.no);
  if (cache_.size() != model_->generalStates.size())
    cache_.assign(model_->generalStates.size(), {});
  std::vector<double> key{t};
  key.insert(key.end(), x, x + ns);
  key.insert(key.end(), u, u + ni);
  key.insert(key.end(), discrete(k), discrete(k) + e.nd);
  Linearization& lin = cache_[static_cast<size_t>(k)];
  if (lin.key == key) return lin;
  lin.key = key;
  lin.f.assign(ns, 0.0);
  lin.g.assign(no, 0.0);
  // The unperturbed call offers the routines to supply their partials (ADAMS's DFLAG set,
  // ADAMS_NEEDS_PARTIALS true).
  user::GseArguments a{t, x, discrete(k), u, true};
  user::GsePartials pf, pg;
  if (ns > 0) e.routines->derivatives(a, lin.f.data(), &pf);
  if (no > 0) e.routines->outputs(a, lin.g.data(), &pg);
  lin.fx = pf.dx.value_or(std::vector<double>());
  lin.fu = pf.du.value_or(std::vector<double>());
  lin.gx = pg.dx.value_or(std::vector<double>());
  lin.gu = pg.du.value_or(std::vector<double>());
  // Central differences for each block the routines left out: h = 1e-6 max(1, |z|) gives
  // about 1e-8 relative accuracy for smooth f and g (truncation h^2, round-off eps/h).
  auto differences = [&](size_t n, const double* z0, bool isState, std::vector<double>& fz,
                         std::vector<double>& gz) {
    const bool needF = ns > 0 && fz.size() != ns * n, needG = no > 0 && gz.size() != no * n;
    if (n == 0 || (!needF && !needG)) return;
    if (needF) fz.assign(ns * n, 0.0);
    if (needG) gz.assign(no * n, 0.0);
    std::vector<double> z(z0, z0 + n), fa(ns), fb(ns), ga(no), gb(no);
    for (size_t c = 0; c < n; ++c) {
      const double h = 1e-6 * std::max(1.0, std::abs(z0[c]));
      user::GseArguments p = a;
      (isState ? p.x : p.u) = z.data();
      z[c] = z0[c] + h;
      if (needF) e.routines->derivatives(p, fa.data(), nullptr);
      if (needG) e.routines->outputs(p, ga.data(), nullptr);
      z[c] = z0[c] - h;
      if (needF) e.routines->derivatives(p, fb.data(), nullptr);
      if (needG) e.routines->outputs(p, gb.data(), nullptr);
      z[c] = z0[c];
      for (size_t i = 0; i < ns && needF; ++i) fz[i + ns * c] = (fa[i] - fb[i]) / (2 * h);
      for (size_t j = 0; j < no && needG; ++j) gz[j + no * c] = (ga[j] - gb[j]) / (2 * h);
    }
  };
  differences(ns, x, true, lin.fx, lin.gx);
  differences(ni, u, false, lin.fu, lin.gu);
  // Blocks of zero size (no states, no inputs) stay empty and are never read.
  return lin;
}

}  // namespace openmss::mechanics
