// RCNVRT and TCNVRT (below). RCNVRT: rotation coordinates from one representation to another
// (c_rcnvrt and its gfortran name rcnvrt_), through the rotation matrix and ADAMS's conventions of
// common/rotation.hpp. Systems: EULER (= B313: psi, theta, phi), EULPAR (e0, e1, e2, e3), RODPAR
// (e/e0), COSINES (nine direction cosines, column by column), YPR (= B321: yaw, pitch, roll) and
// the body-fixed sequences Babc (B123, B231, B312, B132, B213, B321, B121, B131, B212, B232, B313,
// B323): A = R_a(t1) R_b(t2) R_c(t3). docs/user-subroutines.md, "Other utilities".

#include <cctype>
#include <cmath>
#include <cstddef>
#include <string>

#include "common/rotation.hpp"
#include "user/element_call.hpp"
#include "user/openmss_usersub.h"

namespace {

std::string systemName(const char* text, std::size_t length) {
  std::string s;
  for (std::size_t k = 0; k < length && text[k] != '\0'; ++k)
    s += static_cast<char>(std::toupper(static_cast<unsigned char>(text[k])));
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// Babc / YPR / EULER as an axis sequence (0 = x); false for other names.
bool sequence(const std::string& s, int axes[3]) {
  const std::string name = s == "EULER" ? "B313" : s == "YPR" ? "B321" : s;
  if (name.size() != 4 || name[0] != 'B') return false;
  for (int k = 0; k < 3; ++k) {
    if (name[k + 1] < '1' || name[k + 1] > '3') return false;
    axes[k] = name[k + 1] - '1';
  }
  return axes[0] != axes[1] && axes[1] != axes[2];
}

Eigen::Matrix3d axisRotation(int axis, double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
}

bool toMatrix(const std::string& s, const double* c, Eigen::Matrix3d& a) {
  int axes[3];
  if (s == "EULER") {
    a = openmss::matrixFromEuler313(c[0], c[1], c[2]);
  } else if (sequence(s, axes)) {
    a = axisRotation(axes[0], c[0]) * axisRotation(axes[1], c[1]) * axisRotation(axes[2], c[2]);
  } else if (s == "EULPAR" || s == "RODPAR") {
    const Eigen::Quaterniond q = s == "EULPAR" ? Eigen::Quaterniond(c[0], c[1], c[2], c[3])
                                               : Eigen::Quaterniond(1.0, c[0], c[1], c[2]);
    if (q.norm() == 0.0) return false;
    a = q.normalized().toRotationMatrix();
  } else if (s == "COSINES") {
    for (int k = 0; k < 9; ++k) a(k % 3, k / 3) = c[k];
  } else {
    return false;
  }
  return true;
}

bool fromMatrix(const std::string& s, const Eigen::Matrix3d& a, double* c) {
  int axes[3];
  if (s == "EULER") {
    const Eigen::Vector3d e = openmss::euler313FromMatrix(a);
    for (int k = 0; k < 3; ++k) c[k] = e(k);
  } else if (sequence(s, axes)) {
    const Eigen::Vector3d e = openmss::bodyFixedAngles(a, axes[0], axes[1], axes[2]);
    for (int k = 0; k < 3; ++k) c[k] = e(k);
  } else if (s == "EULPAR") {
    const Eigen::Vector4d q = openmss::quaternionFromMatrix(a);
    for (int k = 0; k < 4; ++k) c[k] = q(k);
  } else if (s == "RODPAR") {
    const Eigen::Vector4d q = openmss::quaternionFromMatrix(a);
    if (q(0) == 0.0) return false;  // a half turn has no Rodriguez parameters
    for (int k = 0; k < 3; ++k) c[k] = q(k + 1) / q(0);
  } else if (s == "COSINES") {
    for (int k = 0; k < 9; ++k) c[k] = a(k % 3, k / 3);
  } else {
    return false;
  }
  return true;
}

void convert(const std::string& from, const double* c1, const std::string& to, double* c2,
             int* istat) {
  Eigen::Matrix3d a;
  *istat = toMatrix(from, c1, a) && fromMatrix(to, a, c2) ? 0 : 1;
}

// TCNVRT: a point's coordinates between CARTESIAN (x, y, z), CYLINDRICAL (r, theta, z) and
// SPHERICAL (rho, phi, theta); theta is the azimuth from +x towards +y (atan2, -pi..pi), phi
// the angle from +z (0..pi). ADAMS names the systems but not the angle conventions; these are
// OpenMSS's (docs/user-subroutines.md, "Other utilities").
bool toCartesian(const std::string& s, const double* c, double p[3]) {
  if (s == "CARTESIAN") {
    p[0] = c[0], p[1] = c[1], p[2] = c[2];
  } else if (s == "CYLINDRICAL") {
    p[0] = c[0] * std::cos(c[1]), p[1] = c[0] * std::sin(c[1]), p[2] = c[2];
  } else if (s == "SPHERICAL") {
    p[0] = c[0] * std::sin(c[1]) * std::cos(c[2]);
    p[1] = c[0] * std::sin(c[1]) * std::sin(c[2]);
    p[2] = c[0] * std::cos(c[1]);
  } else {
    return false;
  }
  return true;
}

bool fromCartesian(const std::string& s, const double p[3], double* c) {
  const double r = std::hypot(p[0], p[1]);
  if (s == "CARTESIAN") {
    c[0] = p[0], c[1] = p[1], c[2] = p[2];
  } else if (s == "CYLINDRICAL") {
    c[0] = r, c[1] = std::atan2(p[1], p[0]), c[2] = p[2];
  } else if (s == "SPHERICAL") {
    c[0] = std::hypot(r, p[2]), c[1] = std::atan2(r, p[2]), c[2] = std::atan2(p[1], p[0]);
  } else {
    return false;
  }
  return true;
}

void convertPoint(const std::string& from, const double* c1, const std::string& to, double* c2,
                  int* istat) {
  double p[3];
  *istat = toCartesian(from, c1, p) && fromCartesian(to, p, c2) ? 0 : 1;
}

}  // namespace

void openmss::user::detail::anchorConversionUtilities() {}

extern "C" {

void c_rcnvrt(const char* sys1, const double* coord1, const char* sys2, double* coord2,
              int* istat) {
  convert(systemName(sys1, std::string::npos), coord1, systemName(sys2, std::string::npos), coord2,
          istat);
}

void rcnvrt_(const char* sys1, const double* coord1, const char* sys2, double* coord2, int* istat,
             std::size_t lsys1, std::size_t lsys2) {
  convert(systemName(sys1, lsys1), coord1, systemName(sys2, lsys2), coord2, istat);
}

void c_tcnvrt(const char* sys1, const double* coord1, const char* sys2, double* coord2,
              int* istat) {
  convertPoint(systemName(sys1, std::string::npos), coord1, systemName(sys2, std::string::npos),
               coord2, istat);
}

void tcnvrt_(const char* sys1, const double* coord1, const char* sys2, double* coord2, int* istat,
             std::size_t lsys1, std::size_t lsys2) {
  convertPoint(systemName(sys1, lsys1), coord1, systemName(sys2, lsys2), coord2, istat);
}

}  // extern "C"
