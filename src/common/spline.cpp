#include "common/spline.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace openmss {
namespace {

// Solves a tridiagonal system with partial pivoting (row interchanges fill one extra
// super-diagonal). The not-a-knot rows are not diagonally dominant for uneven spacing, so
// elimination without pivoting could divide by a small number.
// sub[i] is A(i+1, i), diag[i] is A(i, i), super[i] is A(i, i+1); rhs is overwritten.
void solveTridiagonal(std::vector<double> sub, std::vector<double> diag, std::vector<double> super,
                      std::vector<double>& rhs) {
  const std::size_t n = diag.size();
  std::vector<double> super2(n, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (std::abs(diag[i]) >= std::abs(sub[i])) {
      const double factor = sub[i] / diag[i];
      diag[i + 1] -= factor * super[i];
      rhs[i + 1] -= factor * rhs[i];
    } else {
      const double factor = diag[i] / sub[i];
      diag[i] = sub[i];
      const double below = diag[i + 1];
      diag[i + 1] = super[i] - factor * below;
      if (i + 2 < n) {
        super2[i] = super[i + 1];
        super[i + 1] = -factor * super[i + 1];
      }
      super[i] = below;
      std::swap(rhs[i], rhs[i + 1]);
      rhs[i + 1] -= factor * rhs[i];
    }
  }
  rhs[n - 1] /= diag[n - 1];
  if (n >= 2) rhs[n - 2] = (rhs[n - 2] - super[n - 2] * rhs[n - 1]) / diag[n - 2];
  for (std::size_t i = n - 2; i-- > 0;) {
    rhs[i] = (rhs[i] - super[i] * rhs[i + 1] - super2[i] * rhs[i + 2]) / diag[i];
  }
}

std::vector<double> secants(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> s(x.size() - 1);
  for (std::size_t i = 0; i + 1 < x.size(); ++i) s[i] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]);
  return s;
}

}  // namespace

std::vector<double> akimaSlopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  const std::vector<double> delta = secants(x, y);
  // s[k + 2] = delta[k]; two secants are invented at each end by continuing the secants'
  // differences linearly (Akima's end rule), so every knot has four secants around it.
  std::vector<double> s(n + 3);
  for (std::size_t k = 0; k + 1 < n; ++k) s[k + 2] = delta[k];
  s[1] = 2.0 * s[2] - s[3];
  s[0] = 2.0 * s[1] - s[2];
  s[n + 1] = 2.0 * s[n] - s[n - 1];
  s[n + 2] = 2.0 * s[n + 1] - s[n];
  std::vector<double> m(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double wLeft = std::abs(s[i + 3] - s[i + 2]);
    const double wRight = std::abs(s[i + 1] - s[i]);
    m[i] = wLeft + wRight == 0.0 ? 0.5 * (s[i + 1] + s[i + 2])
                                 : (wLeft * s[i + 1] + wRight * s[i + 2]) / (wLeft + wRight);
  }
  return m;
}

std::vector<double> notAKnotSlopes(const std::vector<double>& x, const std::vector<double>& y) {
  // Second derivatives M_i at the knots. Interior rows: continuity of the slope,
  //   h(i-1) M(i-1) + 2 (h(i-1) + h(i)) M(i) + h(i) M(i+1) = 6 (delta(i) - delta(i-1)).
  // Not-a-knot: the third derivative is continuous at x1 and x(n-2), so M0 and M(n-1) are linear
  // extrapolations of their neighbours and are eliminated from rows 1 and n-2.
  const std::size_t n = x.size();
  const std::vector<double> delta = secants(x, y);
  std::vector<double> h(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) h[i] = x[i + 1] - x[i];
  const std::size_t unknowns = n - 2;  // M1 .. M(n-2)
  std::vector<double> sub(unknowns - 1), diag(unknowns), super(unknowns - 1), rhs(unknowns);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const std::size_t row = i - 1;
    diag[row] = 2.0 * (h[i - 1] + h[i]);
    if (row > 0) sub[row - 1] = h[i - 1];
    if (row + 1 < unknowns) super[row] = h[i];
    rhs[row] = 6.0 * (delta[i] - delta[i - 1]);
  }
  // M0 = M1 + (h0 / h1) (M1 - M2).
  diag[0] += h[0] * (1.0 + h[0] / h[1]);
  super[0] -= h[0] * h[0] / h[1];
  // M(n-1) = M(n-2) + (h(n-2) / h(n-3)) (M(n-2) - M(n-3)).
  const double hLast = h[n - 2];
  const double hBefore = h[n - 3];
  diag[unknowns - 1] += hLast * (1.0 + hLast / hBefore);
  sub[unknowns - 2] -= hLast * hLast / hBefore;
  solveTridiagonal(sub, diag, super, rhs);
  std::vector<double> second(n);
  for (std::size_t i = 0; i < unknowns; ++i) second[i + 1] = rhs[i];
  second[0] = second[1] + h[0] / h[1] * (second[1] - second[2]);
  second[n - 1] = second[n - 2] + hLast / hBefore * (second[n - 2] - second[n - 3]);
  std::vector<double> m(n);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    m[i] = delta[i] - h[i] * (2.0 * second[i] + second[i + 1]) / 6.0;
  }
  m[n - 1] = delta[n - 2] + hLast * (second[n - 2] + 2.0 * second[n - 1]) / 6.0;
  return m;
}

Spline::Spline(std::vector<double> x, std::vector<double> z,
               const std::vector<std::vector<double>>& curves, bool linearExtrapolation)
    : x_(std::move(x)), z_(std::move(z)), linear_(linearExtrapolation) {
  const std::size_t n = x_.size();
  for (const std::vector<double>& y : curves) {
    // Hermite data (knot values and slopes) to the power form of each piece.
    for (SplineMethod method : {SplineMethod::Akima, SplineMethod::Cubic}) {
      const std::vector<double> m =
          method == SplineMethod::Akima ? akimaSlopes(x_, y) : notAKnotSlopes(x_, y);
      std::vector<Cubic>& pieces = method == SplineMethod::Akima ? akima_ : cubic_;
      for (std::size_t i = 0; i + 1 < n; ++i) {
        const double h = x_[i + 1] - x_[i];
        const double delta = (y[i + 1] - y[i]) / h;
        pieces.push_back({y[i], m[i], (3.0 * delta - 2.0 * m[i] - m[i + 1]) / h,
                          (m[i] + m[i + 1] - 2.0 * delta) / (h * h)});
      }
    }
    // Extrapolation: the line through the two end points, or the parabola through the three.
    const double h0 = x_[1] - x_[0];
    const double hn = x_[n - 1] - x_[n - 2];
    const double d0 = (y[1] - y[0]) / h0;
    const double dn = (y[n - 1] - y[n - 2]) / hn;
    if (linear_) {
      left_.push_back({y[0], d0, 0.0, 0.0});
      right_.push_back({y[n - 1], dn, 0.0, 0.0});
    } else {
      // Newton form about the end point: y0 + d0 t + f012 t (t - h0), t = x - x0.
      const double f012 = ((y[2] - y[1]) / (x_[2] - x_[1]) - d0) / (x_[2] - x_[0]);
      left_.push_back({y[0], d0 - f012 * h0, f012, 0.0});
      const double fLast =
          (dn - (y[n - 2] - y[n - 3]) / (x_[n - 2] - x_[n - 3])) / (x_[n - 1] - x_[n - 3]);
      right_.push_back({y[n - 1], dn + fLast * hn, fLast, 0.0});
    }
  }
}

void Spline::curveDerivatives(SplineMethod method, std::size_t curve, double x,
                              double out[5]) const {
  const std::size_t n = x_.size();
  const Cubic* piece = nullptr;
  double t = 0.0;
  if (x < x_.front()) {
    piece = &left_[curve];
    t = x - x_.front();
  } else if (x > x_.back()) {
    piece = &right_[curve];
    t = x - x_.back();
  } else {
    // The piece whose interval holds x (the last piece for x = x(n-1)).
    const auto above = std::upper_bound(x_.begin(), x_.end(), x);
    std::size_t i = static_cast<std::size_t>(above - x_.begin());
    i = i == 0 ? 0 : std::min(i - 1, n - 2);
    const std::vector<Cubic>& pieces = method == SplineMethod::Akima ? akima_ : cubic_;
    piece = &pieces[curve * (n - 1) + i];
    t = x - x_[i];
  }
  const Cubic& p = *piece;
  out[0] = p.a + t * (p.b + t * (p.c + t * p.d));
  out[1] = p.b + t * (2.0 * p.c + 3.0 * p.d * t);
  out[2] = 2.0 * p.c + 6.0 * p.d * t;
  out[3] = 6.0 * p.d;
  out[4] = 0.0;
}

SplinePartials Spline::evaluate(SplineMethod method, double x, double z, int order) const {
  const auto k = static_cast<std::size_t>(std::clamp(order, 0, 2));
  double lower[5];
  curveDerivatives(method, 0, x, lower);
  SplinePartials p;
  if (z_.size() < 2) {
    p.g = lower[k];
    p.gx = lower[k + 1];
    p.gxx = lower[k + 2];
    return p;
  }
  // Between curves j and j+1, or beyond the first or last curve by linear extrapolation of the
  // two nearest ones.
  const auto above = std::upper_bound(z_.begin(), z_.end(), z);
  std::size_t j = static_cast<std::size_t>(above - z_.begin());
  j = j == 0 ? 0 : std::min(j - 1, z_.size() - 2);
  double upper[5];
  curveDerivatives(method, j, x, lower);
  curveDerivatives(method, j + 1, x, upper);
  const double dz = z_[j + 1] - z_[j];
  const double w = (z - z_[j]) / dz;
  p.g = (1.0 - w) * lower[k] + w * upper[k];
  p.gx = (1.0 - w) * lower[k + 1] + w * upper[k + 1];
  p.gxx = (1.0 - w) * lower[k + 2] + w * upper[k + 2];
  p.gz = (upper[k] - lower[k]) / dz;
  p.gxz = (upper[k + 1] - lower[k + 1]) / dz;
  p.gzz = 0.0;
  return p;
}

}  // namespace openmss
