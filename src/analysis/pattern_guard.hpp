#pragma once
// When the run-time guard of the sparse Newton matrix (docs/theory.md §9a, "Run-time guard")
// checks a matrix: one directional derivative of the whole residual per check, about a quarter
// of the matrix's own cost on the 100-link chains. A pattern is checked at each of its first
// kEveryMatrix matrices and then at every kPeriod-th: a rule the pattern missed makes its
// entries nonzero at almost any state, so the first matrices find it, and an entry left out
// costs convergence speed, never the solution (the residual is exact). Patterns that change
// during a run (CONTACT's near pairs) are checked at every matrix (`always`).

namespace openmss::analysis {

class PatternGuard {
 public:
  static constexpr long kEveryMatrix = 8;
  static constexpr long kPeriod = 8;

  explicit PatternGuard(bool always = false) : always_(always) {}
  // Counts a matrix formed on the current pattern; true when it is to be checked.
  bool due() {
    ++formed_;
    const bool check = always_ || formed_ <= kEveryMatrix || formed_ % kPeriod == 0;
    checks_ += check ? 1 : 0;
    return check;
  }
  // A new pattern (first build, rebuild, repair): its first matrices are checked again.
  void patternChanged() { formed_ = 0; }
  void checkEveryMatrix(bool always) { always_ = always; }
  long checks() const { return checks_; }

 private:
  bool always_;
  long formed_ = 0;  // matrices formed on the current pattern
  long checks_ = 0;  // checks made, over all patterns
};

}  // namespace openmss::analysis
