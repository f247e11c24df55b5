#pragma once
// Adapts the mechanics' equations of motion to the integrators' DaeProblem interface.

#include <vector>

#include "analysis/pattern_guard.hpp"
#include "mechanics/contact/contact_broad_phase.hpp"
#include "mechanics/coupled_accelerations.hpp"
#include "mechanics/multibody_system.hpp"
#include "solvers/dae_problem.hpp"

namespace openmss::analysis {

class MultibodyDae : public solvers::DaeProblem {
 public:
  // nearContactPattern: the sparse pattern holds only the CONTACT elements near at the state
  // where the matrix is evaluated, rebuilt when that set changes (docs/theory.md §6c,
  // "Near-pair pattern"); false: every CONTACT couples its bodies, one fixed pattern.
  explicit MultibodyDae(const mechanics::MultibodySystem& system, bool nearContactPattern = true)
      : system_(system),
        nearContacts_(nearContactPattern && !system.model().contacts.empty()),
        affineInRates_(!mechanics::readsAccelerationsOrReactions(system.model())),
        guard_(!system.model().contacts.empty()) {
    if (nearContacts_) broadPhase_ = {system.model(), system.layout()};
  }

  int size() const override { return system_.layout().size(); }
  void residual(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                Eigen::VectorXd& g) override {
    g.resize(size());
    system_.residual(t, y.data(), yp.data(), g.data());
  }
  void newtonMatrix(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj,
                    Eigen::MatrixXd& jac) override {
    system_.newtonMatrix(t, y, yp, cj, jac);
  }
  bool differential(int i) const override { return system_.layout().differential(i); }
  bool errorControlled(int i) const override { return system_.layout().displacement(i); }
  // Constraint rows and multipliers: exponent 2 (index 3); the Euler-parameter normalisation
  // and its multiplier mu: exponent 1 (index 2).
  int rowScaleExponent(int i) const override { return scaleExponent(i); }
  int unknownScaleExponent(int i) const override { return scaleExponent(i); }
  // Newmark-family roles: r, e positions; v, w velocities; mu, user algebraic states and
  // multipliers algebraic; DIFF/LSE/TFSISO states first order.
  Role role(int i) const override {
    const auto& l = system_.layout();
    if (i < l.userStates()) {
      const int o = i % mechanics::StateLayout::kPerBody;
      return o == mechanics::StateLayout::kMu ? Role::Algebraic
             : o < mechanics::StateLayout::kV ? Role::Position
                                              : Role::Velocity;
    }
    return l.isUserDifferential(i) ? Role::FirstOrder : Role::Algebraic;
  }
  std::string equationName(int row) const override;
  std::string variableName(int i) const override;
  // The body rows are m v' - m g and J w' + w x J w (constant m and body-frame J); y' enters
  // other force-balance terms only through functions that read accelerations (ACCX.., WDTX..,
  // directly, through a read-back or a user routine's SYSFNC), which a model without such
  // reads cannot have (mechanics/coupled_accelerations.hpp).
  bool forceRowsAffineInRates() const override { return affineInRates_; }
  void addRateTerm(const Eigen::VectorXd& d, Eigen::VectorXd& out) const override;

  // The sparse Newton matrix: structural pattern and compressed forward AD
  // (mechanics/jacobian_pattern.hpp). Evaluations are checked against one exact directional
  // derivative (every one with CONTACT, otherwise on PatternGuard's schedule); rows where an
  // entry falls outside the pattern are made dense (and counted in patternRepairs()), so a
  // pattern rule that misses a dependency costs speed, not convergence.
  bool sparse() const override { return true; }
  // A CONTACT's entries are exact zeros while its solids are apart and turn up at each onset.
  bool zerosPersist() const override { return system_.model().contacts.empty(); }
  const Eigen::SparseMatrix<double>* pattern() override;
  void newtonMatrixSparse(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                          double cj, Eigen::SparseMatrix<double>& jac) override;
  const mechanics::JacobianPattern& jacobianPattern() {
    pattern();
    return pattern_;
  }
  int patternRepairs() const { return repairs_; }
  // Matrices checked by the guard, and a switch to check every one (tests).
  long patternChecks() const { return guard_.checks(); }
  void checkEveryMatrix(bool always) { guard_.checkEveryMatrix(always); }
  // Near-pair patterns built (the first one included); 0 without the near-pair pattern.
  int patternRebuilds() const { return rebuilds_; }

  // Radius factors of the near-pair pattern's margin (docs/theory.md §6c): a rebuild takes the
  // elements whose bounding spheres overlap with radii times kEnter; the pattern is kept while
  // it holds every element near at factor 1 and none is apart at factor kLeave.
  static constexpr double kEnter = 1.1, kLeave = 1.2;

 private:
  int scaleExponent(int i) const {
    const auto& l = system_.layout();
    if (i >= l.lambda(0)) return 2;
    if (i >= l.userStates()) return 0;  // user equations (docs/theory.md §4a)
    return i % mechanics::StateLayout::kPerBody == mechanics::StateLayout::kMu ? 1 : 0;
  }
  // Whether the near-pair pattern must be rebuilt for the state y (and then rebuilds it).
  void updateNearPattern(const Eigen::VectorXd& y);

  const mechanics::MultibodySystem& system_;
  bool nearContacts_ = false;
  bool affineInRates_ = false;
  mechanics::contact::ContactBroadPhase broadPhase_;
  int rebuilds_ = 0;
  mechanics::JacobianPattern pattern_;
  Eigen::SparseMatrix<double> patternMatrix_;
  mechanics::SparseJacobianWork work_;
  bool havePattern_ = false;
  int repairs_ = 0;
  PatternGuard guard_;
};

}  // namespace openmss::analysis
