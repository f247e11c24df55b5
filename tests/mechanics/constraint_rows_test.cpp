// ConstraintRows (the rows of C, gamma and Phi of many equations in one pass, docs/theory.md
// §9e) on pendulum chains, the piston example and data sets with every joint, joint primitive,
// motion, COUPLER, GEAR and GCON kind, at random states (positions moved, Euler parameters
// normalised, random velocities):
//  (1) its rows are MultibodySystem::constraintRowEntries' (same numbers, same structure);
//  (2) gamma is f'' minus constraintRates' second derivative;
//  (3) independent truth: gamma against central differences of C(q(s)) u along the path the
//      bodies follow with their current velocities (r + s v, A exp(s [w])), plus the motion's
//      f'' from central differences of f in time;
//  (4) values(): Phi is constraintValue, nu the motion's f'.

#include "mechanics/constraint_rows.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "language/reader.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "support/part_per_element.hpp"
#include "support/random_state.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;

model::Model buildText(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "rows.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

model::Model buildFile(const std::string& path) {
  language::Dataset ds;
  Diagnostics d;
  EXPECT_TRUE(language::readDatasetFile(path, ds, d)) << path;
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << path;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

// A pendulum chain of unit links as the benchmark builds it (bench/model_generators.hpp, not
// linked into the tests): planar, every hinge about ground z; or spatial, the hinges
// alternating between ground z and ground x, the chain tilted out of every plane.
std::string chainDataSet(int links, bool spatial) {
  const double s = std::sin(0.1), c = std::cos(0.1);
  const double dir[3] = {spatial ? s / std::sqrt(2.0) : s, -c, spatial ? s / std::sqrt(2.0) : 0.0};
  std::ostringstream o;
  o.precision(17);
  o << "chain\nPART/1, GROUND\nMARKER/11, PART=1\n";
  auto point = [&](double along) {
    std::ostringstream p;
    p.precision(17);
    p << along * dir[0] << "," << along * dir[1] << "," << along * dir[2];
    return p.str();
  };
  auto axisPoint = [&](double along, bool xAxis) {
    std::ostringstream p;
    p.precision(17);
    p << along * dir[0] + (xAxis ? 1.0 : 0.0) << "," << along * dir[1] << ","
      << along * dir[2] + (xAxis ? 0.0 : 1.0);
    return p.str();
  };
  for (int i = 0; i < links; ++i) {
    const int part = i + 2;
    const bool xAxis = spatial && i % 2 == 1;
    o << "PART/" << part << ", MASS=1, CM=" << 10 * part << ", IP=0.08,0.08,0.0002\n"
      << "MARKER/" << 10 * part << ", PART=" << part << ", QP=" << point(i + 0.5)
      << "\n"
      // Distal end (the next hinge's J marker) and proximal end (this hinge's I marker).
      << "MARKER/" << 10 * part + 1 << ", PART=" << part << ", QP=" << point(i + 1.0)
      << ", ZP=" << axisPoint(i + 1.0, spatial && i % 2 == 0) << "\n"
      << "MARKER/" << 10 * part + 2 << ", PART=" << part << ", QP=" << point(i)
      << ", ZP=" << axisPoint(i, xAxis) << "\n";
    const int jMarker = i == 0 ? 11 : 10 * (part - 1) + 1;
    o << "JOINT/" << i + 1 << ", REVOLUTE, I=" << 10 * part + 2 << ", J=" << jMarker << "\n";
  }
  o << "END\n";
  return o.str();
}

// One part per element, each generically placed; even elements hold their part to ground,
// odd ones to the previous part, so both sides of an equation move.
std::string everyKindDataSet() {
  const std::vector<std::string> elements = {
      "JOINT/1, REVOLUTE",
      "JOINT/2, SPHERICAL",
      "JOINT/3, UNIVERSAL",
      "JOINT/4, HOOKE",
      "JOINT/5, TRANSLATIONAL",
      "JOINT/6, CYLINDRICAL",
      "JOINT/7, FIXED",
      "JOINT/8, CONVEL",
      "JOINT/9, PLANAR",
      "JOINT/10, RACKPIN, PD=0.8",
      "JOINT/11, SCREW, PITCH=0.05",
      "JPRIM/12, ATPOINT",
      "JPRIM/13, INLINE",
      "JPRIM/14, INPLANE",
      "JPRIM/15, ORIENTATION",
      "JPRIM/16, PARALLEL_AXES",
      "JPRIM/17, PERPENDICULAR",
      "MOTION/18, X, FUNCTION=0.2*SIN(TIME)",
      "MOTION/19, Y, FUNCTION=0.1*TIME**2",
      "MOTION/20, Z, FUNCTION=0.3*COS(2*TIME)",
      "MOTION/21, B1, FUNCTION=0.2*SIN(TIME)",
      "MOTION/22, B2, FUNCTION=0.2*SIN(1.5*TIME)",
      "MOTION/23, B3, FUNCTION=0.4*TIME",
      "MOTION/24, B3, VELOCITY, FUNCTION=COS(TIME)",
      "MOTION/25, Z, ACCELERATION, ICVEL=0.5, FUNCTION=COS(TIME)",
  };
  // Motions on joints: a rotation on the revolute, a translation on the translational joint.
  return test::partPerElementDataSet("every kind", elements,
                                     "MOTION/30, JOINT=1, FUNCTION=0.3*TIME**2\n"
                                     "MOTION/31, JOINT=5, FUNCTION=0.2*SIN(TIME)\n");
}

// COUPLER, GEAR and GCON (the data sets of coupling_test.cpp and general_constraint_test.cpp).
const char* kCoupled =
    "couplings\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1, QP=1,0,0\n"
    "MARKER/12, PART=1, QP=0,2,0, ZP=1,2,0\n"
    "MARKER/13, PART=1, QP=0.1,0,0, ZP=0.1,1,0\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2, QP=0.3,0,0\n"
    "MARKER/21, PART=2\n"
    "PART/3, MASS=1, CM=30, IP=1,1,1\n"
    "MARKER/30, PART=3, QP=1.2,0.1,0\n"
    "MARKER/31, PART=3, QP=1,0,0\n"
    "PART/4, MASS=2, CM=40, IP=1,1,1\n"
    "MARKER/40, PART=4, QP=0.5,2,0.1\n"
    "MARKER/41, PART=4, QP=0,2,0, ZP=1,2,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "JOINT/2, REVOLUTE, I=31, J=11\n"
    "JOINT/3, TRANSLATIONAL, I=41, J=12\n"
    "COUPLER/1, JOINTS=1,2,3, TYPE=R,R,T, SCALES=0.5,-0.25\n"
    "GEAR/2, JOINTS=1,2, CV=13\n"
    "MOTION/1, JOINT=1, FUNCTION=TIME\n"
    "MOTION/2, JOINT=3, FUNCTION=0.4*SIN(TIME)\n"
    "GCON/1, I=20, FUNCTION=DX(20,10)**2+DY(20,10)**2-4+0.3*DZ(20,11,11)\n"
    "GCON/2, I=21, FUNCTION=AZ(21,31)+0.3*SIN(AX(21,31))-0.2*AY(31,21)*PSI(21,11)\n"
    "GCON/3, FUNCTION=DM(21,30)*COS(YAW(21,30))-PITCH(31)+ROLL(21,31)*THETA(30,11)"
    "+PHI(31,21)**2\n"
    "END\n";

// The generalised velocity of the columns of C: (v, w_body) per body.
double velocityOf(const MultibodySystem& s, const Eigen::VectorXd& y, int column) {
  const int o = s.layout().body(column / 6);
  const int dir = column % 6;
  return dir < 3 ? y(o + L::kV + dir) : y(o + L::kW + dir - 3);
}

// C_k(q) u at y, from constraintRowEntries (independent of ConstraintRows).
double rowTimesVelocity(const MultibodySystem& s, int k, const Eigen::VectorXd& y) {
  std::vector<int> cols;
  std::vector<double> vals;
  s.constraintRowEntries(k, y.data(), cols, vals);
  double sum = 0.0;
  for (size_t i = 0; i < cols.size(); ++i) sum += vals[i] * velocityOf(s, y, cols[i]);
  return sum;
}

// The state moved by s along the path with the current velocities and zero accelerations.
Eigen::VectorXd moved(const MultibodySystem& sys, const Eigen::VectorXd& y, double s) {
  Eigen::VectorXd z = y;
  for (int b = 0; b < sys.layout().bodies; ++b) {
    const int o = sys.layout().body(b);
    z.segment<3>(o + L::kR) += s * y.segment<3>(o + L::kV);
    const Eigen::Vector3d w = y.segment<3>(o + L::kW);
    if (w.norm() > 0.0) z = testing::turned(z, o, w / w.norm(), s * w.norm());
  }
  return z;
}

struct Worst {
  double rows = 0.0, gamma = 0.0, truth = 0.0;
};

void checkAt(const MultibodySystem& s, const model::Model& m, const std::vector<int>& rows,
             const Eigen::VectorXd& y, double t, Worst& worst) {
  const ConstraintRows cr(s, rows);
  const auto& eqs = s.constraints().equations();
  ASSERT_EQ(cr.count(), static_cast<int>(rows.size()));
  std::vector<double> values(cr.columns().size(), -1.0), gamma(rows.size(), -1.0);
  cr.evaluate(t, y.data(), values.data(), gamma.data());
  std::vector<double> phi(rows.size()), nu(rows.size());
  cr.values(t, y.data(), phi.data(), nu.data());
  std::vector<int> cols;
  std::vector<double> vals;
  for (int r = 0; r < cr.count(); ++r) {
    const int k = rows[static_cast<size_t>(r)];
    const std::string what = s.constraints().describe(k, m);
    const ConstraintEquation& eq = eqs[static_cast<size_t>(k)];
    // (1) The row: the structure is the one fixed at construction, the numbers those of
    // constraintRowEntries (the same operations on the same frames: equal to round-off).
    s.constraintRowEntries(k, y.data(), cols, vals);
    const int first = cr.start()[static_cast<size_t>(r)];
    ASSERT_EQ(cr.start()[static_cast<size_t>(r) + 1] - first, static_cast<int>(cols.size()))
        << what;
    for (size_t i = 0; i < cols.size(); ++i) {
      EXPECT_EQ(cr.columns()[static_cast<size_t>(first) + i], cols[i]) << what;
      const double got = values[static_cast<size_t>(first) + i];
      const double error = std::abs(got - vals[i]) / std::max(1.0, std::abs(vals[i]));
      worst.rows = std::max(worst.rows, error);
      EXPECT_LE(error, 1e-14) << what << " column " << cols[i] << ": " << got << " vs " << vals[i];
    }
    // (2) gamma against constraintRates (body-axes products there, ground cross products
    // here: equal to a few units of round-off on O(1) numbers).
    double rate = 0.0, second = 0.0;
    s.constraintRates(k, y.data(), &rate, &second);
    const double f2 = eq.motion >= 0 ? s.motionJet(k, t).d2 : 0.0;
    const double gammaError =
        std::abs(gamma[static_cast<size_t>(r)] - (f2 - second)) / (1.0 + std::abs(second));
    worst.gamma = std::max(worst.gamma, gammaError);
    EXPECT_LE(gammaError, 1e-13) << what << ": " << gamma[static_cast<size_t>(r)] << " vs "
                                 << f2 - second;
    // (3) Independent truth: d/ds (C(q(s)) u) by central differences along the path,
    // Richardson-extrapolated from h = 1e-4 and h/2 (truncation ~h^4 |fifth derivative|,
    // round-off ~1e-16/h ~ 1e-12 relative; GCON/3 of the couplings data set, near a singular
    // angle with gamma ~ 1.5e3, is where plain h^2 differences lose digits); the motion's
    // f'' by the five-point second difference of f in time, h = 1e-2 (truncation
    // ~h^4 |f^(6)| / 90 ~ 1e-9 here; round-off ~1e-14/h^2 ~ 1e-10 with the 1e-14 quadrature
    // of VELOCITY/ACCELERATION motions). 1e-6 relative leaves a wide margin over both.
    auto centralDifference = [&](double h) {
      return (rowTimesVelocity(s, k, moved(s, y, h)) - rowTimesVelocity(s, k, moved(s, y, -h))) /
             (2.0 * h);
    };
    const double h = 1e-4;
    const double dCu = (4.0 * centralDifference(h / 2) - centralDifference(h)) / 3.0;
    double f2Truth = 0.0;
    if (eq.motion >= 0) {
      const double ht = 1e-2;
      auto f = [&](double dt) { return s.motionJet(k, t + dt).value; };
      f2Truth = (-f(2 * ht) + 16.0 * f(ht) - 30.0 * f(0.0) + 16.0 * f(-ht) - f(-2 * ht)) /
                (12.0 * ht * ht);
    }
    const double truth = f2Truth - dCu;
    const double truthError =
        std::abs(gamma[static_cast<size_t>(r)] - truth) / (1.0 + std::abs(truth));
    worst.truth = std::max(worst.truth, truthError);
    EXPECT_LE(truthError, 1e-6) << what << ": " << gamma[static_cast<size_t>(r)] << " vs " << truth;
    // (4) Phi and nu.
    EXPECT_EQ(phi[static_cast<size_t>(r)], s.constraintValue(k, t, y.data())) << what;
    EXPECT_EQ(nu[static_cast<size_t>(r)], eq.motion >= 0 ? s.motionJet(k, t).d1 : 0.0) << what;
  }
}

// Every equation in order, and a reordered subset (every third left out, the rest reversed:
// groups of equations sharing markers form differently).
void checkModel(const model::Model& m, const char* name) {
  const MultibodySystem s(m);
  std::vector<int> all, subset;
  for (int k = 0; k < s.constraints().size(); ++k) {
    all.push_back(k);
    if (k % 3 != 1) subset.insert(subset.begin(), k);
  }
  std::mt19937 rng(2024);
  Worst worst;
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::VectorXd y = testing::randomState(s, rng);
    const double t = 0.37 + 0.5 * trial;
    checkAt(s, m, all, y, t, worst);
    checkAt(s, m, subset, y, t, worst);
  }
  std::printf(
      "%s (%d equations): rows vs constraintRowEntries %.1e, gamma vs constraintRates "
      "%.1e, gamma vs central differences %.1e\n",
      name, s.constraints().size(), worst.rows, worst.gamma, worst.truth);
}

TEST(ConstraintRows, PlanarChain) { checkModel(buildText(chainDataSet(12, false)), "planar"); }

TEST(ConstraintRows, SpatialChain) { checkModel(buildText(chainDataSet(12, true)), "spatial"); }

TEST(ConstraintRows, PistonExample) {
  checkModel(buildFile(OPENMSS_SOURCE_DIR "/examples/piston/piston.adm"), "piston");
}

TEST(ConstraintRows, EveryJointPrimitiveAndMotionKind) {
  checkModel(buildText(everyKindDataSet()), "every kind");
}

TEST(ConstraintRows, CouplerGearAndGcon) { checkModel(buildText(kCoupled), "couplings"); }

// Euler parameters off the unit sphere (an integrator's state between projections): the
// ground-axes jets (omega = A w / |e|^2) still give constraintRates' gamma, and the rows
// constraintRowEntries'.
TEST(ConstraintRows, UnnormalisedEulerParameters) {
  const model::Model m = buildText(everyKindDataSet());
  const MultibodySystem s(m);
  std::vector<int> all;
  for (int k = 0; k < s.constraints().size(); ++k) all.push_back(k);
  const ConstraintRows cr(s, all);
  std::mt19937 rng(9);
  Eigen::VectorXd y = testing::randomState(s, rng);
  for (int b = 0; b < s.layout().bodies; ++b)
    y.segment<4>(s.layout().body(b) + L::kE) *= 1.0 + 0.01 * (b % 5 - 2);
  std::vector<double> values(cr.columns().size()), gamma(all.size());
  cr.evaluate(0.4, y.data(), values.data(), gamma.data());
  std::vector<int> cols;
  std::vector<double> vals;
  for (int r = 0; r < cr.count(); ++r) {
    s.constraintRowEntries(r, y.data(), cols, vals);
    for (size_t i = 0; i < cols.size(); ++i)
      EXPECT_EQ(values[static_cast<size_t>(cr.start()[static_cast<size_t>(r)]) + i], vals[i]);
    double first = 0.0, second = 0.0;
    s.constraintRates(r, y.data(), &first, &second);
    const double f2 = s.constraints().equations()[static_cast<size_t>(r)].motion >= 0
                          ? s.motionJet(r, 0.4).d2
                          : 0.0;
    EXPECT_NEAR(gamma[static_cast<size_t>(r)], f2 - second, 1e-13 * (1.0 + std::abs(second)))
        << s.constraints().describe(r, m);
  }
}

// Nothing of the scratch leaks from one call into the next: evaluating at another state and
// back gives the same numbers, bit for bit.
TEST(ConstraintRows, CallsDoNotDependOnEachOther) {
  const model::Model m = buildText(chainDataSet(5, true));
  const MultibodySystem s(m);
  std::vector<int> all;
  for (int k = 0; k < s.constraints().size(); ++k) all.push_back(k);
  const ConstraintRows cr(s, all);
  std::mt19937 rng(5);
  const Eigen::VectorXd y1 = testing::randomState(s, rng), y2 = testing::randomState(s, rng);
  std::vector<double> v1(cr.columns().size()), g1(all.size()), v2 = v1, g2 = g1, p(g1), n(g1);
  cr.evaluate(0.1, y1.data(), v1.data(), g1.data());
  cr.values(0.1, y2.data(), p.data(), n.data());
  cr.evaluate(0.2, y2.data(), v2.data(), g2.data());
  cr.evaluate(0.1, y1.data(), v2.data(), g2.data());
  EXPECT_EQ(v1, v2);
  EXPECT_EQ(g1, g2);
}

TEST(ConstraintRows, RowsAloneAndGammaAloneAreTheSameNumbers) {
  // Either output may be left out (IndexOneDynamics::projectAndEvaluate: C before the velocity
  // projection, gamma after it): what is computed is exactly what evaluate() computes with
  // both, on every joint, primitive and motion kind and on the couplings.
  for (const std::string& text : {everyKindDataSet(), std::string(kCoupled)}) {
    const model::Model m = buildText(text);
    const MultibodySystem s(m);
    std::vector<int> all;
    for (int k = 0; k < s.constraints().size(); ++k) all.push_back(k);
    const ConstraintRows cr(s, all);
    std::mt19937 rng(9);
    for (int trial = 0; trial < 3; ++trial) {
      const Eigen::VectorXd y = testing::randomState(s, rng);
      std::vector<double> values(cr.columns().size()), gamma(all.size());
      cr.evaluate(0.4, y.data(), values.data(), gamma.data());
      std::vector<double> valuesAlone(values.size(), -1.0), gammaAlone(gamma.size(), -1.0);
      cr.evaluate(0.4, y.data(), valuesAlone.data(), nullptr);
      cr.evaluate(0.4, y.data(), nullptr, gammaAlone.data());
      EXPECT_EQ(valuesAlone, values);
      EXPECT_EQ(gammaAlone, gamma);
    }
  }
}

}  // namespace
}  // namespace openmss::mechanics
