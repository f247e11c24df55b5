#include "mechanics/massless_motions.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mechanics/initial_conditions.hpp"
#include "mechanics/sparse_constraint_jacobian.hpp"

namespace openmss::mechanics {
namespace {

// A principal moment at most this fraction of the body's largest one (or exactly zero) counts
// as zero: the parallel-axis transfer of a point mass leaves round-off of ~1e-16 of it.
constexpr double kZeroMomentFraction = 1e-12;
// Columns of C E are normalised; a pivot of the rank-revealing QR below this is a dependent
// direction. Constraint rows are built from unit vectors, so their round-off is ~1e-15.
constexpr double kRankTolerance = 1e-9;

}  // namespace

std::vector<UnheldMotion> unheldMasslessMotions(const MultibodySystem& system, const double* y) {
  const int nb = system.layout().bodies;
  // E: the unit motions (columns of the 6-per-body velocity space) with zero inertia.
  std::vector<UnheldMotion> motions;
  std::vector<Eigen::Matrix<double, 6, 1>> columns;
  for (int b = 0; b < nb; ++b) {
    if (!(system.bodyMass(b) > 0.0))
      for (int k = 0; k < 3; ++k) {
        UnheldMotion u{b, false, Eigen::Vector3d::Unit(k)};
        motions.push_back(u);
      }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(system.bodyInertia(b));
    const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
    for (int k = 0; k < 3; ++k)
      if (eig.eigenvalues()(k) <= kZeroMomentFraction * largest)
        motions.push_back(UnheldMotion{b, true, eig.eigenvectors().col(k)});
  }
  if (motions.empty()) return {};
  const std::vector<int> rows = activeRows(system);
  const SparseMatrix c = sparseConstraintJacobian(system, y, rows);
  // C E, dense: as many columns as zero-inertia motions, the rows of C.
  Eigen::MatrixXd ce = Eigen::MatrixXd::Zero(c.rows(), static_cast<Eigen::Index>(motions.size()));
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(ce.cols());
  for (size_t j = 0; j < motions.size(); ++j) {
    const UnheldMotion& u = motions[j];
    const int first = 6 * u.body + (u.rotation ? 3 : 0);
    for (int k = 0; k < 3; ++k)
      for (SparseMatrix::InnerIterator it(c, first + k); it; ++it)
        ce(it.row(), static_cast<Eigen::Index>(j)) += it.value() * u.axis(k);
    const double norm = ce.col(static_cast<Eigen::Index>(j)).norm();
    if (norm > 0.0) {
      ce.col(static_cast<Eigen::Index>(j)) /= norm;
      scale(static_cast<Eigen::Index>(j)) = 1.0 / norm;
    }
  }
  // No constraint rows: every zero-inertia motion is free.
  if (ce.rows() == 0) return motions;
  // The kernel of C E: motions of zero inertia that every constraint allows.
  Eigen::FullPivLU<Eigen::MatrixXd> lu(ce);
  lu.setThreshold(kRankTolerance);
  if (lu.rank() == ce.cols()) return {};
  // One free motion per kernel dimension. Eigen's kernel basis vector k is 1 on the k-th
  // column without a pivot (permutationQ puts those last) and 0 on the others: that column
  // names the body and the kind of motion; the direction is the kernel vector's combination of
  // that body's motions of the same kind (undoing the column scaling).
  const Eigen::MatrixXd kernel = lu.kernel();
  std::vector<UnheldMotion> free;
  for (Eigen::Index k = 0; k < kernel.cols(); ++k) {
    UnheldMotion u = motions[static_cast<size_t>(lu.permutationQ().indices()(lu.rank() + k))];
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    for (size_t j = 0; j < motions.size(); ++j)
      if (motions[j].body == u.body && motions[j].rotation == u.rotation)
        axis += kernel(static_cast<Eigen::Index>(j), k) * scale(static_cast<Eigen::Index>(j)) *
                motions[j].axis;
    if (axis.norm() > 0.0) u.axis = axis.normalized();
    free.push_back(u);
  }
  std::stable_sort(free.begin(), free.end(), [](const UnheldMotion& a, const UnheldMotion& b) {
    return a.body != b.body ? a.body < b.body : a.rotation < b.rotation;
  });
  return free;
}

std::string describeMotion(const UnheldMotion& motion) {
  char axis[96];
  auto clean = [](double v) { return std::abs(v) < 5e-13 ? 0.0 : v; };
  std::snprintf(axis, sizeof axis, "(%.6g, %.6g, %.6g)", clean(motion.axis(0)),
                clean(motion.axis(1)), clean(motion.axis(2)));
  return motion.rotation ? std::string("a rotation about ") + axis + " in its CM axes"
                         : std::string("a translation along ") + axis + " in ground axes";
}

}  // namespace openmss::mechanics
