// The force-element and user-equation entries of the element-local Newton matrix
// (local_newton_matrix.hpp): compressed forward AD, one pass of their residual rows per colour.
// The passes are independent, so they may run on the thread pool (common/parallel_for.hpp,
// docs/architecture.md "Threads"): each block of colours has its own dual state, and each value
// entry belongs to exactly one column, hence to one colour, so it receives exactly one addition
// whichever thread computes it: the matrix is bit-identical for any thread count.

#include "common/parallel_for.hpp"
#include "mechanics/local_newton_matrix.hpp"
#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {
namespace {

// Below this many force elements a pass is too short (a few microseconds) to pay for waking a
// worker; measured on the bushing chain, where a pass costs about 1 us per element.
constexpr size_t kParallelElements = 32;

}  // namespace

bool LocalNewtonMatrix::coloursMayRunInParallel() const {
  // Conservative: only elements whose loads are pure functions of the state and their own
  // constant data. SFORCE, VFORCE, GFORCE, FRICTION, NFORCE and CONTACT evaluate expressions
  // (shared scratch, DELAY histories), user subroutines or run-state anchors: serial.
  const StateLayout& l = system_.layout();
  if (l.userDifferential != 0 || l.userAlgebraic != 0) return false;
  // Only the elements the colour passes evaluate: the state-local ones are formed element by
  // element (local_newton_forces.cpp), so with them planned there no element qualifies here.
  const auto& elements = system_.forceElements().elements();
  size_t coloured = 0;
  for (char skip : forceSkip_) coloured += skip == 0 ? 1 : 0;
  if (coloured < kParallelElements) return false;
  for (size_t k = 0; k < elements.size(); ++k) {
    const ForceElementRef& e = elements[k];
    if (forceSkip_[k] != 0) continue;
    if (e.kind != ForceElementKind::SpringDamper && e.kind != ForceElementKind::LinearField)
      return false;
    // A FIELD with FUNCTION=USER calls user code (FIESUB): serial too.
    if (e.kind == ForceElementKind::LinearField &&
        system_.model().linearFields[static_cast<size_t>(e.index)].user)
      return false;
  }
  return true;
}

void LocalNewtonMatrix::forceAndUserColours(double t, const Eigen::VectorXd& y,
                                            const Eigen::VectorXd& yp, double cj, double* values,
                                            SparseJacobianWork& work) {
  if (forceAndUser_.nonZeros() == 0) return;
  using D = Dual<double>;
  const StateLayout& l = system_.layout();
  const int n = l.size();
  const JacobianPattern& p = forceAndUser_;
  const int blocks = parallelColours_ ? std::min(threadCount(), p.colours()) : 1;
  if (static_cast<int>(blockDuals_.size()) < blocks - 1)
    blockDuals_.resize(static_cast<size_t>(blocks - 1));
  auto run = [&](int block, int first, int last) {
    std::vector<D>& dy = block == 0 ? work.y : blockDuals_[static_cast<size_t>(block - 1)].y;
    std::vector<D>& dyp = block == 0 ? work.yp : blockDuals_[static_cast<size_t>(block - 1)].yp;
    std::vector<D>& dg = block == 0 ? work.g : blockDuals_[static_cast<size_t>(block - 1)].g;
    dy.resize(static_cast<size_t>(n));
    dyp.resize(static_cast<size_t>(n));
    dg.resize(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) {
      dy[i] = D(y(i), 0.0);
      dyp[i] = D(yp(i), 0.0);
    }
    for (int colour = first; colour < last; ++colour) {
      const int begin = p.colourStart[colour], end = p.colourStart[colour + 1];
      for (int k = begin; k < end; ++k) {
        const int c = p.colourColumns[k];
        dy[c].d = 1.0;
        dyp[c].d = l.differential(c) ? cj : 0.0;
      }
      for (int r : forceAndUserRows_) dg[r] = D(0.0, 0.0);
      // Only dg's derivatives are read below: the CONTACTs whose parts this colour does not
      // seed are left out (their derivatives are exactly zero; theory §6c, "Shared kinematics").
      system_.forceAndUserResidual(t, dy.data(), dyp.data(), dg.data(), true, forceSkip_.data());
      for (int k = begin; k < end; ++k) {
        const int c = p.colourColumns[k];
        for (int e = p.columnStart[c]; e < p.columnStart[c + 1]; ++e)
          values[forceAndUserIndex_[e]] += dg[p.rowIndex[e]].d;
        dy[c].d = 0.0;
        dyp[c].d = 0.0;
      }
    }
  };
  if (blocks <= 1) {
    run(0, 0, p.colours());  // the serial path, on the caller's work vectors
    return;
  }
  parallelFor(p.colours(), run);
}

}  // namespace openmss::mechanics
