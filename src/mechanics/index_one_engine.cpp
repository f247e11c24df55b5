// The engine of the index-1 dynamics (mechanics/index_one_engine.hpp): symbolic set-up of the
// block-sparse Schur complement, its factorisation with the singular-row drop rule, and the
// solves (docs/theory.md §9f).
#include "mechanics/index_one_engine.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <map>
#include <type_traits>
#include <utility>

#include "mechanics/constraint_rows.hpp"
#include "mechanics/coupled_accelerations.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/user_state_solve.hpp"

namespace openmss::mechanics {
namespace {

// A pivot of S at most this fraction of its diagonal entry before elimination means the row
// of C is a combination of the rows eliminated before it to working precision: a singular
// configuration (the flat position of a four-bar, docs/theory.md §9d) or a dependency the
// set-up analysis could not see. The row is then dropped from the solve, as the redundancy
// analysis drops a redundant equation at the start: its multiplier is zero and the rows kept
// carry its reaction. The accelerations stay determined (the mechanism's motion satisfies the
// dropped row when it satisfies the others); only the split of the reaction is arbitrary.
//
// "Diagonal entry" is S_cc, except when its two parts, translational (|C_t|^2 / m) and
// rotational (C_r J^-1 C_r^T), differ by more than kPartRatio: then the smaller part. With very
// unequal inertias (the DAE test-set pendulum, a unit point mass with inertia 1e-10) S_cc is
// dominated by the rotational part and a legitimate pivot of a translational row is 1e-10 of
// it (measured: the MERSON pendulum tests failed with S_cc alone), while at a singular
// configuration the pivot is small against both parts. Only the translational part is taken
// so: a rotational part far below the translational one comes from the geometry, not from the
// inertias (a position row whose lever arm points along the row, as in the rods of the IFToMM
// A02 row within 1e-4 rad of its flat configuration: q ~ 3e-8 against t = 2), and taking it
// as the reference kept those nearly dependent rows in the solve there (MERSON at ERROR = 1e-8
// failed at the first flat passage; docs/theory.md §9d). Any pivot at most kRoundOffPivot of
// S_cc is dependent to working precision whatever the parts.
constexpr double kPivotTolerance = 1e-8;
constexpr double kRoundOffPivot = 1e-12;
constexpr double kPartRatio = 1e6;

// The block kernels below are written once with the block size as a template parameter and
// run with it fixed for the common sizes (1-6 rows: every joint, primitive and motion) so that
// the compiler unrolls and vectorises them; N = 0 is the same code with the size at run time.
template <class Kernel>
void withSize(int n, Kernel&& kernel) {
  switch (n) {
    case 1:
      kernel(std::integral_constant<int, 1>{});
      break;
    case 2:
      kernel(std::integral_constant<int, 2>{});
      break;
    case 3:
      kernel(std::integral_constant<int, 3>{});
      break;
    case 4:
      kernel(std::integral_constant<int, 4>{});
      break;
    case 5:
      kernel(std::integral_constant<int, 5>{});
      break;
    case 6:
      kernel(std::integral_constant<int, 6>{});
      break;
    default:
      kernel(std::integral_constant<int, 0>{});
      break;
  }
}

// target (ni x nj, column-major) (+)= a b^T with a (ni x 6) and b (nj x 6) row-major (each
// row's six entries contiguous, as C's rows arrive).
template <int N>
void multiplyTransposed(int niRuntime, int nj, const double* a, const double* b, double* target,
                        bool assign) {
  const int ni = N > 0 ? N : niRuntime;
  for (int c = 0; c < nj; ++c) {
    double* t = target + ni * c;
    const double* bc = b + 6 * c;
    for (int r = 0; r < ni; ++r) {
      const double* ar = a + 6 * r;
      const double sum = ar[0] * bc[0] + ar[1] * bc[1] + ar[2] * bc[2] + ar[3] * bc[3] +
                         ar[4] * bc[4] + ar[5] * bc[5];
      t[r] = assign ? sum : t[r] + sum;
    }
  }
}

// target (ni x nk) -= a (ni x n) b^T (b: nk x n), column-major.
template <int N>
void subtractProduct(int niRuntime, int nk, int n, const double* a, const double* b,
                     double* target) {
  const int ni = N > 0 ? N : niRuntime;
  for (int c = 0; c < nk; ++c) {
    double* t = target + ni * c;
    for (int k = 0; k < n; ++k) {
      const double f = b[c + nk * k];
      const double* ak = a + ni * k;
      for (int r = 0; r < ni; ++r) t[r] -= ak[r] * f;
    }
  }
}

// b (ni x n) <- b L^-T with L lower triangular (n x n) and inverse its diagonal's inverses.
template <int N>
void solveRight(int niRuntime, int n, const double* l, const double* inverse, double* b) {
  const int ni = N > 0 ? N : niRuntime;
  for (int c = 0; c < n; ++c) {
    double* bc = b + ni * c;
    for (int k = 0; k < c; ++k) {
      const double f = l[c + n * k];
      const double* bk = b + ni * k;
      for (int r = 0; r < ni; ++r) bc[r] -= bk[r] * f;
    }
    for (int r = 0; r < ni; ++r) bc[r] *= inverse[c];
  }
}

}  // namespace

IndexOneDynamics::Engine::Engine(const MultibodySystem& sys)
    : system(sys), rows(sys, activeRows(sys)) {
  nb = sys.layout().bodies;
  m = rows.count();
  baselineAccelerations = readsAccelerationsOrReactions(sys.model());
  for (int b = 0; b < nb; ++b) {
    const double mass = sys.bodyMass(b);
    const Eigen::LLT<Eigen::Matrix3d> llt(sys.bodyInertia(b));
    if (!(mass > 0.0) || llt.info() != Eigen::Success) massInvertible = false;
    inverseMass.push_back(mass > 0.0 ? 1.0 / mass : 0.0);
    Eigen::Matrix3d inverse = Eigen::Matrix3d::Zero();
    if (llt.info() == Eigen::Success) inverse = llt.solve(Eigen::Matrix3d::Identity());
    inverseInertia.push_back(inverse);
  }
  // Group the rows by the set of bodies they touch.
  const std::vector<int>& start = rows.start();
  const std::vector<int>& cols = rows.columns();
  std::map<std::vector<int>, int> blockOfSet;
  std::vector<std::vector<int>> blockRows, blockBodies;
  for (int r = 0; r < m; ++r) {
    std::vector<int> bodies;
    for (int i = start[r]; i < start[r + 1]; ++i) bodies.push_back(cols[i] / 6);
    bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());  // cols increase
    auto [it, added] = blockOfSet.try_emplace(bodies, static_cast<int>(blockRows.size()));
    if (added) {
      blockRows.emplace_back();
      blockBodies.push_back(bodies);
    }
    blockRows[it->second].push_back(r);
  }
  const int nBlocks = static_cast<int>(blockRows.size());
  std::vector<std::vector<int>> blocksOfBody(nb);
  for (int j = 0; j < nBlocks; ++j)
    for (int b : blockBodies[j]) blocksOfBody[b].push_back(j);
  // Approximate minimum degree on the block graph (blocks adjacent when they share a body).
  std::vector<int> order(nBlocks);
  for (int j = 0; j < nBlocks; ++j) order[j] = j;
  if (nBlocks > 1) {
    std::vector<Eigen::Triplet<double, int>> pattern;
    for (int b = 0; b < nb; ++b)
      for (int i : blocksOfBody[b])
        for (int j : blocksOfBody[b]) pattern.emplace_back(i, j, 1.0);
    for (int j = 0; j < nBlocks; ++j) pattern.emplace_back(j, j, 1.0);
    Eigen::SparseMatrix<double, Eigen::ColMajor, int> graph(nBlocks, nBlocks);
    graph.setFromTriplets(pattern.begin(), pattern.end());
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> perm;
    Eigen::AMDOrdering<int>()(graph, perm);
    // perm maps the elimination position to the block (Eigen's convention: the inverse of the
    // permutation applied to the matrix).
    for (int k = 0; k < nBlocks; ++k) order[k] = perm.indices()[k];
  }
  blockStart.assign(1, 0);
  positionOf.assign(m, 0);
  for (int k = 0; k < nBlocks; ++k) {
    for (int r : blockRows[order[k]]) {
      positionOf[r] = static_cast<int>(permutedRow.size());
      permutedRow.push_back(r);
    }
    blockStart.push_back(static_cast<int>(permutedRow.size()));
  }
  auto size = [&](int j) { return blockStart[j + 1] - blockStart[j]; };
  // Incidences and the scatter of C's entries into them.
  std::vector<std::vector<int>> incidencesOfBody(nb);
  std::map<std::pair<int, int>, int> incidenceOf;
  int dense = 0;
  for (int k = 0; k < nBlocks; ++k)
    for (int b : blockBodies[order[k]]) {
      incidenceOf[{k, b}] = static_cast<int>(incidences.size());
      incidencesOfBody[b].push_back(static_cast<int>(incidences.size()));
      incidences.push_back({k, b, dense, size(k)});
      dense += 6 * size(k);
    }
  cDense.assign(dense, 0.0);
  w.assign(dense, 0.0);
  segmentTarget.assign(cols.size() / 6, 0);
  static_assert(StateLayout::kW == StateLayout::kV + 3);
  segmentVelocity.assign(cols.size() / 6, 0);
  for (size_t i = 0; i < cols.size(); i += 6)
    segmentVelocity[i / 6] = sys.layout().body(cols[i] / 6) + StateLayout::kV;
  for (int pos = 0; pos < m; ++pos) {
    const int r = permutedRow[pos];
    const int k = static_cast<int>(std::upper_bound(blockStart.begin(), blockStart.end(), pos) -
                                   blockStart.begin()) -
                  1;
    const int within = pos - blockStart[k];
    // A row's entries come in whole bodies: six consecutive columns from direction 0.
    for (int i = start[r]; i < start[r + 1]; i += 6) {
      const Incidence& inc = incidences[incidenceOf.at({k, cols[i] / 6})];
      segmentTarget[i / 6] = inc.offset + 6 * within;
    }
  }
  // Symbolic block factorisation: the lower structure of each column is its neighbours after
  // it plus the structures of its children in the elimination tree.
  std::vector<std::vector<int>> structure(nBlocks), children(nBlocks);
  for (int b = 0; b < nb; ++b)
    for (int i : incidencesOfBody[b])
      for (int j : incidencesOfBody[b]) {
        const int bi = incidences[i].block, bj = incidences[j].block;
        if (bi > bj) structure[bj].push_back(bi);
      }
  for (int j = 0; j < nBlocks; ++j) {
    std::vector<int>& s = structure[j];
    for (int c : children[j])
      for (int i : structure[c])
        if (i > j) s.push_back(i);
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    if (!s.empty()) children[s.front()].push_back(j);
  }
  int storage = 0;
  offStart.assign(1, 0);
  for (int j = 0; j < nBlocks; ++j) {
    diagOffset.push_back(storage);
    storage += size(j) * size(j);
    for (int i : structure[j]) {
      offRow.push_back(i);
      offOffset.push_back(storage);
      storage += size(i) * size(j);
    }
    offStart.push_back(static_cast<int>(offRow.size()));
  }
  factorValues.assign(storage, 0.0);
  // Where block (i, j), i >= j, lives in the factor storage.
  auto blockAt = [&](int i, int j) {
    if (i == j) return diagOffset[j];
    const auto first = offRow.begin() + offStart[j], last = offRow.begin() + offStart[j + 1];
    return offOffset[static_cast<size_t>(std::lower_bound(first, last, i) - offRow.begin())];
  };
  std::vector<bool> reached(storage, false);
  for (int b = 0; b < nb; ++b)
    for (int p : incidencesOfBody[b])
      for (int q : incidencesOfBody[b])
        if (incidences[p].block >= incidences[q].block) {
          const int target = blockAt(incidences[p].block, incidences[q].block);
          contributions.push_back({p, q, target, !reached[target]});
          reached[target] = true;
        }
  for (int j = 0; j < nBlocks; ++j) {
    if (!reached[diagOffset[j]]) fillBlocks.emplace_back(diagOffset[j], size(j) * size(j));
    for (int s = offStart[j]; s < offStart[j + 1]; ++s)
      if (!reached[offOffset[s]]) fillBlocks.emplace_back(offOffset[s], size(offRow[s]) * size(j));
  }
  updateStart.assign(1, 0);
  for (int j = 0; j < nBlocks; ++j) {
    for (int a = offStart[j]; a < offStart[j + 1]; ++a)
      for (int c = offStart[j]; c <= a; ++c)
        updates.push_back({offOffset[a], size(offRow[a]), offOffset[c], size(offRow[c]),
                           blockAt(offRow[a], offRow[c])});
    updateStart.push_back(static_cast<int>(updates.size()));
  }
  sDiagonal.assign(m, 0.0);
  inverseDiagonal.assign(m, 0.0);
  translationalPart.assign(m, 0.0);
  rotationalPart.assign(m, 0.0);
  values.assign(cols.size(), 0.0);
  gamma.assign(m, 0.0);
  phi.assign(m, 0.0);
  nu.assign(m, 0.0);
  x.assign(m, 0.0);
}

bool IndexOneDynamics::Engine::factoredAt(const Eigen::VectorXd& y) const {
  if (!factored) return false;
  const StateLayout& l = system.layout();
  for (int b = 0; b < nb; ++b)
    for (int i = 0; i < StateLayout::kV; ++i)
      if (factorPositions[static_cast<size_t>(StateLayout::kV * b + i)] != y(l.body(b) + i))
        return false;
  return true;
}

bool IndexOneDynamics::Engine::factor(const double* entries, const Eigen::VectorXd& y) {
  factored = false;
  droppedRows = 0;
  factorPositions.resize(static_cast<size_t>(StateLayout::kV * nb));
  for (int b = 0; b < nb; ++b)
    for (int i = 0; i < StateLayout::kV; ++i)
      factorPositions[static_cast<size_t>(StateLayout::kV * b + i)] =
          y(system.layout().body(b) + i);
  for (size_t s = 0; s < segmentTarget.size(); ++s)
    std::copy_n(entries + 6 * s, 6, cDense.data() + segmentTarget[s]);
  auto size = [&](int j) { return blockStart[j + 1] - blockStart[j]; };
  // W = C M^-1 per incidence: translations scaled by 1/m, rotations times J^-1 (symmetric).
  std::fill(translationalPart.begin(), translationalPart.end(), 0.0);
  std::fill(rotationalPart.begin(), rotationalPart.end(), 0.0);
  for (const Incidence& inc : incidences) {
    const int n = inc.rows;
    const double im = inverseMass[inc.body];
    const Eigen::Matrix3d& ji = inverseInertia[inc.body];
    const double* c = cDense.data() + inc.offset;
    double* wp = w.data() + inc.offset;
    for (int r = 0; r < n; ++r) {
      const double* cr = c + 6 * r;
      double* wr = wp + 6 * r;
      for (int d = 0; d < 3; ++d) wr[d] = cr[d] * im;
      for (int d = 0; d < 3; ++d)
        wr[3 + d] = cr[3] * ji(0, d) + cr[4] * ji(1, d) + cr[5] * ji(2, d);
      const size_t row = static_cast<size_t>(blockStart[inc.block] + r);
      translationalPart[row] += cr[0] * wr[0] + cr[1] * wr[1] + cr[2] * wr[2];
      rotationalPart[row] += cr[3] * wr[3] + cr[4] * wr[4] + cr[5] * wr[5];
    }
  }
  for (const auto& [offset, count] : fillBlocks)
    std::fill_n(factorValues.begin() + offset, count, 0.0);
  for (const Contribution& s : contributions) {
    const Incidence& p = incidences[s.p];
    const Incidence& q = incidences[s.q];
    withSize(kernelSize(p.rows), [&](auto n) {
      multiplyTransposed<decltype(n)::value>(p.rows, q.rows, w.data() + p.offset,
                                             cDense.data() + q.offset,
                                             factorValues.data() + s.target, s.assign);
    });
  }
  const int nBlocks = static_cast<int>(blockStart.size()) - 1;
  for (int j = 0; j < nBlocks; ++j) {
    const int n = size(j);
    for (int c = 0; c < n; ++c)
      sDiagonal[blockStart[j] + c] = factorValues[diagOffset[j] + c + n * c];
  }
  for (int j = 0; j < nBlocks; ++j) {
    const int n = size(j);
    double* l = factorValues.data() + diagOffset[j];
    double* inverse = inverseDiagonal.data() + blockStart[j];
    // Dense Cholesky of the diagonal block (lower triangle; the updates kept it current).
    for (int c = 0; c < n; ++c) {
      double d = l[c + n * c];
      for (int k = 0; k < c; ++k) d -= l[c + n * k] * l[c + n * k];
      // The pivot is what is left of S_cc once the earlier rows are eliminated: a tiny
      // remainder means row c of C is (nearly) a combination of earlier rows.
      if (!std::isfinite(d)) return false;
      const size_t row = static_cast<size_t>(blockStart[j] + c);
      const double t = translationalPart[row], q = rotationalPart[row];
      // (A part within round-off of zero, t <= kRoundOffPivot q, is no part.) Only a
      // translational part far below the rotational one is the reference: see kPartRatio.
      const double part = t > kRoundOffPivot * q && q > kPartRatio * t ? t : sDiagonal[row];
      const bool dependent =
          !(d > kRoundOffPivot * sDiagonal[row]) || !(d > kPivotTolerance * part);
      // A dependent row: inverse 0 zeroes its column of L below the pivot (here and in
      // solveRight), so the row takes no part in the elimination and its multiplier solves to 0.
      const double root = dependent ? 1.0 : std::sqrt(d);
      l[c + n * c] = root;
      inverse[c] = dependent ? 0.0 : 1.0 / root;
      droppedRows += dependent ? 1 : 0;
      for (int r = c + 1; r < n; ++r) {
        double v = l[r + n * c];
        for (int k = 0; k < c; ++k) v -= l[r + n * k] * l[c + n * k];
        l[r + n * c] = v * inverse[c];
      }
    }
    for (int s = offStart[j]; s < offStart[j + 1]; ++s) {
      const int ni = size(offRow[s]);
      withSize(kernelSize(ni), [&](auto nc) {
        solveRight<decltype(nc)::value>(ni, n, l, inverse, factorValues.data() + offOffset[s]);
      });
    }
    for (int u = updateStart[j]; u < updateStart[j + 1]; ++u) {
      const Update& up = updates[u];
      withSize(kernelSize(up.sourceRows), [&](auto nc) {
        subtractProduct<decltype(nc)::value>(
            up.sourceRows, up.otherRows, n, factorValues.data() + up.source,
            factorValues.data() + up.other, factorValues.data() + up.target);
      });
    }
  }
  factored = true;
  return true;
}

void IndexOneDynamics::Engine::solve(double* v) const {
  auto size = [&](int j) { return blockStart[j + 1] - blockStart[j]; };
  const int nBlocks = static_cast<int>(blockStart.size()) - 1;
  // L y = v, column by column.
  for (int j = 0; j < nBlocks; ++j) {
    const int n = size(j);
    const double* l = factorValues.data() + diagOffset[j];
    double* vj = v + blockStart[j];
    const double* inverse = inverseDiagonal.data() + blockStart[j];
    for (int c = 0; c < n; ++c) {
      double s = vj[c];
      for (int k = 0; k < c; ++k) s -= l[c + n * k] * vj[k];
      vj[c] = s * inverse[c];
    }
    for (int s = offStart[j]; s < offStart[j + 1]; ++s) {
      const int ni = size(offRow[s]);
      const double* bl = factorValues.data() + offOffset[s];
      double* vi = v + blockStart[offRow[s]];
      withSize(kernelSize(ni), [&](auto nc) {
        constexpr int N = decltype(nc)::value;
        const int rowsOfBlock = N > 0 ? N : ni;
        for (int c = 0; c < n; ++c)
          for (int a = 0; a < rowsOfBlock; ++a) vi[a] -= bl[a + rowsOfBlock * c] * vj[c];
      });
    }
  }
  // L^T x = y, backwards.
  for (int j = nBlocks - 1; j >= 0; --j) {
    const int n = size(j);
    const double* l = factorValues.data() + diagOffset[j];
    double* vj = v + blockStart[j];
    for (int s = offStart[j]; s < offStart[j + 1]; ++s) {
      const int ni = size(offRow[s]);
      const double* bl = factorValues.data() + offOffset[s];
      const double* vi = v + blockStart[offRow[s]];
      withSize(kernelSize(ni), [&](auto nc) {
        constexpr int N = decltype(nc)::value;
        const int rowsOfBlock = N > 0 ? N : ni;
        for (int c = 0; c < n; ++c) {
          double sum = 0.0;
          for (int a = 0; a < rowsOfBlock; ++a) sum += bl[a + rowsOfBlock * c] * vi[a];
          vj[c] -= sum;
        }
      });
    }
    const double* inverse = inverseDiagonal.data() + blockStart[j];
    for (int c = n - 1; c >= 0; --c) {
      double s = vj[c];
      for (int k = c + 1; k < n; ++k) s -= l[k + n * c] * vj[k];
      vj[c] = s * inverse[c];
    }
  }
}

void IndexOneDynamics::Engine::correction(const double* v, Eigen::VectorXd& out) const {
  out.setZero(6 * nb);
  // -M^-1 C^T v = -W^T v, incidence by incidence.
  for (const Incidence& inc : incidences) {
    const int n = inc.rows;
    const double* vj = v + blockStart[inc.block];
    const double* wp = w.data() + inc.offset;
    double* o = out.data() + 6 * inc.body;
    for (int r = 0; r < n; ++r)
      for (int d = 0; d < 6; ++d) o[d] -= wp[6 * r + d] * vj[r];
  }
}

double IndexOneDynamics::Engine::velocityResidual(const double* entries, const double* rates,
                                                  const Eigen::VectorXd& y, double* residual,
                                                  double* scale) const {
  const std::vector<int>& start = rows.start();
  const double* u = y.data();
  double worst = 0.0, size = 0.0;
  for (int r = 0; r < m; ++r) {
    // Whole bodies: segment by segment, each body's six velocities read contiguously.
    double cu = 0.0, magnitude = std::abs(rates[r]);
    for (int i = start[r]; i < start[r + 1]; i += 6) {
      const double* c = entries + i;
      const double* ub = u + segmentVelocity[static_cast<size_t>(i / 6)];
      for (int d = 0; d < 6; ++d) {
        const double term = c[d] * ub[d];
        cu += term;
        // The size of the terms of C u: the round-off floor of the residual.
        if (scale) magnitude += std::abs(term);
      }
    }
    const double v = cu - rates[r];
    if (residual) residual[positionOf[r]] = v;
    worst = std::max(worst, std::abs(v));
    size = std::max(size, magnitude);
  }
  if (scale) *scale = size;
  return worst;
}

}  // namespace openmss::mechanics
