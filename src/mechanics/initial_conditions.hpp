#pragma once
// Initial-condition analysis (docs/theory.md §7): find redundant constraint equations, assemble
// positions with the least change to the data set, then velocities, then accelerations and
// constraint forces. The same solves give kinematic analysis and consistent outputs.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

// The linear algebra of the set-up solves below (docs/theory.md §7). Dense: the original
// O(bodies^3) factorisations (QR, complete orthogonal decomposition, full-pivot LU). Sparse:
// the sparse constraint Jacobian, a sparse rank-revealing QR for the redundant equations and
// sparse LU factorisations of saddle-point systems (mechanics/saddle_point_solver.hpp), O(N)-ish
// for chains and trees. Automatic: dense below kSparseFromBodies moving bodies, sparse from
// there on. Measured on spatial revolute chains (docs/theory.md §7): the sparse acceleration
// solve is already 5x faster at 8 bodies and 60x at 32; below 8 the two cost about the same
// (< 0.3 ms), and the dense path keeps its full-pivot rank verdicts for the small models.
// Both give the same results to round-off (tests/mechanics/sparse_setup_test.cpp).
enum class LinearAlgebra { Automatic, Dense, Sparse };
inline constexpr int kSparseFromBodies = 8;
bool usesSparseAlgebra(const MultibodySystem& system, LinearAlgebra method);

struct RedundancyReport {
  int rank = 0;
  std::vector<int> removed;  // equation indices found redundant (now inactive)
};

// Deactivates every equation whose row of C is a linear combination of earlier rows (earlier
// statements keep their equations, as ADAMS keeps the first of two coaxial hinges).
// A row counts as a combination when its part orthogonal to the earlier kept rows is at most
// kRedundancyTolerance times its norm.
inline constexpr double kRedundancyTolerance = 1e-9;
RedundancyReport removeRedundantConstraints(MultibodySystem& system, const Eigen::VectorXd& y,
                                            LinearAlgebra method = LinearAlgebra::Automatic);

struct AssemblyResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;   // largest |Phi| at the end
  int worstEquation = -1;  // equation with the largest |Phi| at the end
  std::vector<double> partMoves;  // per moving body: how far its CM moved
  std::vector<double> partTurns;  // per moving body: how far it turned (rad)
  // EXACT coordinates the assembly had to change (they conflict with the constraints).
  struct ExactChange {
    int body = -1;
    int coordinate = 0;  // 0-5: X, Y, Z, PSI, THETA, PHI
    double change = 0.0;
  };
  std::vector<ExactChange> exactChanged;
};

// Controls of the position assembly (IC statement, docs/theory.md §7).
struct AssemblyOptions {
  double tolerance = 1e-10;  // largest |Phi| accepted (IC ERROR)
  int maxIterations = 25;    // IC MAXIT
  double translationLimit = 1e300;  // largest translation of a body per iteration (TLIMIT)
  double angleLimit = 1e300;        // largest rotation of a body per iteration (ALIMIT, rad)
  std::array<bool, 10> pattern = {true, true, true, true, true,
                                  true, true, true, true, true};  // re-form C at iteration j
  // Hold the coordinates PART/EXACT names: they weigh kExactWeight times a free coordinate.
  bool honourExact = false;
  static constexpr double kExactWeight = 1e12;
  // Hold the joints' initial displacements (JOINT IC=, ICTRAN=, ICROT=) as extra equations of
  // this solve only (ConstraintSet::jointInitialConditions; they are not part of the DAE).
  bool holdJointInitialConditions = false;
  LinearAlgebra linearAlgebra = LinearAlgebra::Automatic;
};

// Positions: Gauss-Newton with minimum-norm corrections of body positions and orientations.
AssemblyResult assemblePositions(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                                 double tolerance, int maxIterations);
// The same with step limits, a Jacobian pattern and EXACT coordinates: the least change in the
// weighted sense, EXACT coordinates (X, Y, Z of the CM; 3-1-3 angles of the body frame) weighing
// kExactWeight times the others.
AssemblyResult assemblePositions(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                                 const AssemblyOptions& options);
// TLIMIT / ALIMIT (IC, KINEMATICS, EQUILIBRIUM): the factor, at most 1, that scales a whole
// body correction (6 entries a body: translation, rotation) so that no body moves more than
// translationLimit along an axis or turns more than angleLimit.
double limitedCorrectionScale(const Eigen::VectorXd& delta, int bodies, double translationLimit,
                              double angleLimit);

// Applies a correction of body positions (ground) and body-axes rotations (6 per body).
void applyBodyCorrection(const StateLayout& layout, const Eigen::VectorXd& delta,
                         Eigen::VectorXd& y);

// Velocities satisfying C u = Phi_t-terms, changing given velocities as little as possible
// (a velocity given in the data set weighs 1e6 times an unset one).
// With holdJointInitialConditions, the joints' initial velocities (second values of IC=,
// ICTRAN=, ICROT=) are held as extra equations of this solve.
void solveVelocities(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                     bool holdJointInitialConditions = false,
                     LinearAlgebra method = LinearAlgebra::Automatic);

// Accelerations and multipliers from [M C^T; C 0][u'; lambda] = [Q; gamma]. Fills y' for the
// integrator (r' = v, e' from w, v', w') and the multipliers in y. Returns false if singular.
// The sparse path keeps its symbolic analysis per thread and reuses it while the KKT
// pattern is the same (every output step of a run).
bool solveAccelerations(const MultibodySystem& system, double t, Eigen::VectorXd& y,
                        Eigen::VectorXd& yp, LinearAlgebra method = LinearAlgebra::Automatic);

// The active constraint equations (those not found redundant), in equation order.
std::vector<int> activeRows(const MultibodySystem& system);

// C over the active equations (rows) and moving bodies (6 columns each).
Eigen::MatrixXd activeConstraintJacobian(const MultibodySystem& system, const double* y,
                                         std::vector<int>* rows);

}  // namespace openmss::mechanics
