// Kinematic analysis of two planar mechanisms driven by a MOTION, against closed forms:
// the four-bar of examples/fourbar (crank-rocker) and a slider-crank with an offset slider
// body. Positions, velocities and accelerations are compared with the loop-closure solution
// and its analytic derivatives; the joint and motion reactions with an inverse-dynamics
// computation written here by hand (Newton-Euler for each planar link, solved as one linear
// system for the pin forces, the slider's normal force and moment, and the drive torque).
// Everything goes through the library API at full precision (not the 6-digit .req).
//
// Tolerances: 1e-9 relative to the quantity's scale over the run (pointwise relative error is
// meaningless at zero crossings). The solver's positions satisfy the constraints to 1e-13 and
// the velocity and acceleration solves are direct, so agreement is ~1e-12 in practice.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/request_values.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"

namespace openmss::analysis {
namespace {

using mechanics::MultibodySystem;
using mechanics::StateLayout;
using V2 = Eigen::Vector2d;

constexpr double kGravity = 9.80665;

V2 e(double angle) { return {std::cos(angle), std::sin(angle)}; }
V2 perp(const V2& v) { return {-v.y(), v.x()}; }  // rotated +90 degrees
double cross2(const V2& a, const V2& b) { return a.x() * b.y() - a.y() * b.x(); }

// ---- planar inverse dynamics ---------------------------------------------------------------

struct PlanarBody {
  double mass, izz;
  V2 cm, acc;    // CM position and acceleration
  double alpha;  // angular acceleration
};

// Unknown reactions: a pin (force on body `a` from body `b` at P; b = -1 is ground), a slider
// on ground (force N along n and moment M on body a, at P), a drive torque on body a.
struct Pin {
  int a, b;
  V2 p;
};
struct Slider {
  int a;
  V2 p, n;
};

struct Reactions {
  std::vector<V2> pins;
  double sliderForce = 0.0, sliderMoment = 0.0, torque = 0.0;
};

Reactions inverseDynamics(const std::vector<PlanarBody>& bodies, const std::vector<Pin>& pins,
                          const std::vector<Slider>& sliders, int driven) {
  const int nb = static_cast<int>(bodies.size());
  const int nu = 2 * static_cast<int>(pins.size()) + 2 * static_cast<int>(sliders.size()) + 1;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3 * nb, nu);
  Eigen::VectorXd rhs(3 * nb);
  for (int b = 0; b < nb; ++b) {
    // m acc - m g = sum F ; I alpha = sum M (about the CM).
    rhs.segment<2>(3 * b) = bodies[b].mass * (bodies[b].acc + V2(0.0, kGravity));
    rhs(3 * b + 2) = bodies[b].izz * bodies[b].alpha;
  }
  int col = 0;
  auto addForce = [&](int body, const V2& p, int c, const V2& direction, double sign) {
    if (body < 0) return;
    a.block<2, 1>(3 * body, c) += sign * direction;
    a(3 * body + 2, c) += sign * cross2(p - bodies[body].cm, direction);
  };
  for (const Pin& pin : pins) {
    for (int k = 0; k < 2; ++k) {
      const V2 unit = k == 0 ? V2(1, 0) : V2(0, 1);
      addForce(pin.a, pin.p, col + k, unit, 1.0);
      addForce(pin.b, pin.p, col + k, unit, -1.0);
    }
    col += 2;
  }
  for (const Slider& s : sliders) {
    addForce(s.a, s.p, col, s.n, 1.0);
    a(3 * s.a + 2, col + 1) += 1.0;
    col += 2;
  }
  a(3 * driven + 2, col) = 1.0;
  const Eigen::VectorXd u = a.fullPivLu().solve(rhs);
  EXPECT_LT((a * u - rhs).norm(), 1e-12 * (1.0 + rhs.norm()));
  Reactions r;
  for (size_t k = 0; k < pins.size(); ++k) r.pins.push_back(u.segment<2>(2 * static_cast<int>(k)));
  const int s0 = 2 * static_cast<int>(pins.size());
  if (!sliders.empty()) {
    r.sliderForce = u(s0);
    r.sliderMoment = u(s0 + 1);
  }
  r.torque = u(nu - 1);
  return r;
}

// ---- solver access -------------------------------------------------------------------------

model::Model build(const std::string& text, const std::string& file) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, file, ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

std::string readFile(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  EXPECT_NE(f, nullptr) << path;
  std::string text;
  if (!f) return text;
  char buffer[4096];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
  std::fclose(f);
  return text;
}

// Reaction component (2 Fx, 3 Fy, 4 Fz, 6 Tx, 7 Ty, 8 Tz; ground axes) of an element on its I
// marker's part, as the JOINT()/MOTION() functions return it.
double reaction(const MultibodySystem& s, model::MeasureKind kind, int element, int component,
                const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
  model::Measure ms;
  ms.kind = kind;
  ms.element = element;
  ms.component = component;
  return measureValue(s, ms, 0.0, y, yp);
}

// Kinematic march with the library's solves; `check` sees each solved state.
template <class Check>
void march(MultibodySystem& s, double tEnd, double dt, Check check) {
  Eigen::VectorXd y = s.initialState(), yp;
  mechanics::removeRedundantConstraints(s, y);
  const int steps = static_cast<int>(std::lround(tEnd / dt));
  for (int n = 0; n <= steps; ++n) {
    const double t = n * dt;
    if (n > 0)
      for (int b = 0; b < s.layout().bodies; ++b) {
        const int o = s.layout().body(b);
        y.segment<7>(o) += dt * yp.segment<7>(o);
        y.segment<4>(o + StateLayout::kE).normalize();
      }
    ASSERT_TRUE(mechanics::assemblePositions(s, t, y, 1e-14, 30).converged) << t;
    mechanics::solveVelocities(s, t, y);
    ASSERT_TRUE(mechanics::solveAccelerations(s, t, y, yp)) << t;
    check(t, y, yp);
  }
}

double wz(const MultibodySystem& s, int body, const Eigen::VectorXd& y) {
  return y(s.layout().body(body) + StateLayout::kW + 2);
}
double alphaZ(const MultibodySystem& s, int body, const Eigen::VectorXd& yp) {
  return yp(s.layout().body(body) + StateLayout::kW + 2);
}
V2 cmPos(const MultibodySystem& s, int body, const Eigen::VectorXd& y) {
  return y.segment<2>(s.layout().body(body) + StateLayout::kR);
}
V2 cmVel(const MultibodySystem& s, int body, const Eigen::VectorXd& y) {
  return y.segment<2>(s.layout().body(body) + StateLayout::kV);
}
V2 cmAcc(const MultibodySystem& s, int body, const Eigen::VectorXd& yp) {
  return yp.segment<2>(s.layout().body(body) + StateLayout::kV);
}

#define EXPECT_SCALED(actual, expected, scale) \
  EXPECT_NEAR(actual, expected, 1e-9 * (scale)) << "t = " << t

// ---- four-bar ------------------------------------------------------------------------------

TEST(KinematicsClosedForm, FourBarMatchesLoopClosureAndNewtonEuler) {
  const model::Model m =
      build(readFile(OPENMSS_SOURCE_DIR "/examples/fourbar/fourbar.adm"), "fourbar.adm");
  MultibodySystem s(m);
  const double a = 0.1, b = 0.35, c = 0.3;
  const V2 d(0.4, 0.0);
  const double massCrank = 1, massCoupler = 2, massRocker = 1.5;
  const double izzCrank = 0.001, izzCoupler = 0.02, izzRocker = 0.012;
  // Scales: |omega| <= ~20 rad/s, |alpha| <= ~1e3, forces ~1e2 N.
  const double sPos = 0.5, sVel = 2.0, sAcc = 100.0, sW = 20.0, sAlpha = 1000.0, sF = 200.0;
  int checked = 0;
  march(s, 2.0, 0.01, [&](double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
    const double th = 1.0 + 6.0 * t + 0.5 * std::sin(4.0 * t);
    const double w2 = 6.0 + 2.0 * std::cos(4.0 * t);
    const double a2 = -8.0 * std::sin(4.0 * t);
    // Positions: C is the upper intersection of the circles (A, b) and (D, c).
    const V2 pa = a * e(th);
    const V2 ad = d - pa;
    const double len = ad.norm();
    const double along = (b * b - c * c + len * len) / (2.0 * len);
    const double h = std::sqrt(b * b - along * along);
    const V2 u = ad / len;
    const V2 pc = pa + along * u + h * perp(u);
    const double p3 = std::atan2(pc.y() - pa.y(), pc.x() - pa.x());
    const double p4 = std::atan2(pc.y() - d.y(), pc.x() - d.x());
    // Velocities and accelerations from the loop a e2 + b e3 - c e4 = d, differentiated.
    const double w3 = -a * w2 * std::sin(p4 - th) / (b * std::sin(p4 - p3));
    const double w4 = a * w2 * std::sin(p3 - th) / (c * std::sin(p3 - p4));
    const V2 rr =
        a * (a2 * perp(e(th)) - w2 * w2 * e(th)) - b * w3 * w3 * e(p3) + c * w4 * w4 * e(p4);
    const double al3 = -rr.dot(e(p4)) / (b * std::sin(p4 - p3));
    const double al4 = rr.dot(e(p3)) / (c * std::sin(p3 - p4));
    const V2 accA = a * (a2 * perp(e(th)) - w2 * w2 * e(th));
    const V2 accC = c * (al4 * perp(e(p4)) - w4 * w4 * e(p4));
    const V2 velC = c * w4 * perp(e(p4));

    // Kinematics: rocker pin C (marker 41), body angular velocities and accelerations.
    const auto mc = mechanics::markerState(m, s.layout(), m.markerIndex.at(41), y.data());
    EXPECT_SCALED(mc.p.x, pc.x(), sPos);
    EXPECT_SCALED(mc.p.y, pc.y(), sPos);
    EXPECT_SCALED(mc.pdot.x, velC.x(), sVel);
    EXPECT_SCALED(mc.pdot.y, velC.y(), sVel);
    EXPECT_SCALED(wz(s, 0, y), w2, sW);
    EXPECT_SCALED(wz(s, 1, y), w3, sW);
    EXPECT_SCALED(wz(s, 2, y), w4, sW);
    EXPECT_SCALED(alphaZ(s, 0, yp), a2, sAlpha);
    EXPECT_SCALED(alphaZ(s, 1, yp), al3, sAlpha);
    EXPECT_SCALED(alphaZ(s, 2, yp), al4, sAlpha);
    const V2 accCoupler = accA + 0.5 * b * (al3 * perp(e(p3)) - w3 * w3 * e(p3));
    EXPECT_SCALED(cmAcc(s, 1, yp).x(), accCoupler.x(), sAcc);
    EXPECT_SCALED(cmAcc(s, 1, yp).y(), accCoupler.y(), sAcc);
    EXPECT_SCALED(cmAcc(s, 2, yp).x(), 0.5 * accC.x(), sAcc);
    EXPECT_SCALED(cmPos(s, 2, y).x(), 0.5 * (pc + d).x(), sPos);
    EXPECT_SCALED(cmVel(s, 2, y).y(), 0.5 * velC.y(), sVel);

    // Reactions: bodies crank 0, coupler 1, rocker 2.
    const std::vector<PlanarBody> bodies = {
        {massCrank, izzCrank, 0.5 * pa, 0.5 * accA, a2},
        {massCoupler, izzCoupler, 0.5 * (pa + pc), accCoupler, al3},
        {massRocker, izzRocker, 0.5 * (pc + d), 0.5 * accC, al4}};
    // JOINT/1 crank on ground at O; /2 coupler(I) on crank at A; /3 rocker(I) on coupler at C;
    // /4 rocker(I) on ground at D; the drive torque on the crank.
    const std::vector<Pin> pins = {{0, -1, V2(0, 0)}, {1, 0, pa}, {2, 1, pc}, {2, -1, d}};
    const Reactions r = inverseDynamics(bodies, pins, {}, 0);
    using K = model::MeasureKind;
    for (int j = 0; j < 4; ++j) {
      EXPECT_SCALED(reaction(s, K::JointForce, j, 2, y, yp), r.pins[j].x(), sF) << " joint " << j;
      EXPECT_SCALED(reaction(s, K::JointForce, j, 3, y, yp), r.pins[j].y(), sF) << " joint " << j;
      // Nothing acts out of the plane, and a pin carries no torque about its axis.
      EXPECT_SCALED(reaction(s, K::JointForce, j, 4, y, yp), 0.0, sF) << " joint " << j;
      EXPECT_SCALED(reaction(s, K::JointForce, j, 8, y, yp), 0.0, sF) << " joint " << j;
    }
    EXPECT_SCALED(reaction(s, K::MotionForce, 0, 8, y, yp), r.torque, sF);
    EXPECT_SCALED(reaction(s, K::MotionForce, 0, 2, y, yp), 0.0, sF);
    // REQUEST/4, FORCE between crank and ground: the revolute's force and the drive torque.
    const auto cols = requestColumns(s, m.requests[3], t, y, yp);
    EXPECT_SCALED(cols[1], r.pins[0].x(), sF);
    EXPECT_SCALED(cols[2], r.pins[0].y(), sF);
    EXPECT_SCALED(cols[7], r.torque, sF);
    ++checked;
  });
  EXPECT_EQ(checked, 201);
}

// ---- slider-crank --------------------------------------------------------------------------

std::string num(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

TEST(KinematicsClosedForm, SliderCrankMatchesClosedFormAndNewtonEuler) {
  // Crank OA = r about ground z, rod AB = l, pin B on a slider whose CM (and translational
  // joint marker) sits at B + (0.1, 0.05); the slider runs along ground x.
  const double r = 0.2, l = 0.7, th0 = 0.3;
  const V2 pa0 = r * e(th0);
  const V2 pb0(pa0.x() + std::sqrt(l * l - pa0.y() * pa0.y()), 0.0);
  const V2 off(0.1, 0.05);
  const V2 pc0 = pb0 + off;
  auto q = [&](const V2& p) { return num(p.x()) + "," + num(p.y()) + ",0"; };
  const std::string text =
      "slider-crank\n"
      "UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1, QP=0,0,0\n"
      "MARKER/11, PART=1, QP=0,0.05,0, REULER=90D,90D,0\n"
      "PART/2, MASS=1.2, CM=20, IP=0.004,0.004,0.004\n"
      "MARKER/20, PART=2, QP=" +
      q(0.5 * pa0) +
      "\n"
      "MARKER/21, PART=2, QP=0,0,0\n"
      "MARKER/22, PART=2, QP=" +
      q(pa0) +
      "\n"
      "PART/3, MASS=2.5, CM=30, IP=0.1,0.1,0.1\n"
      "MARKER/30, PART=3, QP=" +
      q(0.5 * (pa0 + pb0)) +
      "\n"
      "MARKER/31, PART=3, QP=" +
      q(pa0) +
      "\n"
      "MARKER/32, PART=3, QP=" +
      q(pb0) +
      "\n"
      "PART/4, MASS=4, CM=40, IP=0.5,0.5,0.5\n"
      "MARKER/40, PART=4, QP=" +
      q(pc0) +
      "\n"
      "MARKER/41, PART=4, QP=" +
      q(pb0) +
      "\n"
      "MARKER/42, PART=4, QP=" +
      q(pc0) +
      ", REULER=90D,90D,0\n"
      "JOINT/1, REVOLUTE, I=21, J=10\n"
      "JOINT/2, REVOLUTE, I=31, J=22\n"
      "JOINT/3, REVOLUTE, I=41, J=32\n"
      "JOINT/4, TRANSLATIONAL, I=42, J=11\n"
      "MOTION/1, JOINT=1, FUNCTION=2*TIME+0.4*SIN(3*TIME)\n"
      "ACCGRAV/JGRAV=-9.80665\n"
      "END\n";
  const model::Model m = build(text, "slider_crank.adm");
  MultibodySystem s(m);
  const double sPos = 1.0, sVel = 2.0, sAcc = 20.0, sW = 5.0, sAlpha = 20.0, sF = 100.0;
  march(s, 3.0, 0.01, [&](double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
    const double th = th0 + 2.0 * t + 0.4 * std::sin(3.0 * t);
    const double w = 2.0 + 1.2 * std::cos(3.0 * t);
    const double al = -3.6 * std::sin(3.0 * t);
    // x = r cos th + qq, qq = sqrt(l^2 - r^2 sin^2 th), and its time derivatives.
    const double qq = std::sqrt(l * l - r * r * std::sin(th) * std::sin(th));
    const double uu = -0.5 * r * r * std::sin(2 * th);
    const double qd = uu * w / qq;
    const double ud = -r * r * std::cos(2 * th) * w;
    const double qdd = (ud * w + uu * al) / qq - uu * w * qd / (qq * qq);
    const double x = r * std::cos(th) + qq;
    const double xd = -r * std::sin(th) * w + qd;
    const double xdd = -r * std::cos(th) * w * w - r * std::sin(th) * al + qdd;
    // Rod angle: B - A = (qq, -r sin th).
    const double phi = std::atan2(-r * std::sin(th), qq);
    const double phid = -r * std::cos(th) * w / qq;
    const double phidd =
        -r * ((-std::sin(th) * w * w + std::cos(th) * al) * qq - std::cos(th) * w * qd) / (qq * qq);
    (void)phi;
    EXPECT_SCALED(cmPos(s, 2, y).x(), x + off.x(), sPos);
    EXPECT_SCALED(cmPos(s, 2, y).y(), off.y(), sPos);
    EXPECT_SCALED(cmVel(s, 2, y).x(), xd, sVel);
    EXPECT_SCALED(cmAcc(s, 2, yp).x(), xdd, sAcc);
    EXPECT_SCALED(wz(s, 1, y), phid, sW);
    EXPECT_SCALED(alphaZ(s, 1, yp), phidd, sAlpha);
    EXPECT_SCALED(wz(s, 2, y), 0.0, sW);

    const V2 pa = r * e(th), pb(x, 0.0), pc = pb + off;
    const V2 accA = r * (al * perp(e(th)) - w * w * e(th));
    const V2 accB(xdd, 0.0);
    const std::vector<PlanarBody> bodies = {{1.2, 0.004, 0.5 * pa, 0.5 * accA, al},
                                            {2.5, 0.1, 0.5 * (pa + pb), 0.5 * (accA + accB), phidd},
                                            {4.0, 0.5, pc, accB, 0.0}};
    // JOINT/1 crank(I) on ground at O; /2 rod(I) on crank at A; /3 slider(I) on rod at B;
    // /4 the slider(I) on ground: normal force along y and moment, at the slider's marker.
    const std::vector<Pin> pins = {{0, -1, V2(0, 0)}, {1, 0, pa}, {2, 1, pb}};
    const std::vector<Slider> sliders = {{2, pc, V2(0, 1)}};
    const Reactions rx = inverseDynamics(bodies, pins, sliders, 0);
    using K = model::MeasureKind;
    for (int j = 0; j < 3; ++j) {
      EXPECT_SCALED(reaction(s, K::JointForce, j, 2, y, yp), rx.pins[j].x(), sF) << " joint " << j;
      EXPECT_SCALED(reaction(s, K::JointForce, j, 3, y, yp), rx.pins[j].y(), sF) << " joint " << j;
      EXPECT_SCALED(reaction(s, K::JointForce, j, 8, y, yp), 0.0, sF) << " joint " << j;
    }
    EXPECT_SCALED(reaction(s, K::JointForce, 3, 2, y, yp), 0.0, sF);
    EXPECT_SCALED(reaction(s, K::JointForce, 3, 3, y, yp), rx.sliderForce, sF);
    EXPECT_SCALED(reaction(s, K::JointForce, 3, 8, y, yp), rx.sliderMoment, sF);
    EXPECT_SCALED(reaction(s, K::MotionForce, 0, 8, y, yp), rx.torque, sF);
  });
}

}  // namespace
}  // namespace openmss::analysis
