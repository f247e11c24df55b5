// BdfIntegrator's fused per-unknown passes (bdf_vector_passes.hpp). The number of terms is a
// template parameter so that the loop over the terms unrolls, their weights stay in registers
// and the loop over the unknowns vectorises (docs/performance.md, "GSTIFF's cost per step,
// cheaper").

#include "solvers/bdf_vector_passes.hpp"

#include <cmath>

namespace openmss::solvers::bdf {
namespace {

template <int M, bool kFromZero>
void combineFixed(double* __restrict out, const double* const* src, const double* w,
                  Eigen::Index n) {
  const double* s[M];
  double c[M];
  for (int j = 0; j < M; ++j) {
    s[j] = src[j];
    c[j] = w[j];
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    double v = kFromZero ? 0.0 + c[0] * s[0][i] : c[0] * s[0][i];
    for (int j = 1; j < M; ++j) v += c[j] * s[j][i];
    out[i] = v;
  }
}

template <bool kFromZero>
void combineAny(double* out, const double* const* src, const double* w, int m, Eigen::Index n) {
  switch (m) {
    case 1:
      return combineFixed<1, kFromZero>(out, src, w, n);
    case 2:
      return combineFixed<2, kFromZero>(out, src, w, n);
    case 3:
      return combineFixed<3, kFromZero>(out, src, w, n);
    case 4:
      return combineFixed<4, kFromZero>(out, src, w, n);
    case 5:
      return combineFixed<5, kFromZero>(out, src, w, n);
    case 6:
      return combineFixed<6, kFromZero>(out, src, w, n);
    case 7:
      return combineFixed<7, kFromZero>(out, src, w, n);
    case 8:
      return combineFixed<8, kFromZero>(out, src, w, n);
    default:
      break;
  }
  if (m <= 0) {  // the sum of no terms: zero, as setZero() leaves it
    for (Eigen::Index i = 0; i < n; ++i) out[i] = 0.0;
    return;
  }
  // More terms than the unrolled cases (KMAX is at most 6, so not reached today): the same
  // operations in the same order, the terms counted at run time.
  for (Eigen::Index i = 0; i < n; ++i) {
    double v = kFromZero ? 0.0 + w[0] * src[0][i] : w[0] * src[0][i];
    for (int j = 1; j < m; ++j) v += w[j] * src[j][i];
    out[i] = v;
  }
}

template <bool kRescale, CorrectorUpdate::Later kLater>
void applyFixed(const CorrectorUpdate& u, double* __restrict dy, const double* __restrict colScale,
                double* __restrict y, const double* __restrict base, double* __restrict yp,
                double* __restrict laterChanges, Eigen::Index n) {
  const double cjFactor = u.cjFactor, cj = u.cj;
  for (Eigen::Index i = 0; i < n; ++i) {
    double d = dy[i] * colScale[i];
    if constexpr (kRescale) d *= cjFactor;
    dy[i] = d;
    const double yi = y[i] - d;
    y[i] = yi;
    yp[i] = cj * yi + base[i];
    if constexpr (kLater == CorrectorUpdate::Later::Assign) laterChanges[i] = std::abs(d);
    if constexpr (kLater == CorrectorUpdate::Later::Add)
      laterChanges[i] = laterChanges[i] + std::abs(d);
  }
}

template <bool kRescale>
void applyRescaled(const CorrectorUpdate& u, double* dy, const double* colScale, double* y,
                   const double* base, double* yp, double* laterChanges, Eigen::Index n) {
  using L = CorrectorUpdate::Later;
  switch (u.later) {
    case L::None:
      return applyFixed<kRescale, L::None>(u, dy, colScale, y, base, yp, laterChanges, n);
    case L::Assign:
      return applyFixed<kRescale, L::Assign>(u, dy, colScale, y, base, yp, laterChanges, n);
    case L::Add:
      return applyFixed<kRescale, L::Add>(u, dy, colScale, y, base, yp, laterChanges, n);
  }
}

}  // namespace

void combineFromZero(double* out, const double* const* src, const double* w, int m,
                     Eigen::Index n) {
  combineAny<true>(out, src, w, m, n);
}

void combine(double* out, const double* const* src, const double* w, int m, Eigen::Index n) {
  combineAny<false>(out, src, w, m, n);
}

void applyCorrectorChange(const CorrectorUpdate& u, double* dy, const double* colScale, double* y,
                          const double* base, double* yp, double* laterChanges, Eigen::Index n) {
  if (u.rescale)
    applyRescaled<true>(u, dy, colScale, y, base, yp, laterChanges, n);
  else
    applyRescaled<false>(u, dy, colScale, y, base, yp, laterChanges, n);
}

}  // namespace openmss::solvers::bdf
