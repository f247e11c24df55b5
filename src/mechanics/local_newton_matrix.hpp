#pragma once
// The sparse Newton matrix dG/dy + cj dG/dy' of a MultibodySystem assembled element by element
// (docs/theory.md §9a) instead of by compressed forward AD over the whole residual:
//  * body blocks (kinematic, Euler-parameter, Newton-Euler left-hand sides, normalisation):
//    analytic, 60 entries per body;
//  * each constraint equation: its value row and its reaction lambda C^T in the force and
//    moment rows of the bodies it touches, differentiated with a local forward-AD pass over the
//    positions (r, e) of those bodies only (all 7 per body in one multi-direction dual for the
//    kinds with analytic gradients; one direction at a time for the others); the multiplier's
//    column is the gradient itself;
//  * force elements whose loads read only the state and their own data (SPRINGDAMPER; BUSHING,
//    FIELD, BEAM without USER: ForceElements::isStateLocal): one local forward-AD pass per
//    element over the 13 state entries (r, e, v, w) of each of its bodies
//    (local_newton_forces.cpp);
//  * the other force elements and user equations: compressed forward AD of their rows alone, on
//    their own coloured pattern (forceAndUserPattern, those elements only).
// Every entry lands in the values of the full pattern through indices found once, when the plan
// is made. A pattern this cannot serve (dense rows, after a repair or for a dependency the
// pattern does not resolve) makes usable() false: the caller then colours the whole residual.
//
// Planned on a pattern of size layout().size() + constraintEquations (si2_newton_pattern.hpp) it
// also fills the stabilised index-2 rows and columns (analysis/multibody_dae_si2.hpp): the
// velocity form C u of each equation and the multiplier eta's terms C_r^T eta and
// E(e) C_pi^T eta / 2 in the kinematic rows, from the same seeded gradients as C^T lambda.

#include <cstdint>
#include <vector>

#include <Eigen/Dense>

#include "common/vec3.hpp"
#include "mechanics/constraint_set.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "mechanics/local_dual.hpp"

namespace openmss::mechanics {

class MultibodySystem;

class LocalNewtonMatrix {
 public:
  // localForces false: every force element on the coloured passes (the path before
  // local_newton_forces.cpp; tests and bench/jacobian_bench compare the two).
  LocalNewtonMatrix(const MultibodySystem& system, const JacobianPattern& pattern,
                    bool localForces = true);

  // Directions per multi-direction pass: the positions (r, e) of one body. One pass per body
  // rather than one over two bodies: the frames of the other bodies are then constants, and a
  // Point equation's side needs only its own body's pass (docs/performance.md, "The
  // element-local Newton matrix, cheaper").
  static constexpr int kChunk = 7;

  bool usable() const { return usable_; }
  // Planned with the SI2 rows and columns (a pattern of size + constraintEquations).
  bool stabilised() const { return stabilised_; }
  std::uint64_t patternStamp() const { return patternStamp_; }
  // How many force elements are formed element by element (local_newton_forces.cpp).
  int stateLocalForceElements() const { return static_cast<int>(forcePlans_.size()); }
  // Whether their passes go to the thread pool (enough of them; local_newton_forces.cpp).
  bool forceElementsOnThePool() const { return parallelForces_; }
  // Overwrites values (the pattern's nonzeros, column-major) with the Newton matrix; work's dual
  // vectors serve the compressed passes of the force elements and user equations.
  void assemble(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj,
                double* values, SparseJacobianWork& work);

 private:
  static constexpr int kBodyEntries = 60;
  struct EquationPlan {
    int bodies[6];     // moving bodies the markers sit on, distinct, ascending
    int bodyCount = 0;
    int slot[6];       // per marker side: index into bodies, -1 for ground
    int index = 0;     // first of this equation's value indices in index_
    int stabilisedIndex = 0;  // first of its SI2 value indices in stabilisedIndex_
  };
  // Value index of (row, column) in the pattern, -1 when the pattern lacks it.
  static int find(const JacobianPattern& pattern, int row, int column);
  void planBodies(const JacobianPattern& pattern);
  void planEquations(const JacobianPattern& pattern);
  void planForceAndUser(const JacobianPattern& pattern);
  // The state-local force elements (local_newton_forces.cpp): their value slots, and the
  // elements the coloured passes leave out.
  void planForceElements(const JacobianPattern& pattern);
  void forceElementEntries(const Eigen::VectorXd& y, double* values);
  struct ForcePlan;
  // One element's pass: writes its terms (ForcePlan::terms) to out and which it wrote to
  // written (2 flags: I, J); reads nothing it or another
  // pass writes, so the passes may run on any threads (local_newton_forces.cpp).
  template <int N>
  void forceElementPass(const ForcePlan& plan, const Eigen::VectorXd& y, double* out,
                        char* written) const;
  void planStabilisation(const JacobianPattern& pattern, int equation, EquationPlan& plan);
  // The SI2 entries of one side's gradient `out` (body slot i) over the chunk's directions.
  // `first`: the first pass that evaluates this side (it adds the values, not derivatives).
  template <class S>
  void stabilisationChunk(const EquationPlan& plan, int slot, const S* out, int base, int last,
                          bool first, double* values) const;
  void bodyBlocks(const Eigen::VectorXd& y, double cj, double* values) const;
  // The force-element and user-equation entries, one compressed AD pass per colour of
  // forceAndUser_ (local_newton_colours.cpp); in parallel over colours when parallelColours_.
  bool coloursMayRunInParallel() const;
  void forceAndUserColours(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                           double cj, double* values, SparseJacobianWork& work);
  void kinematics(const Eigen::VectorXd& y);
  template <class S>
  void buildSeeded(const ConstraintEquation& eq, const EquationPlan& plan, int base,
                   V3<S>* origin, M3<S>* axes, Frame<S>* frames) const;
  template <class S>
  void equationChunk(const ConstraintEquation& eq, const EquationPlan& plan, int base,
                     double lambda, double* values);
  // The chunk's entries of one equation from its seeded poses and frames; arms (with armMask,
  // bit per side set once computed) caches the Point sides' A^T (p - o), nullptr: none.
  template <class S>
  void equationRows(const ConstraintEquation& eq, const EquationPlan& plan, int base,
                    const V3<S>* origin, const M3<S>* axes, const Frame<S>* frames,
                    V3<S>* arms, int* armMask, double lambda, double* values);

  const MultibodySystem& system_;
  std::uint64_t patternStamp_ = 0;
  int nonZeros_ = 0;
  bool usable_ = true;
  bool stabilised_ = false;
  // SI2 only. Per equation: (eta, eta); the velocity-form row over the 7 n position and the 6 n
  // velocity columns; the 7 kinematic rows (r, e) of each body over the 7 n position columns
  // and eta (7 n + 1 each). The state and eta of the equation being assembled:
  std::vector<int> stabilisedIndex_;
  const double* state_ = nullptr;
  double eta_ = 0.0;
  std::vector<int> bodyIndex_;      // kBodyEntries per body
  std::vector<EquationPlan> equations_;
  // Per equation: (lambda, lambda); the value row over the 7 n position columns; the 6 n force
  // and moment rows over those columns and lambda (7 n + 1 each), n = bodyCount.
  std::vector<int> index_;
  // Per state-local force element: its bodies and where its entries go. Each element's pass
  // writes its terms into its own range of forceTerms_ (on the thread pool when
  // parallelForces_); one serial loop then sums them in forceSum_ (one slot per value entry they
  // write, forceSlots_: its index in values) element by element in the residual's order, exactly
  // as one row of the colour pass summed them, and adds them to values once.
  struct ForcePlan {
    int element = 0;           // index in ForceElements::elements()
    int bodies[2] = {-1, -1};  // moving bodies of the I and J markers, distinct
    int bodyCount = 0;
    int slotI = -1, slotJ = -1;  // index into bodies; -1 for ground
    int index = 0;  // first of its 6 n x 13 n slots in forceSlot_, row-major (body rows v, w)
    // First of its terms in forceTerms_: per side on a moving body (I, then J), 3 x 3 rows
    // (force, force's moment, torque) of 13 n derivatives each.
    size_t terms = 0;
  };
  std::vector<ForcePlan> forcePlans_;
  std::vector<int> forceSlot_;   // per element entry: its slot in forceSum_
  std::vector<int> forceSlots_;  // per slot: its index in values
  std::vector<double> forceSum_;
  std::vector<double> forceTerms_;
  std::vector<char> forceTermsWritten_;  // per element and side (I, J): which terms it wrote
  bool parallelForces_ = false;  // enough elements for the passes to go to the thread pool
  std::vector<char> forceSkip_;  // per force element: 1 when planned here (not coloured)
  JacobianPattern forceAndUser_;
  std::vector<int> forceAndUserIndex_;  // per nonzero of forceAndUser_: its index in values
  std::vector<int> forceAndUserRows_;   // rows that pattern writes
  // True when every force element is one whose evaluation reads nothing but its own constant
  // data and the state (SPRINGDAMPER, BUSHING/FIELD/BEAM), there are no user equations, and
  // the elements are many enough to pay for handing out work; then the colours run on the
  // thread pool (common/parallel_for.hpp), block b > 0 on the duals of blockDuals_[b - 1].
  bool parallelColours_ = false;
  struct BlockDuals {
    std::vector<Dual<double>> y, yp, g;
  };
  std::vector<BlockDuals> blockDuals_;
  // The seeded poses and marker frames of the last multi-direction pass over each body slot:
  // the equations of one joint read the same markers, so they are built once per joint and
  // pass, not once per equation.
  struct SeededFrames {
    int markers[ConstraintEquation::kMaxMarkers];
    int markerCount = -1;  // -1: nothing cached
    int base = 0;
    Frame<DualVec<kChunk>> frames[ConstraintEquation::kMaxMarkers];
    V3<DualVec<kChunk>> origin[6];
    M3<DualVec<kChunk>> axes[6];
    V3<DualVec<kChunk>> arms[ConstraintEquation::kMaxMarkers];  // valid where armMask has the bit
    int armMask = 0;
  };
  SeededFrames seeded_[6];
  // Per body at the current state: origin, axes and d(axes)/d(e_k).
  std::vector<V3<double>> origin_;
  std::vector<M3<double>> axes_;
  std::vector<M3<double>> axesDerivative_;  // 4 per body
};

}  // namespace openmss::mechanics
