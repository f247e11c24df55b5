#include "model/beam_stiffness.hpp"

namespace openmss::model {

Eigen::Matrix<double, 6, 6> beamStiffness(const BeamSection& s) {
  const double l = s.length, e = s.emodulus, g = s.gmodulus, a = s.area;
  // Shear flexibility relative to bending flexibility, per bending plane. With it, a tip load
  // P gives the Timoshenko deflection P L^3 / (3 E I) + P L as / (G A) and the slope
  // P L^2 / (2 E I) (tests/mechanics/force_elements_test.cpp solves this).
  const double phiY = 12.0 * e * s.izz * s.asy / (g * a * l * l);  // deflection along y
  const double phiZ = 12.0 * e * s.iyy * s.asz / (g * a * l * l);  // deflection along z
  Eigen::Matrix<double, 6, 6> k = Eigen::Matrix<double, 6, 6>::Zero();
  k(0, 0) = e * a / l;              // axial
  k(3, 3) = g * s.ixx / l;          // torsion
  // Bending in the x-y plane: deflection y and rotation c about z (c = dy/dx).
  k(1, 1) = 12.0 * e * s.izz / (l * l * l * (1.0 + phiY));
  k(1, 5) = k(5, 1) = -6.0 * e * s.izz / (l * l * (1.0 + phiY));
  k(5, 5) = (4.0 + phiY) * e * s.izz / (l * (1.0 + phiY));
  // Bending in the x-z plane: deflection z and rotation b about y (b = -dz/dx).
  k(2, 2) = 12.0 * e * s.iyy / (l * l * l * (1.0 + phiZ));
  k(2, 4) = k(4, 2) = 6.0 * e * s.iyy / (l * l * (1.0 + phiZ));
  k(4, 4) = (4.0 + phiZ) * e * s.iyy / (l * (1.0 + phiZ));
  return k;
}

}  // namespace openmss::model
