#pragma once
// The 6x6 stiffness matrix of a linear (Timoshenko) BEAM element, relating the displacement
// q = (x - LENGTH, y, z, a, b, c) of its I end relative to its J end (J axes, the neutral axis
// along x_J) to the elastic force and torque on I: {F; T} = -K q (docs/theory.md §6).

#include <Eigen/Dense>

namespace openmss::model {

struct BeamSection {
  double length = 0.0;    // LENGTH: undeformed distance from J to I along x_J
  double area = 0.0;      // AREA
  double ixx = 0.0;       // IXX: torsional constant
  double iyy = 0.0;       // IYY: area moment about y (bending in the x-z plane)
  double izz = 0.0;       // IZZ: area moment about z (bending in the x-y plane)
  double emodulus = 0.0;  // EMODULUS
  double gmodulus = 0.0;  // GMODULUS
  double asy = 0.0;       // ASY: shear area ratio for deflection along y (0: no shear)
  double asz = 0.0;       // ASZ: shear area ratio for deflection along z (0: no shear)
};

// The clamped-J stiffness of the beam: a cantilever built in at J and loaded at I.
Eigen::Matrix<double, 6, 6> beamStiffness(const BeamSection& s);

}  // namespace openmss::model
