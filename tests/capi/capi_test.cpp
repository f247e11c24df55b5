// The embedding API (include/openmss/openmss.h, docs/embedding.md) through the shared library
// libopenmss, as an embedding program uses it: errors with their location, plant inputs and
// outputs against a conservation law, REQUEST values against closed forms, and SAVE/RELOAD.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "openmss/openmss.h"
#include "openmss/openmss.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kPlant =
    std::string(OPENMSS_SOURCE_DIR) + "/examples/embedding/pendulum_plant.adm";
constexpr double kG = 9.80665, kM = 1.0, kL = 0.5, kIp = 0.26;  // pendulum_plant.adm

fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("openmss_capi_" + name);
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

TEST(EmbeddingApi, ABadDataSetGivesAnInputErrorWithFileAndLine) {
  const fs::path dir = scratch("bad");
  const fs::path adm = dir / "bad.adm";
  std::ofstream(adm) << "bad\nPART/1, GROUND\nMARKER/10, PART=1, QP=0,0\nEND\n";
  openmss_solver* s = reinterpret_cast<openmss_solver*>(&s);  // must be reset to null
  EXPECT_EQ(openmss_open(adm.c_str(), dir.c_str(), &s), OPENMSS_ERROR_INPUT);
  EXPECT_EQ(s, nullptr);
  const std::string message = openmss_last_error();
  EXPECT_NE(message.find("bad.adm:3:"), std::string::npos) << message;
  EXPECT_NE(message.find("MARKER/10"), std::string::npos) << message;
  EXPECT_EQ(openmss_last_error_line(), 3);
  EXPECT_EQ(fs::path(openmss_last_error_file()).filename().string(), "bad.adm");
  // A missing file, and the C++ layer's exception carrying the same location.
  EXPECT_EQ(openmss_open((dir / "none.adm").c_str(), nullptr, &s), OPENMSS_ERROR_FILE);
  try {
    openmss::Solver bad(adm.string(), dir.string());
    ADD_FAILURE() << "no exception";
  } catch (const openmss::Error& e) {
    EXPECT_EQ(e.status(), OPENMSS_ERROR_INPUT);
    EXPECT_EQ(e.line(), 3);
  }
}

TEST(EmbeddingApi, WrongCallsAreRefusedWithoutChangingTheRun) {
  const fs::path dir = scratch("calls");
  openmss::Solver s(kPlant, dir.string());
  int n = 0;
  EXPECT_EQ(openmss_pinput_count(s.handle(), 1, &n), OPENMSS_OK);
  EXPECT_EQ(n, 1);
  EXPECT_EQ(openmss_poutput_count(s.handle(), 1, &n), OPENMSS_OK);
  EXPECT_EQ(n, 2);
  const double two[2] = {1.0, 2.0};
  EXPECT_EQ(openmss_set_pinput(s.handle(), 1, two, 2), OPENMSS_ERROR_ARGUMENT);
  EXPECT_NE(std::string(openmss_last_error()).find("PINPUT/1 lists 1"), std::string::npos);
  EXPECT_EQ(openmss_set_pinput(s.handle(), 7, two, 1), OPENMSS_ERROR_ARGUMENT);
  EXPECT_EQ(openmss_advance(s.handle(), 0.0, 1), OPENMSS_ERROR_STATE);
  EXPECT_EQ(openmss_advance(s.handle(), 1.0, 0), OPENMSS_ERROR_ARGUMENT);
  EXPECT_EQ(openmss_command(s.handle(), "INTEGRATOR/NOSUCH"), OPENMSS_ERROR_INPUT);
  EXPECT_STRNE(openmss_last_error(), "");
  // A model-changing command before any input is set: the rebuilt model holds m g' at rest.
  s.command("ACCGRAV/JGRAV=-2");
  s.initialize();
  EXPECT_NEAR(s.request(2)[0], 2.0 * kM, 1e-9);
  // After an input is set it is refused (its rebuilt model would lose the input).
  s.setInputs(1, {0.5});
  EXPECT_EQ(openmss_command(s.handle(), "SFORCE/1, FUNCTION=1"), OPENMSS_ERROR_STATE);
  EXPECT_NE(std::string(openmss_last_error()).find("SFORCE/1 changes the model"), std::string::npos)
      << openmss_last_error();
  EXPECT_EQ(openmss_command(s.handle(), "ACCGRAV/LIST"), OPENMSS_OK);
  double v[8];
  EXPECT_EQ(openmss_request(s.handle(), 99, v), OPENMSS_ERROR_ARGUMENT);
  EXPECT_EQ(s.time(), 0.0);
  EXPECT_EQ(openmss_time(nullptr, v), OPENMSS_ERROR_ARGUMENT);
}

// Constant torque u on the pendulum: E = I w^2/2 - m g l cos(a) - u a is conserved, and the
// requests agree with the outputs: the centre of mass at l (sin a, -cos a), the pivot reaction
// at rest m g. Tolerances: GSTIFF at ERROR=1e-9 keeps the energy to 1.3e-8 over 1 s (measured;
// 2e-7 leaves room for integrator changes; a torque not applied would miss by u a ~ 0.7); the
// requests are the same state read two ways (1e-12).
TEST(EmbeddingApi, AConstantInputTorqueConservesTheWorkEnergyBalance) {
  const fs::path dir = scratch("energy");
  openmss::Solver s(kPlant, dir.string());
  s.command("INTEGRATOR/GSTIFF, ERROR=1e-9");
  s.initialize();
  const auto rest = s.request(2);  // FORCE I=21 J=10: the joint holds the weight
  EXPECT_NEAR(rest[0], kM * kG, 1e-9);
  const double u = 1.5;
  s.setInputs(1, {u});
  EXPECT_EQ(s.variable(1), u);
  const auto energy = [&](const std::vector<double>& y) {
    return 0.5 * kIp * y[1] * y[1] - kM * kG * kL * std::cos(y[0]) - u * y[0];
  };
  const double e0 = energy(s.outputs(1));
  int compared = 0;
  for (int k = 1; k <= 20; ++k) {
    s.advance(0.05 * k, 5);
    const auto y = s.outputs(1);
    EXPECT_NEAR(energy(y), e0, 2e-7) << "t=" << s.time();
    const auto d = s.request(1);  // DISPLACEMENT I=20 J=10 (radians)
    EXPECT_NEAR(d[1], kL * std::sin(y[0]), 1e-12);
    EXPECT_NEAR(d[2], -kL * std::cos(y[0]), 1e-12);
    EXPECT_NEAR(d[5] + d[7], y[0], 1e-12);  // body 3-1-3 angles about one z axis
    ++compared;
  }
  EXPECT_EQ(compared, 20);
  EXPECT_GT(s.outputs(1)[0], 0.3);  // the torque has turned the rod
  EXPECT_EQ(s.time(), 1.0);
}

// SAVE/RELOAD: continuing from a reloaded state is bit-identical to not having stopped, with
// the plant inputs as last set.
TEST(EmbeddingApi, ReloadingSavedStatesContinuesBitIdentically) {
  const fs::path dir = scratch("reload");
  const std::string file = (dir / "half.sav").string();
  openmss::Solver s(kPlant, dir.string());
  s.initialize();
  s.setInputs(1, {0.8});
  s.advance(0.5, 5);
  s.save(file);
  s.advance(1.0, 5);
  const auto straight = s.outputs(1);
  const auto straightRequest = s.request(1);
  s.reload(file);
  EXPECT_EQ(s.time(), 0.5);
  s.advance(1.0, 5);
  EXPECT_EQ(s.outputs(1), straight);
  EXPECT_EQ(s.request(1), straightRequest);
  EXPECT_EQ(openmss_reload(s.handle(), (dir / "none.sav").c_str()), OPENMSS_ERROR_FILE);
}

}  // namespace
