#include "common/bspline_curve.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace openmss {

std::string BSplineCurve::check(const std::vector<std::array<double, 3>>& points, int order,
                                bool closed) {
  const auto m = static_cast<int>(points.size());
  if (m < 4) return "the curve needs at least 4 points, the matrix has " + std::to_string(m);
  if (order < 2 || order > kMaxOrder) {
    return "ORDER must be 2 to " + std::to_string(kMaxOrder) + ", not " + std::to_string(order);
  }
  if (closed) {
    if (points.front() != points.back()) {
      return "a CLOSED curve needs its first point equal to its last point";
    }
    if (m - 1 < order) {
      return "a CLOSED curve of ORDER=" + std::to_string(order) + " needs at least " +
             std::to_string(order + 1) + " points (the last repeats the first)";
    }
  } else if (m < order) {
    return "a curve of ORDER=" + std::to_string(order) + " needs at least " +
           std::to_string(order) + " points";
  }
  return "";
}

double BSplineCurve::deBoor(const Piecewise& s, double u, int comp) {
  const int p = s.degree;
  const auto count = static_cast<int>(s.points.size());
  const auto above = std::upper_bound(s.knots.begin(), s.knots.end(), u);
  int span = static_cast<int>(above - s.knots.begin()) - 1;
  span = std::clamp(span, p, count - 1);
  double d[kMaxOrder];
  for (int j = 0; j <= p; ++j) d[j] = s.points[static_cast<std::size_t>(span - p + j)][comp];
  for (int r = 1; r <= p; ++r) {
    for (int j = p; j >= r; --j) {
      const int i = span - p + j;
      const double left = s.knots[static_cast<std::size_t>(i)];
      const double width = s.knots[static_cast<std::size_t>(i + p + 1 - r)] - left;
      const double a = width == 0.0 ? 0.0 : (u - left) / width;
      d[j] = (1.0 - a) * d[j - 1] + a * d[j];
    }
  }
  return d[p];
}

BSplineCurve::BSplineCurve(const std::vector<std::array<double, 3>>& points, int order, bool closed,
                           bool throughPoints)
    : order_(order), closed_(closed) {
  const int p = order - 1;
  const auto m = static_cast<int>(points.size());
  Piecewise& curve = hodographs_[0];
  curve.degree = p;
  // Control-point layout and knots; `unknown` maps a stored control point to the distinct
  // point it copies (periodic curves repeat their first p points at the end).
  std::vector<int> source;
  std::vector<double> sites;  // parameter values of the given points (CURVE_POINTS)
  int distinct = m;
  if (!closed) {
    // Clamped uniform knots on [0, 1].
    for (int j = 0; j < order; ++j) curve.knots.push_back(0.0);
    if (throughPoints) {
      for (int i = 0; i < m; ++i) sites.push_back(static_cast<double>(i) / (m - 1));
      // de Boor's knot averaging: interior knot j is the mean of p consecutive sites.
      for (int j = 1; j <= m - order; ++j) {
        double sum = 0.0;
        for (int i = j; i < j + p; ++i) sum += sites[static_cast<std::size_t>(i)];
        curve.knots.push_back(sum / p);
      }
    } else {
      for (int j = 1; j <= m - order; ++j) {
        curve.knots.push_back(static_cast<double>(j) / (m - order + 1));
      }
    }
    for (int j = 0; j < order; ++j) curve.knots.push_back(1.0);
    for (int i = 0; i < m; ++i) source.push_back(i);
    uMin_ = 0.0;
    uMax_ = 1.0;
  } else {
    // Periodic uniform knots: N distinct points, the first p repeated, integer knots; one
    // period is u in [p, N + p].
    distinct = m - 1;
    for (int i = 0; i < distinct + p; ++i) source.push_back(i % distinct);
    for (int j = 0; j < distinct + p + order; ++j) curve.knots.push_back(j);
    uMin_ = p;
    uMax_ = distinct + p;
    if (throughPoints) {
      // Sites at knots for odd degree, at mid-knots for even degree: the periodic collocation
      // matrix is then invertible for any number of points.
      const double shift = p % 2 == 1 ? 0.0 : 0.5;
      for (int i = 0; i < distinct; ++i) sites.push_back(p + i + shift);
    }
  }
  std::vector<std::array<double, 3>> control(static_cast<std::size_t>(distinct));
  if (!throughPoints) {
    for (int i = 0; i < distinct; ++i)
      control[static_cast<std::size_t>(i)] = points[static_cast<std::size_t>(i)];
  } else {
    // Collocation: row i holds the basis functions at site i; one basis function at a time is
    // obtained by evaluating the spline whose only non-zero control point is 1.
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(distinct, distinct);
    curve.points.assign(source.size(), {0.0, 0.0, 0.0});
    for (int j = 0; j < distinct; ++j) {
      for (std::size_t r = 0; r < source.size(); ++r) {
        curve.points[r][0] = source[r] == j ? 1.0 : 0.0;
      }
      for (int i = 0; i < distinct; ++i)
        a(i, j) = deBoor(curve, sites[static_cast<std::size_t>(i)], 0);
    }
    Eigen::MatrixXd rhs(distinct, 3);
    for (int i = 0; i < distinct; ++i) {
      for (int c = 0; c < 3; ++c)
        rhs(i, c) = points[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)];
    }
    const Eigen::MatrixXd solution = a.partialPivLu().solve(rhs);
    for (int i = 0; i < distinct; ++i) {
      for (int c = 0; c < 3; ++c)
        control[static_cast<std::size_t>(i)][static_cast<std::size_t>(c)] = solution(i, c);
    }
  }
  curve.points.clear();
  for (int r : source) curve.points.push_back(control[static_cast<std::size_t>(r)]);
  // Derivative curves (hodographs): degree p - 1, knots without the end ones, control points
  // p (P(i+1) - P(i)) / (t(i+p+1) - t(i+1)). Degree 0 differentiates to zero.
  for (int k = 1; k < kDerivatives; ++k) {
    const Piecewise& s = hodographs_[static_cast<std::size_t>(k - 1)];
    Piecewise& d = hodographs_[static_cast<std::size_t>(k)];
    if (s.degree == 0) {
      d = s;
      for (auto& point : d.points) point = {0.0, 0.0, 0.0};
      continue;
    }
    d.degree = s.degree - 1;
    d.knots.assign(s.knots.begin() + 1, s.knots.end() - 1);
    for (std::size_t i = 0; i + 1 < s.points.size(); ++i) {
      const double width = s.knots[i + static_cast<std::size_t>(s.degree) + 1] - s.knots[i + 1];
      std::array<double, 3> q{};
      for (std::size_t c = 0; c < 3; ++c) {
        q[c] = width == 0.0 ? 0.0 : s.degree * (s.points[i + 1][c] - s.points[i][c]) / width;
      }
      d.points.push_back(q);
    }
  }
}

void BSplineCurve::derivatives(double alpha, int comp, double out[kDerivatives]) const {
  if (user_) {
    user_->derivatives(alpha, comp, out);
    return;
  }
  if (closed_) alpha -= 2.0 * std::floor((alpha + 1.0) / 2.0);  // into [-1, 1)
  const double scale = 0.5 * (uMax_ - uMin_);                   // du / d alpha
  const double u = uMin_ + (alpha + 1.0) * scale;
  double factor = 1.0;
  for (int k = 0; k < kDerivatives; ++k) {
    out[k] = factor * deBoor(hodographs_[static_cast<std::size_t>(k)], u, comp);
    factor *= scale;
  }
}

}  // namespace openmss
