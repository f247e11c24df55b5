#pragma once
// The structural sparsity pattern of the Newton matrix dG/dy + cj dG/dy' of a MultibodySystem,
// its column colouring, and the compressed forward-AD evaluation that fills it (docs/theory.md,
// "Sparse Newton matrix").
//
// The pattern is derived from the model's topology, not from values: each body's own rows read
// that body; each force element and each constraint equation couples the bodies of the markers
// it reads; user equations and function expressions couple whatever their measures read. A
// measure whose dependencies are not known here makes the rows that read it dense, so that the
// pattern can be too full but never too sparse. Columns of one colour share no row, so one
// residual pass with all of them seeded yields every one of their entries.

#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/SparseCore>

#include "common/dual.hpp"

namespace openmss::mechanics {

class MultibodySystem;
class LocalNewtonMatrix;

struct JacobianPattern {
  int size = 0;
  // Compressed sparse columns: the rows of column c are rowIndex[columnStart[c] ..
  // columnStart[c+1]), ascending.
  std::vector<int> columnStart;
  std::vector<int> rowIndex;
  // Columns grouped by colour: colour k holds colourColumns[colourStart[k] .. colourStart[k+1]).
  std::vector<int> colourStart;
  std::vector<int> colourColumns;
  // Rows made dense because a dependency could not be resolved structurally.
  int denseRows = 0;
  // Distinct for every pattern made by patternFromRows (copies share it): what plans made on
  // a pattern (local_newton_matrix.hpp) check before they reuse their value indices.
  std::uint64_t stamp = 0;
  // The CONTACT elements whose coupling the pattern holds, one flag per Model::contacts
  // element; empty: all of them (docs/theory.md §6c, "Near-pair pattern"). An element left out
  // must have exactly zero loads and partials wherever the matrix is evaluated on this pattern.
  std::vector<char> contacts;

  int colours() const { return static_cast<int>(colourStart.size()) - 1; }
  int nonZeros() const { return static_cast<int>(rowIndex.size()); }
  // A compressed column-major matrix with this pattern and zero values.
  Eigen::SparseMatrix<double> matrix() const;
};

// Builds the pattern (rows as sets of columns) from row lists and colours it.
JacobianPattern patternFromRows(int size, std::vector<std::vector<int>> rows);

// The structural pattern of the system's Newton matrix, coloured.
// With `contacts` (one flag per CONTACT element; empty: all), only the flagged CONTACT
// elements couple their bodies.
JacobianPattern newtonMatrixPattern(const MultibodySystem& system,
                                    const std::vector<char>& contacts = {});
// The part of it that the force elements and the user equations make (rows they write,
// columns those rows read; other rows empty), coloured: what the element-local Newton matrix
// still fills by compressed AD.
// `skip` (one flag per force element, ForceElements::elements(); empty: none): elements left
// out, whose entries the element-local Newton matrix forms element by element.
JacobianPattern forceAndUserPattern(const MultibodySystem& system,
                                    const std::vector<char>& contacts = {},
                                    const std::vector<char>& skip = {});

// Greedy distance-2 colouring of the columns in ascending order (deterministic): two columns
// that share a row get different colours.
void colourColumns(JacobianPattern& pattern);

// Replaces the given rows by dense rows (every column) and recolours: the repair when a
// directional-derivative check finds an entry outside the pattern.
void makeRowsDense(JacobianPattern& pattern, const std::vector<int>& rows);

// Work vectors of the compressed evaluation (sized once, reused at every Jacobian).
struct SparseJacobianWork {
  std::vector<Dual<double>> y, yp, g;
  std::vector<double> direction, product, magnitude;
  // The element-local assembly planned on the pattern last used (local_newton_matrix.hpp);
  // elementLocal = false forces the compressed colouring of the whole residual (tests, bench).
  std::shared_ptr<LocalNewtonMatrix> local;
  bool elementLocal = true;
  // forceElementsLocal = false puts every force element on the element-local matrix's coloured
  // passes (LocalNewtonMatrix's localForces; tests, bench).
  bool forceElementsLocal = true;
};

}  // namespace openmss::mechanics
