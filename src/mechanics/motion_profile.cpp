#include "mechanics/motion_profile.hpp"

#include <array>
#include <cmath>

namespace openmss::mechanics {
namespace {

// 8-point Gauss-Legendre nodes and weights on [-1, 1] (exact for degree 15).
constexpr std::array<double, 4> kNode = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                         0.9602898564975363};
constexpr std::array<double, 4> kWeight = {0.3626837833783620, 0.3137066458778873,
                                           0.2223810344533745, 0.1012285362903763};

struct Integrals {
  double f = 0.0;       // integral of f over the panel
  double moment = 0.0;  // integral of (t - s) f(s) over the panel
};

Integrals panel(const expr::Expression& f, double a, double b, double t) {
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  Integrals out;
  for (size_t k = 0; k < kNode.size(); ++k)
    for (double sign : {-1.0, 1.0}) {
      const double s = mid + sign * half * kNode[k];
      const double v = f.evaluate(nullptr, s);
      out.f += kWeight[k] * v;
      out.moment += kWeight[k] * (t - s) * v;
    }
  out.f *= half;
  out.moment *= half;
  return out;
}

// Adaptive bisection until a panel agrees with its two halves to the absolute tolerance. The
// tolerance is not halved with the panels: the rule converges so fast on smooth functions that
// few panels are ever needed, and a fixed floor keeps round-off from forcing endless splitting.
Integrals adaptive(const expr::Expression& f, double a, double b, double t, const Integrals& whole,
                   double tolerance, int depth) {
  const double m = 0.5 * (a + b);
  const Integrals left = panel(f, a, m, t), right = panel(f, m, b, t);
  Integrals sum{left.f + right.f, left.moment + right.moment};
  const bool converged = std::abs(sum.f - whole.f) <= tolerance &&
                         std::abs(sum.moment - whole.moment) <= tolerance * (1.0 + std::abs(t));
  if (converged || depth >= 30) return sum;
  const Integrals l = adaptive(f, a, m, t, left, tolerance, depth + 1);
  const Integrals r = adaptive(f, m, b, t, right, tolerance, depth + 1);
  return {l.f + r.f, l.moment + r.moment};
}

}  // namespace

expr::TimeJet motionProfile(const model::Motion& motion, double t) {
  using Form = model::Motion::Form;
  const expr::TimeJet fj = motion.function.evaluateTimeJet(t);
  if (motion.form == Form::Displacement) return fj;
  Integrals integral;
  if (t != 0.0) {
    // Tolerance relative to the size of the integrand over the interval (a coarse first pass),
    // near round-off: the motion's value is a constraint target solved to 1e-10 and better.
    Integrals coarse = panel(motion.function, 0.0, t, t);
    double scale = 0.0;
    for (int k = 0; k <= 16; ++k)
      scale = std::max(scale, std::abs(motion.function.evaluate(nullptr, t * k / 16.0)));
    const double tolerance = 1e-14 * (1.0 + scale * std::abs(t));
    integral = adaptive(motion.function, 0.0, t, t, coarse, tolerance, 0);
  }
  expr::TimeJet out;
  if (motion.form == Form::Velocity) {
    out.value = motion.icDisp + integral.f;
    out.d1 = fj.value;
    out.d2 = fj.d1;
  } else {
    out.value = motion.icDisp + motion.icVel * t + integral.moment;
    out.d1 = motion.icVel + integral.f;
    out.d2 = fj.value;
  }
  return out;
}

}  // namespace openmss::mechanics
