#pragma once
// Linearization of the equations of motion about an operating point (LINEAR/EIGENSOL and
// LINEAR/STATEMAT, docs/theory.md "Linear analysis"). The constraints are eliminated with a
// basis of the directions they allow; the result is the first-order system x' = A x + B u,
// y = C x + D u in the minimal coordinates (positions and velocities along that basis, then
// the user differential states), with every derivative taken exactly by forward-mode AD of
// MultibodySystem::residual.

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "mechanics/multibody_system.hpp"

namespace openmss::analysis {

// How the minimal position coordinates are chosen. Both span the same directions, so the
// eigenvalues do not depend on the choice; the state matrices do.
enum class LinearBasis {
  // An orthonormal basis of the null space of C (ground coordinates, below): the numerically
  // best-conditioned choice, used for eigenvalues and mode shapes.
  Orthonormal,
  // Part coordinates: state j is one coordinate of one part (the n best-conditioned ones,
  // chosen by column-pivoted QR), every other coordinate following it through the linearised
  // constraints. Used for state matrices, whose states must be named.
  PartCoordinates,
};

struct LinearizationRequest {
  LinearBasis basis = LinearBasis::Orthonormal;
  std::vector<int> inputs;      // plant inputs: indices into Model::variables (PINPUT)
  std::vector<int> outputs;     // plant outputs: indices into Model::variables (POUTPUT)
  bool withoutDamping = false;  // NODAMPIN: drop the velocity terms of the balance equations
};

// The coordinates of a part's position perturbation, all in ground axes: a translation of the
// CM (X, Y, Z) and a small rotation (RX, RY, RZ) about the ground axes. Coordinate 6 b + k of
// moving body b.
struct LinearSystem {
  int degreesOfFreedom = 0;  // n: minimal position coordinates
  int userStates = 0;        // user differential states (DIFF, LSE, TFSISO) after the 2 n
  // x = [z (n positions), z' (n velocities), user differential states]; u = PINPUT variables;
  // y = POUTPUT variables.
  Eigen::MatrixXd a, b, c, d;
  // Columns: the ground-coordinate perturbation of every part per unit of each position
  // coordinate z_j (6 rows per moving body).
  Eigen::MatrixXd positionBasis;
  // Second-order matrices of the mechanical part in z (M z'' + C z' + K z = ...), for reports.
  Eigen::MatrixXd mass, damping, stiffness;
  std::vector<std::string> stateNames;  // one per state: "PART/2 X", "PART/2 VX", "DIFF/5"
  std::vector<int> inputVariables, outputVariables;  // indices into Model::variables
  std::vector<std::string> inputNames;               // "VARIABLE/3"
  std::vector<std::string> outputNames;              // "VARIABLE/4"
};

// "X", "Y", "Z", "RX", "RY", "RZ" of the ground coordinates, and their rates "VX" ... "WZ".
const char* partCoordinateName(int k, bool rate);

// Linearises the DAE about (t, y, yp), which must be a consistent point (positions assembled,
// multipliers and accelerations from solveAccelerations or a converged step, or a static
// equilibrium). Returns false with the reason in *whyNot when the model has no degree of
// freedom or the linearised equations cannot be put in state-space form.
bool linearize(const mechanics::MultibodySystem& system, double t, const Eigen::VectorXd& y,
               const Eigen::VectorXd& yp, const LinearizationRequest& request, LinearSystem& out,
               std::string* whyNot);

// Dimension of the space of motions the active constraints allow at y (6 nb - rank C).
int tangentDimension(const mechanics::MultibodySystem& system, const Eigen::VectorXd& y);

}  // namespace openmss::analysis
