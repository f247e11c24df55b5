// GTUNTS, GETMOD and GETINM from a user routine (tests/user/explicit_routines.c, Units_var):
// the unit factors against their SI definitions, the unit symbols, the analysis mode against
// the MODE expression; and the FORTRAN entry's blank padding.

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "analysis/request_values.hpp"
#include "language/reader.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "user/openmss_usersub.h"

extern "C" void gtunts_(int* exists, double* scales, char* units, std::size_t lunits);

namespace openmss {
namespace {

const std::string kC = OPENMSS_TEST_C_ROUTINES;

// The routine's values, one VARIABLE each, evaluated at the initial state: Units_var(k) for
// k = 0..6, then the 12 characters of GTUNTS's units, then its terminator test; last the
// expression MODE.
std::vector<double> values(const std::string& units) {
  std::string text = "q\n" + units + "PART/1, GROUND\nMARKER/10, PART=1\n";
  int id = 0;
  auto add = [&](int what, int at) {
    text += "VARIABLE/" + std::to_string(++id) + ", FUNCTION=USER(" + std::to_string(what) + ", " +
            std::to_string(at) + "), ROUTINE=\"" + kC + "::Units_var\"\n";
  };
  for (int k = 0; k < 7; ++k) add(k, 0);
  for (int c = 0; c < 12; ++c) add(7, c);
  add(8, 0);
  text += "VARIABLE/99, FUNCTION=MODE\nEND\n";
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "q.adm", ds, d);
  model::Model m;
  std::string all;
  const bool ok = model::buildModel(ds, m, d) && !d.hasErrors();
  for (const auto& x : d.all()) all += format(x) + "\n";
  EXPECT_TRUE(ok) << all;
  std::vector<double> out;
  if (!ok) return out;
  const mechanics::MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState(), yp = Eigen::VectorXd::Zero(y.size());
  for (const model::Variable& v : m.variables) {
    std::vector<double> host;
    for (const auto& ms : v.function.measures)
      host.push_back(analysis::measureValue(s, ms, 0.0, y, yp));
    out.push_back(v.function.expression.evaluate(host.data(), 0.0));
  }
  return out;
}

// The 12 characters GTUNTS gave, from values() entries 7..18.
std::string unitText(const std::vector<double>& v) {
  std::string s;
  for (std::size_t k = 7; k < 19 && k < v.size(); ++k) s += static_cast<char>(v[k]);
  return s;
}

TEST(ModelQueries, GtuntsGivesTheUnitsInSi) {
  // The UNITS statement's factors: 1 ms = 1e-3 s, 1 in = 0.0254 m (exact), 1 lbf =
  // 4.4482216152605 N and 1 lbm = 0.45359237 kg (exact definitions).
  const std::vector<double> v =
      values("UNITS/ FORCE=POUND_FORCE, MASS=POUND_MASS, LENGTH=INCH, TIME=MILLISECONDS\n");
  ASSERT_EQ(v.size(), 21u);
  EXPECT_EQ(v[0], 1e-3);
  EXPECT_EQ(v[1], 0.0254);
  EXPECT_EQ(v[2], 4.4482216152605);
  EXPECT_EQ(v[3], 0.45359237);
  EXPECT_EQ(v[4], 1.0);  // a UNITS statement exists
  EXPECT_EQ(unitText(v), "ms in lbflbm");
  EXPECT_EQ(v[19], 1.0);  // NUL-terminated after 12 characters
  // Without UNITS: SI, no statement.
  const std::vector<double> w = values("");
  ASSERT_EQ(w.size(), 21u);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(w[static_cast<std::size_t>(k)], 1.0) << k;
  EXPECT_EQ(w[4], 0.0);
  EXPECT_EQ(unitText(w), "s  m  N  kg ");
}

TEST(ModelQueries, GetmodIsTheModeExpression) {
  const std::vector<double> v = values("");
  ASSERT_EQ(v.size(), 21u);
  EXPECT_EQ(v[5], v[20]);  // GETMOD == MODE
  EXPECT_GE(v[5], 1.0);
  EXPECT_EQ(v[6], v[20] == 3.0 ? 1.0 : 0.0);  // GETINM
}

// Outside a routine: no model, so no UNITS; FORTRAN's CHARACTER*20 is blank-padded.
TEST(ModelQueries, FortranGtuntsPadsWithBlanks) {
  int exists = 7;
  double scales[4] = {0, 0, 0, 0};
  char units[20];
  gtunts_(&exists, scales, units, sizeof units);
  EXPECT_EQ(exists, 0);
  EXPECT_EQ(std::string(units, sizeof units), std::string(20, ' '));
  for (double s : scales) EXPECT_EQ(s, 1.0);
}

}  // namespace
}  // namespace openmss
