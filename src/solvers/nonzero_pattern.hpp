#pragma once
// The entries of a sparse Newton matrix that have been nonzero since its structure was last
// set: the pattern the factorisation is analysed on (docs/theory.md §9a, "Exact zeros").
// A structural pattern holds every entry that can be nonzero; on a given model many are zero
// for the whole run (every out-of-plane entry of a planar mechanism: 73 % of the 100-link
// planar chain's Newton matrix, 46 % of the spatial one's). Factoring them costs fill: KLU's
// L + U falls from 51,066 to 9,271 entries on the planar chain once they are dropped. The
// selected pattern only grows, so an entry that became nonzero once stays (as a zero when it
// is zero again) and the analysis is redone only when a new entry turns up.

#include <Eigen/SparseCore>
#include <vector>

namespace openmss::solvers {

class NonzeroPattern {
 public:
  // The entries of `full` (compressed) that have been nonzero since its structure last
  // changed, with full's current values. `grew`, if given, tells whether the selection
  // changed (and so needs a new analysis).
  const Eigen::SparseMatrix<double>& select(const Eigen::SparseMatrix<double>& full,
                                            bool* grew = nullptr);
  // After this many growths on one structure the selection takes the whole structure: entries
  // that keep turning up (a force that switches on and off) would otherwise cost an analysis
  // and a full factorisation each time.
  static constexpr int kMaxGrowths = 8;

 private:
  std::vector<int> outer_, inner_;  // full's structure when the selection was started
  std::vector<char> kept_;          // per entry of full: in the selection
  int growths_ = 0;                 // since the structure was set
  std::vector<int> source_;         // per entry of the selection: its index in full
  Eigen::SparseMatrix<double> selected_;
};

}  // namespace openmss::solvers
