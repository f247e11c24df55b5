// Force elements (mechanics/force_elements.hpp): the Newton matrix with every element against
// central differences, action and reaction in balance, BUSHING equal to its FIELD, and the
// BEAM's static cantilever deflection against Timoshenko theory.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/newton_matrix_check.hpp"
#include "language/reader.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;

model::Model build(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "forces.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d));
  // The every-element model starts with its BEAM deformed on purpose (a warning); only errors
  // fail here.
  for (const auto& x : d.all())
    if (x.severity == Severity::Error) ADD_FAILURE() << format(x);
  return m;
}

// Two free parts and ground joined by one element of every kind. The FIELD's matrices are full
// and unsymmetric and the VFORCE resolves in a moving marker's axes, so that every coupling
// of the law shows in the Jacobian.
const char* kEveryElement =
    "every force element\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1, QP=0,0,-1\n"
    "PART/2, MASS=2, CM=20, IP=0.3,0.4,0.5\n"
    "MARKER/20, PART=2, QP=0.2,0.1,0.3\n"
    "MARKER/21, PART=2, QP=1,0.1,0\n"
    "MARKER/22, PART=2, QP=0,0,0.5, REULER=10D,5D,0\n"
    "MARKER/23, PART=2, FLOATING\n"
    "PART/3, MASS=3, CM=30, IP=0.5,0.6,0.7, QG=1.5,0,0\n"
    "MARKER/30, PART=3\n"
    "MARKER/31, PART=3, QP=0.1,0.2,0.4\n"
    "MARKER/32, PART=3, QP=-0.5,0,0\n"
    "SFORCE/1, TRANSLATION, I=31, J=21, FUNCTION=-5*(DM(31,21)-0.4)-0.3*VR(31,21)\n"
    "SFORCE/2, ROTATION, ACTIONONLY, I=30, J=22, FUNCTION=-2*WZ(30,22,22)\n"
    "SPRINGDAMPER/1, TRANSLATIONAL, I=21, J=11, K=40, C=3, LENGTH=1.2, FORCE=2\n"
    "SPRINGDAMPER/2, ROTATIONAL, I=30, J=10, KT=20, CT=1.5, ANGLE=0.2, TORQUE=0.5\n"
    "BUSHING/1, I=32, J=21, K=100,200,300, C=1,2,3, KT=10,20,30, CT=0.1,0.2,0.3,"
    " FORCE=1,2,3, TORQUE=0.1,0.2,0.3\n"
    "FIELD/1, I=31, J=20,"
    " KMATRIX=50,1,2,3,4,5, 1.5,60,2,3,4,5, 2,1,70,3,4,5, 3,2,1,40,0.5,0.6,"
    " 0.4,2,1,0.3,45,0.7, 0.5,2,1,0.3,0.2,55,"
    " CRATIO=0.01, LENGTH=1,0.1,0.2,0.05,0.02,0.01, FORCE=1,2,3,0.4,0.5,0.6\n"
    "BEAM/1, I=30, J=22, LENGTH=1.4, AREA=0.01, IXX=2e-5, IYY=1e-5, IZZ=1.5e-5,"
    " EMODULUS=1e6, GMODULUS=4e5, ASY=1.2, ASZ=1.1,"
    " CMATRIX=0.1, 0,0.2, 0,0,0.3, 0,0,0,0.01, 0,0,0,0,0.02, 0,0.01,0,0,0,0.03\n"
    "VFORCE/1, I=31, JFLOAT=23, RM=22, FX=-3*DX(31,20,22)\\FY=-2*VY(31,20,22)\\FZ=1.5\n"
    "VTORQUE/1, I=30, JFLOAT=23, RM=10, TX=-WX(30,20)\\TY=0.2\\TZ=-0.5*WZ(30,20)\n"
    "GFORCE/1, I=32, JFLOAT=23, RM=30, FX=1\\FY=-DY(32,20)\\FZ=VZ(32,20)\\TX=0.1\\TY=-WY(32,20)"
    "\\TZ=0.3\n"
    "END\n";

Eigen::VectorXd randomState(const MultibodySystem& s, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd y = s.initialState();
  for (int b = 0; b < s.layout().bodies; ++b) {
    const int o = s.layout().body(b);
    for (int c = 0; c < 3; ++c) y(o + L::kR + c) += 0.05 * u(rng);
    Eigen::Vector4d e = y.segment<4>(o + L::kE);
    for (int c = 0; c < 4; ++c) e(c) += 0.1 * u(rng);
    y.segment<4>(o + L::kE) = e.normalized();
    for (int c = 0; c < 3; ++c) {
      y(o + L::kV + c) = u(rng);
      y(o + L::kW + c) = u(rng);
    }
    y(o + L::kMu) = 0.01 * u(rng);
  }
  return y;
}

TEST(ForceElements, EveryElementIsBuilt) {
  const model::Model m = build(kEveryElement);
  EXPECT_EQ(m.sforces.size(), 2u);
  EXPECT_EQ(m.springDampers.size(), 2u);
  EXPECT_EQ(m.linearFields.size(), 3u);
  EXPECT_EQ(m.vectorForces.size(), 3u);
  const MultibodySystem s(m);
  EXPECT_EQ(s.forceElements().elements().size(), 10u);
}

TEST(ForceElements, NewtonMatrixMatchesCentralDifferences) {
  const model::Model m = build(kEveryElement);
  const MultibodySystem s(m);
  std::mt19937 rng(3);
  const int n = s.layout().size();
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::VectorXd y = randomState(s, rng);
    const Eigen::VectorXd yp = Eigen::VectorXd::Random(n);
    // Entries reach ~1e3 (BUSHING and FIELD stiffness times lever arms); the shared 1e-6
    // relative tolerance still leaves margin over truncation and round-off.
    testing::checkNewtonMatrix(s, 0.4, y, yp, 23.0, "trial " + std::to_string(trial));
  }
}

TEST(ForceElements, ActionAndReactionBalance) {
  // Every action-reaction element is in equilibrium: the forces at I and J sum to zero and so
  // do their moments about J's origin (momentum and angular momentum are conserved).
  const model::Model m = build(kEveryElement);
  const MultibodySystem s(m);
  std::mt19937 rng(9);
  const Eigen::VectorXd y = randomState(s, rng);
  const ForceElements& fe = s.forceElements();
  for (const ForceElementRef& e : fe.elements()) {
    if (e.kind == ForceElementKind::SForce && m.sforces[e.index].actionOnly) continue;
    Eigen::Vector3d fi, ti, fj, tj;
    fe.action(e, false, 0.1, y.data(), fi, ti);
    fe.action(e, true, 0.1, y.data(), fj, tj);
    const Eigen::Vector3d pi = toEigen(markerState(m, s.layout(), fe.iMarker(e), y.data()).p);
    // The J torque is about J's origin; a floating J marker sits at I.
    const int jm = fe.jMarker(e);
    const Eigen::Vector3d pj =
        m.markers[jm].floating ? pi : toEigen(markerState(m, s.layout(), jm, y.data()).p);
    const double scale = 1.0 + fi.norm() + ti.norm();
    EXPECT_LT((fi + fj).norm(), 1e-13 * scale) << static_cast<int>(e.kind) << " " << e.index;
    EXPECT_LT((ti + tj + (pi - pj).cross(fi)).norm(), 1e-13 * scale)
        << static_cast<int>(e.kind) << " " << e.index;
    EXPECT_GT(fi.norm() + ti.norm(), 0.0);
  }
}

TEST(ForceElements, BushingEqualsTheDiagonalField) {
  const std::string parts =
      "bushing or field\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1, QG=0.1,0.05,-0.02, REULER=3D,2D,1D\n"
      "MARKER/20, PART=2\n";
  const model::Model mb = build(parts +
                                "BUSHING/7, I=20, J=10, K=10,20,30, C=1,2,3, KT=4,5,6,"
                                " CT=0.4,0.5,0.6, FORCE=1,-1,2, TORQUE=0.1,0.2,-0.3\nEND\n");
  const model::Model mf = build(
      parts +
      "FIELD/7, I=20, J=10, KMATRIX=10,0,0,0,0,0, 0,20,0,0,0,0, 0,0,30,0,0,0, 0,0,0,4,0,0,"
      " 0,0,0,0,5,0, 0,0,0,0,0,6, CMATRIX=1,0,0,0,0,0, 0,2,0,0,0,0, 0,0,3,0,0,0,"
      " 0,0,0,0.4,0,0, 0,0,0,0,0.5,0, 0,0,0,0,0,0.6, FORCE=1,-1,2,0.1,0.2,-0.3\nEND\n");
  const MultibodySystem sb(mb), sf(mf);
  std::mt19937 rng(2);
  const Eigen::VectorXd y = randomState(sb, rng);
  Eigen::Vector3d f1, t1, f2, t2;
  for (bool atJ : {false, true}) {
    sb.forceElements().action({ForceElementKind::LinearField, 0}, atJ, 0.0, y.data(), f1, t1);
    sf.forceElements().action({ForceElementKind::LinearField, 0}, atJ, 0.0, y.data(), f2, t2);
    // The same law with the same coefficients: the same operations, bit for bit.
    EXPECT_EQ(f1, f2);
    EXPECT_EQ(t1, t2);
  }
}

// The BEAM as a cantilever: J on ground, the tip part's CM at I. Newton on the element's force
// law finds the tip pose where the beam balances an end load; Timoshenko theory gives it.
TEST(ForceElements, BeamCantileverMatchesTimoshenko) {
  const double len = 2.0, area = 0.02, ixx = 3e-5, iyy = 1e-5, izz = 2e-5, e = 2e8, g = 8e7,
               asy = 1.2, asz = 10.0 / 9.0;
  const std::string text =
      "cantilever\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2, QP=2,0,0\n"
      "BEAM/1, I=20, J=10, LENGTH=2, AREA=0.02, IXX=3e-5, IYY=1e-5, IZZ=2e-5, EMODULUS=2e8,"
      " GMODULUS=8e7, ASY=1.2, ASZ=1.1111111111111111\n"
      "END\n";
  const model::Model m = build(text);
  const MultibodySystem s(m);
  const ForceElements& fe = s.forceElements();
  Eigen::VectorXd y = s.initialState();
  const Eigen::Vector3d r0 = y.segment<3>(L::kR);
  const Eigen::Vector4d e0 = y.segment<4>(L::kE);
  // x: tip translation (3) and rotation vector (3) from the undeformed pose.
  auto stateOf = [&](const Eigen::Matrix<double, 6, 1>& x) {
    Eigen::VectorXd z = y;
    z.segment<3>(L::kR) = r0 + x.head<3>();
    const Eigen::Vector3d rot = x.tail<3>();
    const Eigen::Quaterniond q0(e0(0), e0(1), e0(2), e0(3));
    const Eigen::Quaterniond q =
        rot.norm() > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(rot.norm(), rot.normalized())) * q0
                       : q0;
    z.segment<4>(L::kE) << q.w(), q.x(), q.y(), q.z();
    return z;
  };
  // Newton on the element's force law: the tip pose where the beam balances the end load.
  auto solve = [&](const Eigen::Vector3d& load, const Eigen::Vector3d& moment) {
    auto imbalance = [&](const Eigen::Matrix<double, 6, 1>& x) {
      const Eigen::VectorXd z = stateOf(x);
      Eigen::Vector3d f, t;
      fe.action({ForceElementKind::LinearField, 0}, false, 0.0, z.data(), f, t);
      Eigen::Matrix<double, 6, 1> out;
      out << f + load, t + moment;
      return out;
    };
    Eigen::Matrix<double, 6, 1> x = Eigen::Matrix<double, 6, 1>::Zero();
    for (int it = 0; it < 8; ++it) {
      Eigen::Matrix<double, 6, 6> jac;
      for (int c = 0; c < 6; ++c) {
        Eigen::Matrix<double, 6, 1> dx = Eigen::Matrix<double, 6, 1>::Zero();
        dx(c) = 1e-7;
        jac.col(c) = (imbalance(x + dx) - imbalance(x - dx)) / 2e-7;
      }
      x -= jac.lu().solve(imbalance(x));
    }
    // Round-off: 1e-16 relative in the tip position times the axial stiffness EA/L = 2e6.
    EXPECT_LT(imbalance(x).norm(), 1e-9);
    return x;
  };
  const double eiz = e * izz, eiy = e * iyy;
  // One load at a time: the tip then turns about one J axis only, where the projected rotations
  // are exact, so the element must reproduce linear theory to round-off; 1e-9 relative leaves
  // margin over the 1e-9 N imbalance divided by stiffnesses of 1e2..1e6.
  const double p = 5.0;
  auto near = [](double got, double want) { EXPECT_NEAR(got, want, 1e-9 * std::abs(want)); };
  {
    // End load along y: bending in the x-y plane, deflection = bending + shear.
    const auto x = solve({0, p, 0}, {0, 0, 0});
    const double v = p * len * len * len / (3 * eiz) + p * len * asy / (g * area);
    std::printf("load along y: tip %.12e (Timoshenko %.12e), slope %.12e (%.12e)\n", x(1), v,
                x(5), p * len * len / (2 * eiz));
    near(x(1), v);
    near(x(5), p * len * len / (2 * eiz));  // slope dy/dx = rotation about z
    EXPECT_NEAR(x(0), 0.0, 1e-15);
    EXPECT_NEAR(x(2), 0.0, 1e-15);
  }
  {
    // End load along z: bending in the x-z plane; the slope dz/dx is a rotation about -y.
    const auto x = solve({0, 0, p}, {0, 0, 0});
    near(x(2), p * len * len * len / (3 * eiy) + p * len * asz / (g * area));
    near(x(4), -p * len * len / (2 * eiy));
  }
  {
    const auto x = solve({p, 0, 0}, {0, 0, 0});
    near(x(0), p * len / (e * area));  // axial
  }
  {
    const auto x = solve({0, 0, 0}, {p, 0, 0});
    near(x(3), p * len / (g * ixx));  // torsion
  }
  {
    // An end moment about z alone: slope M L / (E I), deflection M L^2 / (2 E I) (no shear).
    const auto x = solve({0, 0, 0}, {0, 0, p * 1e-3});
    near(x(5), p * 1e-3 * len / eiz);
    near(x(1), p * 1e-3 * len * len / (2 * eiz));
  }
}

}  // namespace
}  // namespace openmss::mechanics
