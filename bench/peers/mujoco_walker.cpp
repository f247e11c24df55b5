// The walker of bench/walking_foot.py in MuJoCo (Debian libmujoco-dev), the peer figure:
//
//   mujoco_walker END DT
//
// The same bodies, masses, inertias and joints: a carriage sliding along x, a pelvis (20 kg)
// sliding along z on it, two legs of thigh, shank and box foot on hinges about y. MuJoCo has
// no prescribed joint motion in 2.2, so each hinge follows the data set's MOTION function
// through a stiff position servo (about 100 rad/s, critically damped; gains below); the feet touch
// a box floor through MuJoCo's own soft contacts with friction 0.7 (condim 3), not the IMPACT law.
// RK4 at the fixed step DT to END. Prints key=value lines: wall, cpu (s, over the steps), steps,
// walked (the carriage's x at END, m), lowest (the pelvis's lowest height over the steps, m), depth
// (the deepest sole corner below the floor at the outputs every 0.01 s, as bench/walking_foot.py
// reads OpenMSS's, m). A cost figure beside OpenMSS's, not the same trajectory.
//
//   g++ -std=c++20 -O2 -o mujoco_walker bench/peers/mujoco_walker.cpp -lmujoco

#include <mujoco/mujoco.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>

#include "mujoco_support.hpp"

namespace {

constexpr double kH = 0.865;  // the pelvis height at t = 0 (bench/walking_foot.py's H)

// bench/walking_foot.py's angles(): hip, knee, ankle of the leg of the given phase at t.
void angles(double t, double phase, double out[3]) {
  const double x = std::clamp(t / 0.5, 0.0, 1.0);
  const double ramp = x * x * (3.0 - 2.0 * x);  // STEP(TIME, 0, 0, 0.5, 1)
  const double s = std::sin(2.0 * M_PI * t + phase), c = std::cos(2.0 * M_PI * t + phase);
  const double w = (1.0 - s) / 2.0;
  out[0] = ramp * (-0.3 * c);
  out[1] = ramp * 0.8 * w * w * w;
  out[2] = -out[0] - out[1];
}

std::string model(double dt) {
  std::ostringstream x;
  x.precision(12);
  x << "<mujoco><option timestep=\"" << dt << "\" integrator=\"RK4\" gravity=\"0 0 -9.81\"/>"
    << "<default><geom friction=\"0.7 0.005 0.0001\" condim=\"3\"/></default><worldbody>"
    << "<geom type=\"box\" pos=\"3 0 -0.05\" size=\"5 1 0.05\"/>"
    << "<body pos=\"0 0 " << kH << "\"><joint type=\"slide\" axis=\"1 0 0\"/>"
    << "<inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"0.01 0.01 0.01\"/>"
    << "<body><joint type=\"slide\" axis=\"0 0 1\"/>"
    << "<inertial pos=\"0 0 0\" mass=\"20\" diaginertia=\"0.3 0.3 0.3\"/>";
  // Servo gains per joint from the inertia it moves (about 1.6, 0.27 and 0.008 kg m^2 for the
  // hip, knee and ankle): kp = I w^2 and damping 2 I w with w = 100 rad/s, critically damped,
  // and the damping's time I / c = 5 ms far above DT (a stiffer ankle servo made RK4 unstable).
  const char* hip = "<joint type=\"hinge\" axis=\"0 1 0\" damping=\"320\"/>";
  const char* knee = "<joint type=\"hinge\" axis=\"0 1 0\" damping=\"54\"/>";
  const char* ankle = "<joint type=\"hinge\" axis=\"0 1 0\" damping=\"1.6\"/>";
  for (const double y : {-0.1, 0.1}) {
    x << "<body pos=\"0 " << y << " 0\">" << hip
      << "<inertial pos=\"0 0 -0.2\" mass=\"3\" diaginertia=\"0.04 0.04 0.002\"/>"
      << "<body pos=\"0 0 -0.4\">" << knee
      << "<inertial pos=\"0 0 -0.2\" mass=\"2\" diaginertia=\"0.027 0.027 0.001\"/>"
      << "<body pos=\"0 0 -0.4\">" << ankle
      << "<inertial pos=\"0.05 0 -0.04\" mass=\"1\" diaginertia=\"0.001 0.004 0.004\"/>"
      << "<geom type=\"box\" pos=\"0.05 0 -0.04\" size=\"0.1 0.05 0.02\"/>"
      << "</body></body></body>";
  }
  x << "</body></body></worldbody><actuator>";
  const double kp[3] = {16000, 2700, 80};
  for (int j = 2; j < 8; ++j)
    x << "<position joint=\"j" << j << "\" kp=\"" << kp[(j - 2) % 3] << "\"/>";
  x << "</actuator></mujoco>";
  // Name the hinges j2..j7 (qpos order): the joints above are unnamed, so add the names here.
  std::string s = x.str();
  int next = 2;
  for (size_t at = s.find("<joint type=\"hinge\""); at != std::string::npos;
       at = s.find("<joint type=\"hinge\"", at + 1))
    s.insert(at + 7, "name=\"j" + std::to_string(next++) + "\" ");
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: mujoco_walker END DT\n");
    return 2;
  }
  const double end = std::atof(argv[1]), dt = std::atof(argv[2]);
  const std::string path = "/tmp/openmss_mujoco_walker.xml";
  mjModel* m = loadModelXml(model(dt), path);
  if (!m) return 1;
  mjData* d = mj_makeData(m);
  const StepTimer timer;
  long steps = 0;
  const long outputEvery = std::max(1L, std::lround(0.01 / dt));  // every 0.01 s
  double lowest = kH, depth = -1.0;
  while (d->time < end - 0.5 * dt) {
    for (int leg = 0; leg < 2; ++leg) angles(d->time, leg == 0 ? 0.0 : M_PI, d->ctrl + 3 * leg);
    mj_step(m, d);
    ++steps;
    lowest = std::min(lowest, kH + d->qpos[1]);
    if (steps % outputEvery != 0) continue;  // the sole depth at the outputs, as OpenMSS's
    for (int g = 1; g < m->ngeom; ++g) {     // the feet: their four sole corners
      const double* p = d->geom_xpos + 3 * g;
      const double* r = d->geom_xmat + 9 * g;
      for (const double cx : {-0.1, 0.1})
        for (const double cy : {-0.05, 0.05})
          depth = std::max(depth, -(p[2] + r[6] * cx + r[7] * cy + r[8] * -0.02));
    }
  }
  const double wall = timer.wall();
  const double cpu = timer.cpu();
  std::printf("wall=%.6f\ncpu=%.6f\nsteps=%ld\nwalked=%.9f\nlowest=%.9f\ndepth=%.9f\n", wall, cpu,
              steps, d->qpos[0], lowest, depth);
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
