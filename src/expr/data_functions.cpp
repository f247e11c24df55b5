#include "expr/data_functions.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace openmss::expr {
namespace {

// The knot values of the first curve. The spline interpolates its data, so reading it at the
// knots returns the numbers the SPLINE statement gave (the Spline keeps no copy of them).
std::vector<double> knotValues(const Spline& spline) {
  std::vector<double> y;
  y.reserve(spline.x().size());
  const double z = spline.z().empty() ? 0.0 : spline.z().front();
  for (double x : spline.x()) y.push_back(spline.evaluate(SplineMethod::Cubic, x, z, 0).g);
  return y;
}

// Index of the segment [x_k, x_k+1] that serves `at`: the last one whose left end is <= at,
// clamped to the first and last segments.
std::size_t segmentOf(const std::vector<double>& x, double at) {
  const auto upper = std::upper_bound(x.begin(), x.end(), at);
  const auto k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(upper - x.begin() - 1, 0));
  return std::min(k, x.size() - 2);
}

}  // namespace

LinearTable::LinearTable(const Spline& spline) : x_(spline.x()), y_(knotValues(spline)) {}

ScalarJet LinearTable::evaluate(double x) const {
  const std::size_t k = segmentOf(x_, x);
  const double slope = (y_[k + 1] - y_[k]) / (x_[k + 1] - x_[k]);
  return {y_[k] + slope * (x - x_[k]), slope, 0.0};
}

double PsdSignal::psdAt(const std::vector<double>& f, const std::vector<double>& s, double at,
                        bool logarithmic) {
  if (at <= f.front()) return s.front();
  if (at >= f.back()) return s.back();
  const std::size_t k = segmentOf(f, at);
  // Log-log interpolation needs positive frequencies and densities at both knots; a segment
  // that touches zero is read linearly instead.
  if (logarithmic && f[k] > 0.0 && s[k] > 0.0 && s[k + 1] > 0.0) {
    const double t = std::log(at / f[k]) / std::log(f[k + 1] / f[k]);
    return s[k] * std::pow(s[k + 1] / s[k], t);
  }
  const double t = (at - f[k]) / (f[k + 1] - f[k]);
  return s[k] + t * (s[k + 1] - s[k]);
}

double PsdSignal::uniform(std::uint64_t& state) {
  state += 0x9E3779B97F4A7C15ULL;
  std::uint64_t z = state;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;  // the top 53 bits: [0, 1)
}

PsdSignal::PsdSignal(const Spline& spline, double f0, double f1, int frequencyCount,
                     int logarithmic, double seed) {
  const std::vector<double>& f = spline.x();
  const std::vector<double> s = knotValues(spline);
  const auto n = static_cast<std::size_t>(std::max(frequencyCount, 2));
  const double df = (f1 - f0) / static_cast<double>(n - 1);
  // The C++ solver casts the seed to an integer; so do we (toward zero).
  auto state = static_cast<std::uint64_t>(static_cast<std::int64_t>(std::trunc(seed)));
  for (std::size_t i = 0; i < n; ++i) {
    const double fi = f0 + static_cast<double>(i) * df;
    const double density = std::max(psdAt(f, s, fi, logarithmic == 1), 0.0);
    frequency_.push_back(fi);
    amplitude_.push_back(std::sqrt(2.0 * density * std::abs(df)));
    phase_.push_back(2.0 * std::numbers::pi * uniform(state));
  }
}

ScalarJet PsdSignal::evaluate(double x) const {
  ScalarJet out;
  for (std::size_t i = 0; i < frequency_.size(); ++i) {
    const double w = 2.0 * std::numbers::pi * frequency_[i];
    const double angle = w * x + phase_[i];
    const double s = std::sin(angle);
    const double c = std::cos(angle);
    out.g += amplitude_[i] * s;
    out.gx += amplitude_[i] * w * c;
    out.gxx -= amplitude_[i] * w * w * s;
  }
  return out;
}

}  // namespace openmss::expr
