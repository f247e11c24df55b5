// UVX/UVY/UVZ, TRANS, ORIENT codes 28-29 and UV of the zero vector.
//
// Truth: marker orientations A_i, A_j built here from elementary rotations; the axes and the
// frame changes are computed with Eigen directly (A_jᵀ A_i columns, A_iᵀ A_j v), independently
// of the parser's expansion into ORIENT(29, n, i, j) host calls and of orientValue, which
// supplies those host values here exactly as the mechanics do. Products of a few rotation
// matrices round to ~1e-15, so 1e-13 is a safe agreement. Rodriguez parameters are checked
// against tan(angle/2) * axis (RCNVRT: R_k = P_k / P0). Derivatives against central
// differences (expr_test_support.hpp: Richardson, 1e-6 relative).

#include <Eigen/Dense>
#include <cmath>
#include <map>

#include "common/dual.hpp"
#include "expr_test_support.hpp"
#include "mechanics/orientation_measure.hpp"

namespace openmss::expr {
namespace {

using testing::checkAllDerivatives;
using testing::parseOk;

Eigen::Matrix3d rotation(double a, double b, double c) {
  return (Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(b, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(c, Eigen::Vector3d::UnitY()))
      .toRotationMatrix();
}

// Host values for every call of `e`: ORIENT codes read from the marker orientations `frames`
// (ground = identity for an absent or 0 id) with mechanics::orientValue, as the model does.
std::vector<double> hostValues(const Expression& e, const std::map<long, Eigen::Matrix3d>& frames) {
  std::vector<double> values;
  for (const HostCall& call : e.hostCalls()) {
    EXPECT_EQ(call.name, "ORIENT");
    const auto frame = [&](std::size_t k) -> Eigen::Matrix3d {
      if (k >= call.args.size() || call.args[k] == 0) return Eigen::Matrix3d::Identity();
      return frames.at(call.args[k]);
    };
    const Eigen::Matrix3d r = frame(3).transpose() * frame(2);
    double out = 0.0;
    EXPECT_TRUE(mechanics::orientValue(M3<double>::from(r), static_cast<int>(call.args[0]),
                                       static_cast<int>(call.args[1]), &out));
    values.push_back(out);
  }
  return values;
}

// Component k of the vector expression `vectorText`, evaluated with the frames `f`.
double component(const std::string& vectorText, int k, const std::map<long, Eigen::Matrix3d>& f) {
  const char* unit[3] = {"[1,0,0]", "[0,1,0]", "[0,0,1]"};
  const Expression e = parseOk("(" + vectorText + ")*" + unit[k]);
  const std::vector<double> h = hostValues(e, f);
  return e.evaluate(h.data(), 0.0);
}

const std::map<long, Eigen::Matrix3d> kFrames = {
    {1, rotation(0.7, -0.4, 1.3)}, {2, rotation(-2.1, 0.9, 0.2)}, {3, rotation(2.8, 1.4, -0.6)}};

TEST(MarkerVectors, UvxExpandsIntoDirectionCosinesOfTheMarkers) {
  const Expression e = parseOk("UVX(1,2)*UVZ(3)");
  ASSERT_EQ(e.hostCalls().size(), 6u);
  EXPECT_EQ(e.hostCalls()[0].args, (std::vector<long>{29, 1, 1, 2}));
  EXPECT_EQ(e.hostCalls()[2].args, (std::vector<long>{29, 3, 1, 2}));
  EXPECT_EQ(e.hostCalls()[3].args, (std::vector<long>{29, 7, 3}));
  EXPECT_EQ(e.hostCalls()[5].args, (std::vector<long>{29, 9, 3}));
  EXPECT_EQ(e.hostCalls()[0].column, 1);
  EXPECT_EQ(e.hostCalls()[3].column, 10);
}

TEST(MarkerVectors, UnitAxesAreTheMarkerAxesResolvedInK) {
  const Eigen::Matrix3d& ai = kFrames.at(1);
  const Eigen::Matrix3d& ak = kFrames.at(2);
  const char* names[3] = {"UVX", "UVY", "UVZ"};
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d inK = ak.transpose() * ai.col(axis);
    const Eigen::Vector3d inGround = ai.col(axis);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(component(std::string(names[axis]) + "(1,2)", k, kFrames), inK(k), 1e-13);
      EXPECT_NEAR(component(std::string(names[axis]) + "(1)", k, kFrames), inGround(k), 1e-13);
      EXPECT_NEAR(component(std::string(names[axis]) + "(1,0)", k, kFrames), inGround(k), 1e-13);
    }
  }
  // The ADAMS help's example: DXYZ(i,j)*UVX(k) is DX(i,j,k); here with a constant vector d,
  // d * UVX(2) is the x component of d resolved in marker 2.
  const Eigen::Vector3d d(0.3, -1.1, 2.2);
  EXPECT_NEAR(component("[0.3,-1.1,2.2]*UVX(2)*[1,0,0]", 0, kFrames), (ak.transpose() * d)(0),
              1e-13);
}

TEST(MarkerVectors, TransResolvesAVectorOfJInTheAxesOfI) {
  const Eigen::Vector3d v(0.8, -0.25, 1.7);
  const Eigen::Matrix3d& ai = kFrames.at(1);
  const Eigen::Matrix3d& aj = kFrames.at(3);
  const Eigen::Vector3d inI = ai.transpose() * aj * v;
  const Eigen::Vector3d fromGround = ai.transpose() * v;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(component("TRANS([0.8,-0.25,1.7],1,3)", k, kFrames), inI(k), 1e-13);
    EXPECT_NEAR(component("TRANS([0.8,-0.25,1.7],1)", k, kFrames), fromGround(k), 1e-13);
    EXPECT_NEAR(component("TRANS([0.8,-0.25,1.7],1,0)", k, kFrames), fromGround(k), 1e-13);
    // Round trip: to marker 1 from marker 3, then back.
    EXPECT_NEAR(component("TRANS(TRANS([0.8,-0.25,1.7],1,3),3,1)", k, kFrames), v(k), 1e-13);
  }
  // A rotation preserves lengths.
  EXPECT_NEAR(component("MAG(TRANS([0.8,-0.25,1.7],2,3))*[1,0,0]", 0, kFrames), v.norm(), 1e-13);
}

TEST(MarkerVectors, TransDerivativesAgreeWithCentralDifferences) {
  // Host values are free inputs here (direction cosines and displacements): the partials of the
  // expansion are those of a bilinear form, checked at an arbitrary point.
  const Expression e = parseOk("TRANS(DXYZ(4,5),1,2)*[1,-2,0.5] + UVY(1)*[TIME,1,0]");
  std::vector<double> h;
  for (std::size_t k = 0; k < e.hostCalls().size(); ++k) h.push_back(0.1 * double(k) - 0.7);
  checkAllDerivatives(e, h, 0.4, "TRANS and UVY");
}

TEST(OrientCodes, RodriguezParametersAreTanHalfAngleTimesAxis) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  for (double angle : {0.4, -1.9, 2.7}) {
    const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    for (int k = 1; k <= 3; ++k) {
      double out = 0.0;
      ASSERT_TRUE(mechanics::orientValue(M3<double>::from(r), 28, k, &out));
      EXPECT_NEAR(out, std::tan(0.5 * angle) * axis(k - 1), 1e-13) << angle << " " << k;
    }
  }
}

TEST(OrientCodes, DirectionCosinesAreNumberedDownTheColumns) {
  const Eigen::Matrix3d r = kFrames.at(2);
  for (int n = 1; n <= 9; ++n) {
    double out = 0.0;
    ASSERT_TRUE(mechanics::orientValue(M3<double>::from(r), 29, n, &out));
    EXPECT_EQ(out, r((n - 1) % 3, (n - 1) / 3)) << n;
  }
}

TEST(OrientCodes, RodriguezDerivativeAgreesWithCentralDifferences) {
  // r(t) = rotation about a fixed axis by t, composed with a fixed rotation: the dual
  // derivative of each Rodriguez parameter against central differences of the double path.
  const Eigen::Vector3d axis = Eigen::Vector3d(-0.2, 0.6, 0.7).normalized();
  const Eigen::Matrix3d base = kFrames.at(1);
  const auto value = [&](double t, int k) {
    const Eigen::Matrix3d r = Eigen::AngleAxisd(t, axis).toRotationMatrix() * base;
    double out = 0.0;
    mechanics::orientValue(M3<double>::from(r), 28, k, &out);
    return out;
  };
  const double t0 = 0.35;
  // dR/dt = [axis]x R at t0, carried as the dual part of every element.
  const Eigen::Matrix3d r0 = Eigen::AngleAxisd(t0, axis).toRotationMatrix() * base;
  Eigen::Matrix3d skew;
  skew << 0, -axis.z(), axis.y(), axis.z(), 0, -axis.x(), -axis.y(), axis.x(), 0;
  const Eigen::Matrix3d dr = skew * r0;
  M3<Dual<double>> rd;
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) rd.c[col][row] = Dual<double>(r0(row, col), dr(row, col));
  for (int k = 1; k <= 3; ++k) {
    Dual<double> out;
    ASSERT_TRUE(mechanics::orientValue(rd, 28, k, &out));
    const double numeric =
        testing::centralDifference([&](double t) { return value(t, k); }, t0, 1e-4);
    testing::expectDerivativeNear(out.d, numeric, std::abs(out.v),
                                  "Rodriguez " + std::to_string(k));
  }
}

TEST(Vectors, UnitVectorOfTheZeroVectorIsZeroWithZeroPartials) {
  EXPECT_EQ(parseOk("UV([0,0,0])*[1,1,1]").evaluate(nullptr, 0.0), 0.0);
  const Expression e = parseOk("UV(DXYZ(1,2))*[1,2,3]");
  const std::vector<double> zero = {0.0, 0.0, 0.0};
  std::vector<double> dHost(3, -1.0);
  double dTime = -1.0;
  EXPECT_EQ(e.evaluate(zero.data(), 0.0, dHost.data(), &dTime), 0.0);
  for (double d : dHost) EXPECT_EQ(d, 0.0);
  EXPECT_EQ(dTime, 0.0);
  // Away from zero it is still v/|v| with exact partials.
  const std::vector<double> h = {0.3, -0.4, 1.2};
  EXPECT_NEAR(e.evaluate(h.data(), 0.0), (0.3 - 0.8 + 3.6) / 1.3, 1e-15);
  checkAllDerivatives(e, h, 0.0, "UV");
}

}  // namespace
}  // namespace openmss::expr
