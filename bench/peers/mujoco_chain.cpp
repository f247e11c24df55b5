// The benchmark pendulum chains in MuJoCo (Debian libmujoco-dev 2.2.2), for scripts/bench.sh.
//
//   mujoco_chain KIND N END DT [INTEGRATOR]
//
// KIND: chain-planar | chain-spatial | chain-stiff4 | chain-stiff8 (the stiff chains' joint
// springs as hinge stiffness and damping). INTEGRATOR: RK4 (default), Euler (semi-implicit,
// joint damping implicit) or implicit (implicit in velocity). Builds the chain of
// bench/model_generators.cpp as MJCF
// (nested bodies with hinge joints, the same inertias, gravity and initial state), integrates
// with RK4 at a fixed step DT to END, and prints key=value lines: wall times, steps, the tip's
// final position and velocity, and peak resident memory. Contacts are disabled (no geoms).
// The four-bar row and the bushing chain are not built here: MuJoCo closes loops only through
// soft equality constraints, and it has no bushing element, so their results would not be the
// same model.

#include <mujoco/mujoco.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "../model_generators.hpp"

namespace {

using openmss::bench::ChainModel;
using openmss::bench::Vec3;

std::string vec(const Vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << v[0] << ' ' << v[1] << ' ' << v[2];
  return s.str();
}

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// Body frames sit at each link's proximal joint point with ground-aligned axes, so qpos = 0 is
// the generator's initial configuration. MuJoCo's XML parser refuses nesting deeper than about
// 100 elements, so the nested bodies are split into files of kLinksPerFile links, each one
// <include>d inside the last body of the previous file (includes are expanded after parsing).
constexpr int kLinksPerFile = 50;

std::string bodies(const ChainModel& m, int first, int last, const std::string& nextFile) {
  std::ostringstream x;
  x.precision(17);
  for (int i = first; i < last; ++i) {
    const auto& b = m.bodies[i];
    const Vec3 parentOrigin = i == 0 ? Vec3{0, 0, 0} : m.bodies[i - 1].proximal;
    const auto inertia = openmss::bench::inertiaTensorInGround(b);
    x << "<body name=\"link" << i << "\" pos=\"" << vec(minus(b.proximal, parentOrigin))
      << "\">\n"
      << "<joint type=\"hinge\" pos=\"0 0 0\" axis=\"" << vec(m.joints[i].axis) << "\""
      << " stiffness=\"" << m.jointSpring.stiffness << "\" damping=\"" << m.jointSpring.damping
      << "\"/>\n"
      << "<inertial pos=\"" << vec(minus(b.centerOfMass, b.proximal)) << "\" mass=\"" << b.mass
      << "\" fullinertia=\"" << inertia[0] << ' ' << inertia[4] << ' ' << inertia[8] << ' '
      << inertia[1] << ' ' << inertia[2] << ' ' << inertia[5] << "\"/>\n";
    if (i + 1 == static_cast<int>(m.bodies.size()))
      x << "<site name=\"tip\" pos=\"" << vec(minus(b.distal, b.proximal)) << "\"/>\n";
  }
  if (!nextFile.empty()) x << "<include file=\"" << nextFile << "\"/>\n";
  for (int i = first; i < last; ++i) x << "</body>";
  x << "\n";
  return x.str();
}

// Writes the model files into `dir`; returns the main file.
std::string writeMjcf(const ChainModel& m, const std::string& dir, const std::string& integrator) {
  const int n = static_cast<int>(m.bodies.size());
  const int files = (n + kLinksPerFile - 1) / kLinksPerFile;
  auto name = [](int k) { return "part" + std::to_string(k) + ".xml"; };
  for (int k = 1; k < files; ++k) {
    const int last = std::min(n, (k + 1) * kLinksPerFile);
    std::ofstream(dir + "/" + name(k))
        << "<mujoco>\n"
        << bodies(m, k * kLinksPerFile, last, k + 1 < files ? name(k + 1) : "") << "</mujoco>\n";
  }
  std::ostringstream x;
  x.precision(17);
  x << "<mujoco model=\"chain\">\n"
    << "  <compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n"
    << "  <option gravity=\"" << vec(m.gravity) << "\" integrator=\"" << integrator << "\">\n"
    << "    <flag contact=\"disable\"/>\n  </option>\n  <worldbody>\n"
    << bodies(m, 0, std::min(n, kLinksPerFile), files > 1 ? name(1) : "")
    << "  </worldbody>\n</mujoco>\n";
  const std::string main = dir + "/chain.xml";
  std::ofstream(main) << x.str();
  return main;
}

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5 && argc != 6) {
    std::cerr << "usage: mujoco_chain chain-planar|chain-spatial|chain-stiff4|chain-stiff8 N END "
                 "DT [RK4|Euler|implicit]\n";
    return 64;
  }
  const std::string kind = argv[1];
  const std::string integrator = argc == 6 ? argv[5] : "RK4";
  if (kind != "chain-planar" && kind != "chain-spatial" && kind != "chain-stiff4" &&
      kind != "chain-stiff8") {
    std::cerr << "mujoco_chain: " << kind << " is not built for MuJoCo (see the file header)\n";
    return 3;
  }
  const int links = std::stoi(argv[2]);
  const double end = std::stod(argv[3]);
  const double dt = std::stod(argv[4]);
  const auto t0 = std::chrono::steady_clock::now();
  const ChainModel model = openmss::bench::modelByName(kind, links);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("openmss-mujoco-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = writeMjcf(model, dir.string(), integrator);
  char error[1000] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
  std::filesystem::remove_all(dir);
  if (m == nullptr) {
    std::cerr << "mujoco_chain: " << error << "\n";
    return 2;
  }
  m->opt.timestep = dt;
  mjData* d = mj_makeData(m);
  const auto t1 = std::chrono::steady_clock::now();
  const long steps = std::lround(end / dt);
  for (long k = 0; k < steps; ++k) mj_step(m, d);
  const auto t2 = std::chrono::steady_clock::now();
  // mj_step leaves derived quantities at the start of its last step: recompute them.
  mj_forward(m, d);
  const int tip = mj_name2id(m, mjOBJ_SITE, "tip");
  mjtNum velocity[6];  // angular, then linear, in world axes
  mj_objectVelocity(m, d, mjOBJ_SITE, tip, velocity, 0);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("engine=mujoco\nsetting=%s dt=%g\nbuild_s=%.6f\nintegrate_s=%.6f\nsteps=%ld\n",
              integrator.c_str(), dt,
              seconds(t0, t1), seconds(t1, t2), steps);
  std::printf("time=%.17g\n", d->time);
  std::printf("tip=%.17g %.17g %.17g %.17g %.17g %.17g\n", d->site_xpos[3 * tip],
              d->site_xpos[3 * tip + 1], d->site_xpos[3 * tip + 2], velocity[3], velocity[4],
              velocity[5]);
  std::printf("rss_mb=%.1f\n", static_cast<double>(usage.ru_maxrss) / 1024.0);
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
