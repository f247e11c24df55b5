#pragma once
// Shared by the MuJoCo peers of the bench scripts (mujoco_pile.cpp, mujoco_walker.cpp): a model
// loaded from XML text, and the wall and CPU time of the steps.

#include <mujoco/mujoco.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>

// MuJoCo 2.2 loads XML from files: `xml` is written to `path`, loaded, and the file removed.
// nullptr (after printing MuJoCo's message) when MuJoCo refuses the model.
inline mjModel* loadModelXml(const std::string& xml, const std::string& path) {
  std::ofstream(path) << xml;
  char error[1000] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  std::remove(path.c_str());
  if (!m) std::fprintf(stderr, "MuJoCo: %s\n", error);
  return m;
}

// Wall and CPU seconds since it was made (CPU: the process's, std::clock).
struct StepTimer {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::clock_t cpuStart = std::clock();

  double wall() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  double cpu() const { return static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC; }
};
