#pragma once
// The rows of the GSEs (docs/theory.md, "GSE") in the DAE residual:
//
//   x_i' - f_i(x, xd, u, t) = 0       one per continuous state (user differential)
//   y_j  - g_j(x, xd, u, t) = 0       one per output (user algebraic)
//
// f and g are black boxes (user/gse_routines.hpp), evaluated on numbers. On dual numbers the
// rows get their derivatives from one linearization per state: the routines' own partials
// (ADAMS_NEEDS_PARTIALS/SYSPAR) where they supply them, central differences of f and g
// otherwise, cached while the state's values stay the same (every column of one Newton
// matrix reuses it; that cache and the x_..g_ buffers are pure scratch: a hit returns the
// numbers a recomputation gives, so they never change results). xd is a constant between
// samples, held in the run state (ExpressionRunState::gseDiscrete; the ICD without one).

#include <type_traits>
#include <vector>

#include "common/dual.hpp"
#include "mechanics/expression_run_state.hpp"
#include "mechanics/state_layout.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

// Column of the state vector that holds GSE k's state c, input c (its U array's VARIABLE) and
// output j.
int gseStateColumn(const model::Model& m, const StateLayout& l, int k, int c);
int gseInputColumn(const model::Model& m, const StateLayout& l, int k, int c);
int gseOutputColumn(const model::Model& m, const StateLayout& l, int k, int j);

class GeneralStateRows {
 public:
  explicit GeneralStateRows(const model::Model& model) : model_(&model) {}
  void setLayout(const StateLayout& layout) { layout_ = layout; }
  void setRunState(const ExpressionRunState* run) { run_ = run; }
  // GSE k's discrete states xd: the run state's, or its ICD without one.
  const double* discrete(int k) const;

  template <class T>
  void addToResidual(double t, const T* y, const T* yp, T* g) const;

  // f and g of GSE k at values x (ns) and u (ni); either output may be null.
  void evaluate(int k, double t, const double* x, const double* u, double* xdot,
                double* outputs) const;

  // Column-major partials of f and g with respect to x and u, with the values they belong to.
  struct Linearization {
    std::vector<double> key;  // t, x, u, xd at which it was formed
    std::vector<double> f, g, fx, fu, gx, gu;
  };
  const Linearization& linearize(int k, double t, const double* x, const double* u) const;

 private:
  const model::Model* model_;
  StateLayout layout_;
  const ExpressionRunState* run_ = nullptr;
  mutable std::vector<Linearization> cache_;
  mutable std::vector<double> x_, u_, f_, g_;
};

template <class T>
void GeneralStateRows::addToResidual(double t, const T* y, const T* yp, T* g) const {
  const model::Model& m = *model_;
  for (int k = 0; k < static_cast<int>(m.generalStates.size()); ++k) {
    const model::GeneralStateElement& e = m.generalStates[k];
    x_.resize(static_cast<size_t>(e.ns));
    u_.resize(static_cast<size_t>(e.ni));
    for (int c = 0; c < e.ns; ++c) x_[c] = valueOf(y[gseStateColumn(m, layout_, k, c)]);
    for (int c = 0; c < e.ni; ++c) u_[c] = valueOf(y[gseInputColumn(m, layout_, k, c)]);
    if constexpr (std::is_same_v<T, double>) {
      f_.resize(static_cast<size_t>(e.ns));
      g_.resize(static_cast<size_t>(e.no));
      evaluate(k, t, x_.data(), u_.data(), f_.data(), g_.data());
      for (int i = 0; i < e.ns; ++i) {
        const int row = gseStateColumn(m, layout_, k, i);
        g[row] = yp[row] - f_[i];
      }
      for (int j = 0; j < e.no; ++j) {
        const int row = gseOutputColumn(m, layout_, k, j);
        g[row] = y[row] - g_[j];
      }
    } else {
      const Linearization& lin = linearize(k, t, x_.data(), u_.data());
      // value + J (z - value(z)): the derivative part of each input, times its partial.
      auto linear = [&](double value, const std::vector<double>& dx, const std::vector<double>& du,
                        int row, int rows) {
        T out(value);
        for (int c = 0; c < e.ns; ++c) {
          const T& z = y[gseStateColumn(m, layout_, k, c)];
          out = out + dx[static_cast<size_t>(row + rows * c)] * (z - T(x_[c]));
        }
        for (int c = 0; c < e.ni; ++c) {
          const T& z = y[gseInputColumn(m, layout_, k, c)];
          out = out + du[static_cast<size_t>(row + rows * c)] * (z - T(u_[c]));
        }
        return out;
      };
      // The rows read x_ and u_ of this element only through `lin` and the lambda, so the
      // scratch is not overwritten in between.
      for (int i = 0; i < e.ns; ++i) {
        const int row = gseStateColumn(m, layout_, k, i);
        g[row] = yp[row] - linear(lin.f[i], lin.fx, lin.fu, i, e.ns);
      }
      for (int j = 0; j < e.no; ++j) {
        const int row = gseOutputColumn(m, layout_, k, j);
        g[row] = y[row] - linear(lin.g[j], lin.gx, lin.gu, j, e.no);
      }
    }
  }
}

}  // namespace openmss::mechanics
