#pragma once
// The SPLINE-based functions that are not plain AKISPL/CUBSPL reads: INTERP (a time series read
// linearly or with a cubic spline) and INVPSD (a time signal regenerated from a power spectral
// density). Each is built once, when its call is bound to the SPLINE, into an immutable table;
// evaluation is allocation-free and gives the value with its first and second derivative in x
// (docs/expressions.md, "INTERP" and "INVPSD").

#include <cstdint>
#include <vector>

#include "common/spline.hpp"

namespace openmss::expr {

// y(x) and its first two derivatives.
struct ScalarJet {
  double g = 0.0, gx = 0.0, gxx = 0.0;
};

// Piecewise-linear interpolation through the knots (x_k, y_k) of the first curve of a SPLINE.
// Beyond the ends the first or last segment is extended. At a knot the segment on the right
// gives the slope.
class LinearTable {
 public:
  explicit LinearTable(const Spline& spline);
  ScalarJet evaluate(double x) const;
  const std::vector<double>& y() const { return y_; }

 private:
  std::vector<double> x_, y_;
};

// INVPSD(x, id, f0, f1, nf, linlog, seed) = sum_i A_i sin(2 pi f_i x + phi_i), with nf
// frequencies f_i = f0 + i (f1 - f0)/(nf - 1), amplitudes A_i = sqrt(2 S(f_i) df) so that the
// signal's mean square sum A_i^2 / 2 equals sum S(f_i) df, S the PSD read from the SPLINE knots
// (linearly, or linearly in log S versus log f when linlog = 1), and phases phi_i = 2 pi u_i
// from the SplitMix64 sequence seeded with the integer part of seed.
class PsdSignal {
 public:
  PsdSignal(const Spline& spline, double f0, double f1, int frequencyCount, int logarithmic,
            double seed);
  ScalarJet evaluate(double x) const;

  const std::vector<double>& frequencies() const { return frequency_; }
  const std::vector<double>& amplitudes() const { return amplitude_; }
  const std::vector<double>& phases() const { return phase_; }

  // The PSD the signal uses at frequency f (the knots' interpolation, held constant beyond the
  // first and last knot).
  static double psdAt(const std::vector<double>& f, const std::vector<double>& s, double at,
                      bool logarithmic);
  // Uniform numbers in [0, 1) of the SplitMix64 sequence (Steele, Lea, Flood 2014) for `seed`.
  static double uniform(std::uint64_t& state);

 private:
  std::vector<double> frequency_, amplitude_, phase_;
};

}  // namespace openmss::expr
