#pragma once
// What the corpus simulation test (tests/analysis/corpus_simulation_test.cpp) reads from a
// run's .msg file, ours or the one real ADAMS wrote for the same command file: the time each
// simulation ended at, our integrator's step counts, and whether the zero-DOF warning was
// given. ADAMS's step counts are printed too but not compared: its integrator chooses other
// steps (docs/validation.md, "Corpus simulations").

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace openmss::testing {

struct MsgRun {
  int simulations = 0;        // " End Simulation" lines
  double endTime = 0.0;       // time reached by the last simulation
  long integrationSteps = 0;  // ours: sum of the "Integrator statistics" lines
  long outputSteps = 0;       // ours: the run summary
  bool zeroDofWarning = false;
  std::vector<double> ends;  // the time each simulation ended at
};

// The leading number of a line ("   2.00000E+00  1.00000E-02 ..."), if it has one.
inline bool leadingNumber(const std::string& line, double& value) {
  const char* begin = line.c_str();
  char* end = nullptr;
  value = std::strtod(begin, &end);
  return end != begin;
}

// Our .msg and the program's output (the run summary line, printed without --quiet).
inline MsgRun readOpenMssRun(const std::string& msg, const std::string& output) {
  MsgRun r;
  std::istringstream in(msg);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find(" End Simulation") != std::string::npos) ++r.simulations;
    if (const auto p = line.find("Integrator statistics: "); p != std::string::npos)
      r.integrationSteps += std::atol(line.c_str() + p + 23);
    if (line.find("zero degrees of freedom; a kinematic analysis") != std::string::npos)
      r.zeroDofWarning = true;
  }
  // The warning is in the .msg and on the terminal; either will do.
  if (output.find("zero degrees of freedom; a kinematic analysis") != std::string::npos)
    r.zeroDofWarning = true;
  // "  analysis: dynamic, reached t = 2 with 205 integration steps, 201 output steps"
  if (const auto p = output.find("reached t = "); p != std::string::npos) {
    r.endTime = std::strtod(output.c_str() + p + 12, nullptr);
    if (const auto q = output.find(" steps, ", p); q != std::string::npos)
      r.outputSteps = std::atol(output.c_str() + q + 8);
  }
  return r;
}

// A .msg real ADAMS wrote: each simulation's last progress line before "End Simulation".
inline MsgRun readAdamsRun(const std::string& msg) {
  MsgRun r;
  std::istringstream in(msg);
  std::string line;
  double last = 0.0;
  long lastSteps = 0;
  bool inSimulation = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find("Begin Simulation") != std::string::npos) inSimulation = true;
    if (line.find("kinematically determinate") != std::string::npos) r.zeroDofWarning = true;
    double t = 0.0;
    if (inSimulation && leadingNumber(line, t)) {
      last = t;
      // time, step size, function evaluations, cumulative steps, order, CPU time
      std::istringstream fields(line);
      double column[4] = {0, 0, 0, 0};
      for (double& c : column) fields >> c;
      lastSteps = static_cast<long>(column[3]);
    }
    if (line.find("End Simulation") != std::string::npos) {
      ++r.simulations;
      r.ends.push_back(last);
      r.endTime = last;
      r.integrationSteps += lastSteps;
      inSimulation = false;
    }
  }
  return r;
}

// Compares our run with ADAMS's .msg of the same command file; returns the number of
// quantities compared (2 when ADAMS's run ended, 0 otherwise).
inline int compareWithAdams(const std::string& base, const MsgRun& ours,
                            const std::string& adamsMsg) {
  const MsgRun adams = readAdamsRun(adamsMsg);
  if (adams.simulations == 0) return 0;
  EXPECT_EQ(ours.simulations, adams.simulations) << base;
  // Both print the end time with 6 significant digits (ours %g, ADAMS 1.00000E+00).
  EXPECT_NEAR(ours.endTime, adams.endTime, 5e-6 * std::max(1.0, std::abs(adams.endTime))) << base;
  // ADAMS warns that a data set is kinematically determinate; so do we (zero DOF).
  EXPECT_EQ(ours.zeroDofWarning, adams.zeroDofWarning) << base;
  std::printf(
      "  ADAMS .msg of %s: %d simulation(s) ending at %g (ours %g); zero-DOF warning "
      "ADAMS %s, ours %s; %ld integration steps (ours %ld, not compared)\n",
      base.c_str(), adams.simulations, adams.endTime, ours.endTime,
      adams.zeroDofWarning ? "yes" : "no", ours.zeroDofWarning ? "yes" : "no",
      adams.integrationSteps, ours.integrationSteps);
  return 2;
}

}  // namespace openmss::testing
