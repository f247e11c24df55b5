// The contact pile of bench/contact_pile.py in MuJoCo (Debian libmujoco-dev), the peer figure:
//
//   mujoco_pile N K END DT
//
// N spheres (radius 0.05, mass 0.1) on the same jittered K x K grid in layers 0.12 apart, an
// open box of the same floor and walls (box geoms), gravity 9.81; RK4 at the fixed step DT to
// END. Prints key=value lines: wall (s), cpu (s, the process's CPU time over the steps), steps,
// mean_height (m). MuJoCo's contacts are its own
// soft constraints (default solref/solimp, no friction: condim 1), not the IMPACT law: the
// figure is a cost per step of a comparable pile, not the same trajectory.
//
//   g++ -std=c++20 -O2 -o mujoco_pile bench/peers/mujoco_pile.cpp -lmujoco

#include <mujoco/mujoco.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>

#include "mujoco_support.hpp"

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: mujoco_pile N K END DT\n");
    return 2;
  }
  const int n = std::atoi(argv[1]), k = std::atoi(argv[2]);
  const double end = std::atof(argv[3]), dt = std::atof(argv[4]);
  const double radius = 0.05, spacing = 0.12, half = k * spacing / 2 + 0.01;
  // MuJoCo 2.2 allocates dense njmax x njmax arrays: 60 rows per sphere up to N = 100 (the
  // figures measured so far), 4 above (a heap has about 3 contact rows per sphere: condim 1);
  // 60 per sphere at N = 1000 could not be allocated ("could not create mjData").
  const int njmax = n <= 100 ? 60 * n + 300 : 4 * n + 300;
  std::ostringstream x;
  x.precision(12);
  x << "<mujoco><option timestep=\"" << dt << "\" integrator=\"RK4\" gravity=\"0 0 -9.81\"/>"
    << "<size nconmax=\"" << 20 * n + 100 << "\" njmax=\"" << njmax
    << "\"/><default><geom condim=\"1\"/></default><worldbody>";
  // Floor (top at z = 0) and walls, as bench/contact_pile.py's BOX solids (centre, half sizes).
  const double w = half + 0.1;
  x << "<geom type=\"box\" pos=\"0 0 -0.05\" size=\"" << w << " " << w << " 0.05\"/>";
  x << "<geom type=\"box\" pos=\"" << -half - 0.05 << " 0 1\" size=\"0.05 " << w << " 1\"/>";
  x << "<geom type=\"box\" pos=\"" << half + 0.05 << " 0 1\" size=\"0.05 " << w << " 1\"/>";
  x << "<geom type=\"box\" pos=\"0 " << -half - 0.05 << " 1\" size=\"" << half << " 0.05 1\"/>";
  x << "<geom type=\"box\" pos=\"0 " << half + 0.05 << " 1\" size=\"" << half << " 0.05 1\"/>";
  long long state = 12345;
  for (int i = 0; i < n; ++i) {
    const int layer = i / (k * k), cell = i % (k * k), row = cell / k, col = cell % k;
    double jitter[2];
    for (double& j : jitter) {
      state = (1103515245LL * state + 12345) % 2147483648LL;
      j = (static_cast<double>(state) / 2147483648.0 - 0.5) * 1e-3 * spacing;
    }
    x << "<body pos=\"" << (col - (k - 1) / 2.0) * spacing + jitter[0] << " "
      << (row - (k - 1) / 2.0) * spacing + jitter[1] << " " << radius + 0.02 + layer * spacing
      << "\"><freejoint/><geom type=\"sphere\" size=\"" << radius << "\" mass=\"0.1\"/></body>";
  }
  x << "</worldbody></mujoco>";
  // MuJoCo 2.2 loads XML from files: write it next to the working directory's temporary files.
  const std::string path = "/tmp/openmss_mujoco_pile_" + std::to_string(n) + ".xml";
  mjModel* m = loadModelXml(x.str(), path);
  if (!m) return 1;
  mjData* d = mj_makeData(m);
  const StepTimer timer;
  long steps = 0;
  while (d->time < end - 0.5 * dt) {
    mj_step(m, d);
    ++steps;
  }
  const double wall = timer.wall();
  const double cpu = timer.cpu();
  double height = 0.0;
  for (int i = 0; i < n; ++i) height += d->qpos[7 * i + 2];
  std::printf("wall=%.6f\ncpu=%.6f\nsteps=%ld\nmean_height=%.9f\n", wall, cpu, steps, height / n);
  // Contacts dropped because njmax or nconmax was too small (the figure is then not valid).
  std::printf("constraint_full_warnings=%d\ncontact_full_warnings=%d\n",
              d->warning[mjWARN_CNSTRFULL].number, d->warning[mjWARN_CONTACTFULL].number);
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
