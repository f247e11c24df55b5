// HHT and NEWMARK on the undamped oscillator q'' = -w^2 q, written as the second-order DAE the
// multibody equations are (kinematic row q' = u, force balance u' + w^2 q = 0). At a fixed step
// h the method is a linear map of (q, u, q'') whose amplification matrix follows from the
// textbook HHT-alpha recurrences alone (built here independently of the integrator): its
// principal eigenvalue pair has modulus rho < 1, and the energy after N steps is E0 rho^(2N)
// up to the small oscillation of a non-normal map. That is the documented numerical
// dissipation the integrator must reproduce: no more (a bug adding damping), no less.
#include "solvers/hht_integrator.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <string>

namespace openmss::solvers {
namespace {

constexpr double kOmega = 2.0;
// The energy of a non-normal linear map oscillates about the envelope rho^(2N) within a
// period; sampled after N steps it stays within this share of it (measured 2.7e-3 at w h = 0.5,
// 1e-5 at w h = 0.1).
constexpr double kEnvelope = 5e-3;

// Energy after `steps` applications of the map to the consistent start (1, 0, -w^2), over E0.
double mappedEnergyRatio(const Eigen::Matrix3d& map, long steps) {
  Eigen::Vector3d x(1.0, 0.0, -kOmega * kOmega);
  for (long k = 0; k < steps; ++k) x = map * x;
  return (x(1) * x(1) + kOmega * kOmega * x(0) * x(0)) / (kOmega * kOmega);
}

class SecondOrderOscillator : public DaeProblem {
 public:
  int size() const override { return 2; }
  void residual(double, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override {
    g.resize(2);
    g(0) = yp(0) - y(1);
    g(1) = yp(1) + kOmega * kOmega * y(0);
  }
  void newtonMatrix(double, const Eigen::VectorXd&, const Eigen::VectorXd&, double cj,
                    Eigen::MatrixXd& jac) override {
    jac.resize(2, 2);
    jac << cj, -1.0, kOmega * kOmega, cj;
  }
  bool differential(int) const override { return true; }
  bool errorControlled(int i) const override { return i == 0; }
  int rowScaleExponent(int) const override { return 0; }
  int unknownScaleExponent(int) const override { return 0; }
  Role role(int i) const override { return i == 0 ? Role::Position : Role::Velocity; }
  std::string equationName(int row) const override { return "row " + std::to_string(row); }
  std::string variableName(int i) const override { return "y" + std::to_string(i); }
};

// The HHT-alpha map (d, v, a)_n -> (d, v, a)_n+1 for d'' = -w^2 d at step h:
//   a+ + w^2 ((1 + alpha) d+ - alpha d) = 0
//   d+ = d + h v + h^2 ((1/2 - beta) a + beta a+),  v+ = v + h ((1 - gamma) a + gamma a+).
Eigen::Matrix3d amplification(double h, double alpha, double beta, double gamma) {
  const double w2 = kOmega * kOmega;
  Eigen::Matrix3d map;
  for (int c = 0; c < 3; ++c) {
    Eigen::Vector3d x = Eigen::Vector3d::Unit(c);
    const double dHat = x(0) + h * x(1) + h * h * (0.5 - beta) * x(2);
    const double aNew =
        -w2 * ((1.0 + alpha) * dHat - alpha * x(0)) / (1.0 + (1.0 + alpha) * w2 * h * h * beta);
    map(0, c) = dHat + h * h * beta * aNew;
    map(1, c) = x(1) + h * ((1.0 - gamma) * x(2) + gamma * aNew);
    map(2, c) = aNew;
  }
  return map;
}

double principalModulus(const Eigen::Matrix3d& map) {
  Eigen::EigenSolver<Eigen::Matrix3d> eig(map);
  double best = 0.0;
  for (int k = 0; k < 3; ++k)  // the oscillating pair (the third root is the spurious one)
    if (std::abs(eig.eigenvalues()(k).imag()) > 0)
      best = std::max(best, std::abs(eig.eigenvalues()(k)));
  return best;
}

struct Outcome {
  double energyRatio;
  long steps;
};

Outcome integrate(const HhtSettings& base, double h, long steps) {
  SecondOrderOscillator problem;
  HhtSettings s = base;
  s.error = 1e3;  // no step-size control: the fixed step h
  s.hinit = h;
  s.hmax = h;
  HhtIntegrator hht(problem, s);
  const Eigen::Vector2d y0(1.0, 0.0), yp0(0.0, -kOmega * kOmega);
  hht.start(0.0, y0, yp0);
  EXPECT_TRUE(hht.advanceTo(h * static_cast<double>(steps))) << hht.failure().reason;
  auto energy = [](const Eigen::VectorXd& y) {
    return 0.5 * (y(1) * y(1) + kOmega * kOmega * y(0) * y(0));
  };
  return {energy(hht.y()) / energy(y0), hht.statistics().steps};
}

TEST(HhtIntegrator, TrapezoidalNewmarkConservesEnergy) {
  // alpha = 0, beta = 1/4, gamma = 1/2: the map is a rotation in the energy norm.
  const double h = 0.05;
  const Outcome r = integrate(HhtSettings::hht(0.0), h, 400);
  EXPECT_EQ(r.steps, 400);
  EXPECT_NEAR(r.energyRatio, 1.0, 1e-10);
}

TEST(HhtIntegrator, DissipatesExactlyAsTheHhtAmplificationMatrixPredicts) {
  for (const double alpha : {-0.05, -0.1, -0.3, -1.0 / 3.0}) {
    const HhtSettings s = HhtSettings::hht(alpha);
    const double h = 0.25;   // w h = 0.5: about 12.6 steps per period, visible dissipation
    const long steps = 240;  // about 19 periods
    const Eigen::Matrix3d map = amplification(h, alpha, s.beta, s.gamma);
    const double rho = principalModulus(map);
    const double expected = std::pow(rho, 2.0 * static_cast<double>(steps));
    const Outcome r = integrate(s, h, steps);
    std::printf("alpha %.4f: rho %.10f, energy ratio %.6f, envelope %.6f, map %.10f\n", alpha, rho,
                r.energyRatio, expected, mappedEnergyRatio(map, steps));
    EXPECT_LT(rho, 1.0);
    // The recurrence itself, step for step: only round-off and the corrector tolerance differ.
    EXPECT_NEAR(r.energyRatio, mappedEnergyRatio(map, steps), 1e-8);
    EXPECT_LT(expected, 1.0 - 10.0 * kEnvelope);  // the dissipation is far above the tolerance
    EXPECT_NEAR(r.energyRatio / expected, 1.0, kEnvelope) << "alpha " << alpha;
  }
}

TEST(HhtIntegrator, NewmarkWithGammaAboveOneHalfDissipatesAsPredicted) {
  HhtSettings s;
  s.alpha = 0.0;
  s.beta = 0.36;
  s.gamma = 0.7;
  const double h = 0.05;
  const long steps = 300;
  const double rho = principalModulus(amplification(h, 0.0, s.beta, s.gamma));
  const Outcome r = integrate(s, h, steps);
  EXPECT_NEAR(r.energyRatio / std::pow(rho, 2.0 * static_cast<double>(steps)), 1.0, kEnvelope);
  EXPECT_LT(r.energyRatio, 0.9);  // visibly damped: gamma > 1/2 costs accuracy
}

TEST(HhtIntegrator, ConvergesAtSecondOrderUnderErrorControl) {
  // Against the closed form q = cos(w t): halving ERROR by 8 roughly halves the step and
  // quarters the error (second order, step ~ ERROR^(1/3)).
  SecondOrderOscillator problem;
  double errors[2];
  int k = 0;
  for (const double tol : {1e-4, 1e-7}) {
    HhtSettings s = HhtSettings::hht(-0.3);
    s.error = tol;
    s.hinit = 1e-3;
    HhtIntegrator hht(problem, s);
    hht.start(0.0, Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, -kOmega * kOmega));
    ASSERT_TRUE(hht.advanceTo(2.0));
    errors[k++] = std::abs(hht.y()(0) - std::cos(kOmega * 2.0));
  }
  std::printf("global error at ERROR=1e-4: %.2e, at 1e-7: %.2e\n", errors[0], errors[1]);
  EXPECT_LT(errors[0], 1e-2);
  EXPECT_LT(errors[1], errors[0] / 50.0);
}

}  // namespace
}  // namespace openmss::solvers
