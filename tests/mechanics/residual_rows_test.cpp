// The constraint rows of MultibodySystem::residual<double> (multibody_residual_rows.cpp: a
// joint's frames, bodies and Point arms taken once) against the generic serial loop, which
// residual<Dual<double>> runs: on equations whose geometry and its virtual derivative neither
// divide nor call a function (Dual division multiplies by a reciprocal, so its value part is
// not double's quotient; hence no atan2 kinds, MotionRotation or a rotational COUPLER, here),
// the dual residual's value parts are the same operations on the same numbers, so every entry
// must agree to the last bit (docs/performance.md, "GSTIFF's cost per step, cheaper").

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "common/dual.hpp"
#include "language/reader.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "support/part_per_element.hpp"
#include "support/random_state.hpp"

namespace openmss::mechanics {
namespace {

model::Model buildText(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "residual_rows.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

// One part per element, generically placed; even elements hold their part to ground, odd ones
// to the previous part, so both sides of an equation move. Joints of Point, Dot and Along
// equations (the shared path), a CONVEL (its Convel equation takes the generic path between
// shared ones), a motion on a translational joint (MotionTranslation) and a translational
// COUPLER (four markers, generic).
std::string mixedDataSet() {
  const std::vector<std::string> elements = {
      "JOINT/1, REVOLUTE",       "JOINT/2, SPHERICAL",   "JOINT/3, UNIVERSAL",
      "JOINT/4, TRANSLATIONAL",  "JOINT/5, CYLINDRICAL", "JOINT/6, FIXED",
      "JOINT/7, TRANSLATIONAL",  "JPRIM/8, INLINE",      "JPRIM/9, PERPENDICULAR",
      "JOINT/10, TRANSLATIONAL", "JOINT/11, CONVEL",     "JOINT/12, REVOLUTE",
  };
  return test::partPerElementDataSet("mixed rows", elements,
                                     "MOTION/30, JOINT=4, FUNCTION=0.2*SIN(TIME)\n"
                                     "COUPLER/31, JOINTS=7,10, TYPE=T,T, SCALES=1,-0.5\n");
}

TEST(ResidualRows, DoubleRowsAreTheGenericLoopsBitForBit) {
  const model::Model m = buildText(mixedDataSet());
  const MultibodySystem s(m);
  const int n = s.layout().size();
  std::mt19937 rng(11);
  for (int trial = 0; trial < 4; ++trial) {
    const Eigen::VectorXd y = testing::randomState(s, rng, testing::RandomMu::Yes);
    const Eigen::VectorXd yp = Eigen::VectorXd::Random(n);
    const double t = 0.37 * (trial + 1);
    Eigen::VectorXd g(n);
    s.residual(t, y.data(), yp.data(), g.data());
    std::vector<Dual<double>> yd(static_cast<size_t>(n)), ypd(static_cast<size_t>(n)),
        gd(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
      yd[static_cast<size_t>(i)] = Dual<double>(y(i));
      ypd[static_cast<size_t>(i)] = Dual<double>(yp(i));
    }
    s.residual(t, yd.data(), ypd.data(), gd.data());
    int differing = 0;
    for (int i = 0; i < n; ++i) {
      const double generic = gd[static_cast<size_t>(i)].v;
      if (std::bit_cast<std::uint64_t>(g(i)) != std::bit_cast<std::uint64_t>(generic)) {
        ++differing;
        ADD_FAILURE() << "trial " << trial << ", row " << i << ": " << g(i) << " vs " << generic;
      }
    }
    EXPECT_EQ(differing, 0);
  }
  // The data set has what the test is about: equations on the shared path and others.
  int shared = 0, generic = 0;
  for (const ConstraintEquation& eq : s.constraints().equations())
    (eq.markerCount() == 2 && MultibodySystem::hasAnalyticGradient(eq) ? shared : generic) += 1;
  EXPECT_GE(shared, 20);
  EXPECT_GE(generic, 2);
}

}  // namespace
}  // namespace openmss::mechanics
