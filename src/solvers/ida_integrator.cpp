#include "solvers/ida_integrator.hpp"

#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>
#include <sunnonlinsol/sunnonlinsol_newton.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <string>
#include <vector>

#include "solvers/hermite_weights.hpp"
#include "solvers/klu_linear_solver.hpp"

namespace openmss::solvers {

// Absolute tolerance given to unknowns outside error control (velocities and multipliers of an
// index-3 system): so large that their weight in IDA's norms vanishes. DASSL's users exclude
// the index-2 and index-3 unknowns from the error test in the same way (Brenan, Campbell and
// Petzold, ch. 5); IDASetSuppressAlg only covers the algebraic ones.
constexpr double kUncontrolledTolerance = 1e20;
// Singular configurations (docs/integrators.md, "DSTIFF and ABAM", Newton convergence): IDA's
// Newton convergence test rejects every iteration whose average rate exceeds 0.9. Near a kinematic
// singularity (the flat row of four-bars of IFToMM A02) the Newton matrix is nearly singular
// along the mechanism's extra degrees of freedom and the iteration, having driven the
// residual to round-off, keeps making changes of one size: the residual's round-off mapped
// through the nearly singular matrix. IDA then cuts the step to its floor and stops. As in
// BdfIntegrator (kResidualNoise, kRawResidualNoise), a stalled iteration whose balanced
// residual, or whose unscaled residual, has fallen below this share of its value at the
// predictor has converged as far as the linear solves allow.
constexpr double kResidualNoise = 1e-6;
constexpr double kRawResidualNoise = 1e-6;
// IDA's Newton iteration stops when its estimated remainder, rate / (1 - rate) times the last
// change, is below this share of the tolerance (IDASetNonlinConvCoef; IDA's default is
// DASSL's 0.33). BdfIntegrator asks 1e-4 of the step's local error (kCorrectorShare) for the
// same reason: a corrector stopped short leaves a remainder that the next steps' predictors
// extrapolate. On A02 (N = 4, ERROR = 1e-8) the remainder along the flat passage's extra
// degrees of freedom inflated the error estimates of the couplers' velocities, which cut the steps
// until one landed on the flat configuration itself, where the noise of the nearly singular
// solves fails the error test at any step (stopped at t = 0.717 s; with 1e-4 and the round-off
// rule above it reaches 10 s within 1.6e-6 m; 1e-2 and 1e-3 still stopped there, 1e-4 without
// the round-off rule at t = 0.717 s; docs/integrators.md, "DSTIFF and ABAM").
constexpr double kNewtonConvergence = 1e-4;
// Two more rules of BdfIntegrator's corrector for a stalled iteration (docs/integrators.md,
// "DSTIFF and ABAM", the flat passages of A02): it has converged when its weighted change is
// below kStalledChange of the tolerance, or when every differential unknown's change is within
// kRoundOffUlps ulps of the unknown (a velocity: of the largest position, times c_j, as the
// velocities are recovered from the positions through c_j).
constexpr double kStalledChange = 1e-1;
// A solve accepted by a stall rule whose last change is above this share of the tolerance
// moved along the near-null direction (BdfIntegrator's and HhtIntegrator's threshold).
constexpr double kStalledMove = 1e-3;
constexpr double kRoundOffUlps = 1000.0;
constexpr double kEps = std::numeric_limits<double>::epsilon();

struct IdaIntegrator::Engine {
  DaeProblem* problem = nullptr;
  SUNContext context = nullptr;
  void* ida = nullptr;
  N_Vector yy = nullptr, yp = nullptr, id = nullptr, atol = nullptr, work = nullptr;
  N_Vector weights = nullptr, localErrors = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver linear = nullptr;
  // IDA's Newton solver, ours to free, and IDA's own convergence test on it, which
  // convergenceTest() consults first (the test and its data, IDA's memory, as IDA installed
  // them on the solver).
  SUNNonlinearSolver newton = nullptr;
  SUNNonlinSolConvTestFn idaTest = nullptr;
  void* idaTestData = nullptr;
  // Largest balanced and unscaled residual at the predictor of the current Newton solve.
  double firstResidual = 0.0, firstRaw = 0.0;
  double previousChange = 0.0;  // weighted norm of the last change of the current solve
  // Newton matrix at the last Jacobian call, and its balanced factorisation.
  Eigen::MatrixXd jac;
  double cj = 1.0;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  // The sparse path (a sparse problem of BdfIntegrator::kSparseThreshold unknowns or more):
  // the problem's sparse Newton matrix, balanced in place and factored by KLU. IDA is then
  // given a 1-entry sparse SUNMatrix it only ever zeroes: the matrix lives here.
  bool sparse = false;
  Eigen::SparseMatrix<double> sparseJac;
  KluLinearSolver klu;
  bool kluFactored = false;
  Eigen::VectorXd rowScale, colScale, yWork, ypWork, gWork, rhs;
  long jacobianEvaluations = 0;
  std::string lastMessage;
  // Error weights (IDAWFtolerances): rtol = ERROR and atol per unknown; the roles of the
  // unknowns for the round-off floors; the weights of errorWeights() for this step, which
  // every Newton solve starts from (a solve accepted at noise widens them, convergenceTest);
  // the sum of |change| of the current solve's iterations after the first.
  double rtol = 0.0;
  Eigen::VectorXd absTol;
  std::vector<char> velocity, position;
  Eigen::VectorXd baseWeights, laterChanges;
  // The noise the predictor carries (docs/integrators.md, "DSTIFF and ABAM", noise rules): the
  // accepted solutions, most recent first (kHistory of them), their times and the noise of their
  // solves (laterChanges of a solve accepted by a stall rule, spread over its role; empty for a
  // solve that converged), and, for the solve under way, the predictor's share of that noise
  // (empty when none of the solutions it interpolates is noisy). solveAtNoise: the solve under
  // way was accepted by a stall rule.
  static constexpr size_t kHistory = 6;  // IDA's largest order, 5, plus one
  std::deque<double> acceptedTimes;
  std::deque<Eigen::VectorXd> acceptedNoise;
  Eigen::VectorXd predictorNoise;
  bool solveAtNoise = false;
  // ... with a last change above kStalledMove of the tolerance: a move along the Newton
  // matrix's near-null direction, not round-off (IdaIntegrator::step).
  bool stalledMove = false;

  ~Engine() {
    if (ida) IDAFree(&ida);
    if (newton) SUNNonlinSolFree(newton);
    if (linear) SUNLinSolFree(linear);
    if (matrix) SUNMatDestroy(matrix);
    for (N_Vector v : {yy, yp, id, atol, work, weights, localErrors})
      if (v) N_VDestroy(v);
    if (context) SUNContext_Free(&context);
  }

  static Eigen::Map<Eigen::VectorXd> view(N_Vector v) {
    return {N_VGetArrayPointer(v), static_cast<Eigen::Index>(N_VGetLength(v))};
  }

  static int residual(realtype t, N_Vector y, N_Vector yp, N_Vector r, void* user) {
    auto* e = static_cast<Engine*>(user);
    e->yWork = view(y);
    e->ypWork = view(yp);
    e->problem->residual(t, e->yWork, e->ypWork, e->gWork);
    if (!e->gWork.allFinite()) return 1;  // recoverable: IDA retries with a smaller step
    view(r) = e->gWork;
    return 0;
  }

  static int jacobian(realtype t, realtype cj, N_Vector y, N_Vector yp, N_Vector, SUNMatrix,
                      void* user, N_Vector, N_Vector, N_Vector) {
    auto* e = static_cast<Engine*>(user);
    e->yWork = view(y);
    e->ypWork = view(yp);
    e->cj = cj;
    ++e->jacobianEvaluations;
    if (e->sparse) {
      e->problem->newtonMatrixSparse(t, e->yWork, e->ypWork, cj, e->sparseJac);
      const Eigen::Map<const Eigen::VectorXd> values(e->sparseJac.valuePtr(),
                                                     e->sparseJac.nonZeros());
      return values.allFinite() ? 0 : 1;
    }
    e->problem->newtonMatrix(t, e->yWork, e->ypWork, cj, e->jac);
    return e->jac.allFinite() ? 0 : 1;
  }

  // The linear solver: IDA's SUNMatrix is never filled; the Newton matrix from jacobian()
  // is factored as R J C with R = diag(cj^rowScaleExponent), C = diag(cj^unknownScaleExponent)
  // (DaeProblem), so that the constraint rows and multiplier columns of an index-3 system keep
  // their pivots when cj = O(1/h) is large. Solutions are mapped back: x = C (R J C)^-1 R b.
  static Engine* of(SUNLinearSolver s) { return static_cast<Engine*>(s->content); }
  static SUNLinearSolver_Type type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
  static SUNLinearSolver_ID identity(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
  static int initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }
  static int setup(SUNLinearSolver s, SUNMatrix) {
    Engine* e = of(s);
    const Eigen::Index n = e->sparse ? e->sparseJac.rows() : e->jac.rows();
    e->rowScale.resize(n);
    e->colScale.resize(n);
    for (int i = 0; i < n; ++i) {
      e->rowScale(i) = std::pow(e->cj, e->problem->rowScaleExponent(i));
      e->colScale(i) = std::pow(e->cj, e->problem->unknownScaleExponent(i));
    }
    if (e->sparse) {
      // The matrix is formed anew at every setup (IDA calls the Jacobian first), so it is
      // scaled in place.
      for (int c = 0; c < e->sparseJac.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(e->sparseJac, c); it; ++it)
          it.valueRef() *= e->rowScale(it.row()) * e->colScale(c);
      e->kluFactored = e->klu.factor(e->sparseJac);
      return e->kluFactored ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;
    }
    e->lu.compute(e->rowScale.asDiagonal() * e->jac * e->colScale.asDiagonal());
    const Eigen::VectorXd pivots = e->lu.matrixLU().diagonal().cwiseAbs();
    if (n > 0 && !(pivots.minCoeff() > 1e-14 * pivots.maxCoeff())) return SUNLS_LUFACT_FAIL;
    return SUNLS_SUCCESS;
  }
  static int solve(SUNLinearSolver s, SUNMatrix, N_Vector x, N_Vector b, realtype) {
    Engine* e = of(s);
    e->rhs = e->rowScale.cwiseProduct(view(b));
    auto out = view(x);
    if (e->sparse) {
      if (!e->kluFactored) return SUNLS_PACKAGE_FAIL_REC;
      e->klu.solve(e->rhs);
      out = e->colScale.cwiseProduct(e->rhs);
    } else {
      out = e->colScale.cwiseProduct(e->lu.solve(e->rhs));
    }
    return out.allFinite() ? SUNLS_SUCCESS : SUNLS_PACKAGE_FAIL_REC;
  }
  static sunindextype lastFlag(SUNLinearSolver) { return 0; }
  static int release(SUNLinearSolver s) {
    s->content = nullptr;  // the Engine owns itself
    SUNLinSolFreeEmpty(s);
    return SUNLS_SUCCESS;
  }

  // IDA's weighted norm, replaced by the largest weighted component (GSTIFF's norm, §9 of
  // docs/theory.md). The root-mean-square IDA uses by default divides by the number of
  // unknowns, so in a mechanism where most coordinates are at rest (the z, e1, e2 of a planar
  // pendulum, every multiplier) one moving coordinate's error is diluted by sqrt(n / moving)
  // and ERROR = 1e-3 lets the pendulum drift by 2.6e-3.
  static realtype largestWeighted(N_Vector x, N_Vector w) {
    const auto xs = view(x);
    const auto ws = view(w);
    double worst = 0.0;
    for (Eigen::Index i = 0; i < xs.size(); ++i) {
      const double v = std::abs(xs(i) * ws(i));
      if (!(v <= worst)) worst = v;  // NaN propagates: it must fail the test
    }
    return worst;
  }
  static realtype largestWeightedMasked(N_Vector x, N_Vector w, N_Vector mask) {
    const auto xs = view(x);
    const auto ws = view(w);
    const auto ms = view(mask);
    double worst = 0.0;
    for (Eigen::Index i = 0; i < xs.size(); ++i) {
      if (ms(i) <= 0.0) continue;
      const double v = std::abs(xs(i) * ws(i));
      if (!(v <= worst)) worst = v;
    }
    return worst;
  }

  // IDA's convergence test, then the round-off rule of kResidualNoise on the iterations it
  // does not accept: those it rejects for their average rate and those that stall (this
  // change no smaller than 0.9 of the last; IDA would go on to MAXIT and fail). gWork holds
  // the residual at the iterate the change was computed from (IDA evaluates it just before
  // the linear solve), rowScale the balance of the matrix in use. IDA's verdict is only ever
  // overturned towards success at round-off residual, so a run that never stalls there takes
  // exactly IDA's steps.
  static int convergenceTest(SUNNonlinearSolver nls, N_Vector ycor, N_Vector del, realtype tol,
                             N_Vector ewt, void* user) {
    auto* e = static_cast<Engine*>(user);
    const int verdict = e->idaTest(nls, ycor, del, tol, ewt, e->idaTestData);
    int m = 0;
    SUNNonlinSolGetCurIter(nls, &m);
    const double size = largestWeighted(del, ewt);
    const double raw = e->gWork.cwiseAbs().maxCoeff();
    const double balanced = e->rowScale.size() == e->gWork.size()
                                ? e->rowScale.cwiseProduct(e->gWork).cwiseAbs().maxCoeff()
                                : raw;
    const double previous = e->previousChange;
    e->previousChange = size;
    if (m == 0) {
      if (e->baseWeights.size() == view(ewt).size()) view(ewt) = e->baseWeights;
      e->laterChanges.setZero(view(del).size());
      e->firstResidual = balanced;
      e->firstRaw = raw;
      e->solveAtNoise = false;
      e->stalledMove = false;
      e->updatePredictorNoise();
      if (verdict == SUN_NLS_SUCCESS) e->widen(view(ewt), false);
      return verdict;
    }
    const bool stalled = verdict == SUN_NLS_CONV_RECVR || !(size < 0.9 * previous);
    e->laterChanges += view(del).cwiseAbs();
    if (verdict != SUN_NLS_SUCCESS && stalled && std::isfinite(size) &&
        (size <= kStalledChange || balanced <= kResidualNoise * e->firstResidual ||
         raw <= kRawResidualNoise * e->firstRaw || e->withinRoundOff(view(del)))) {
      // The iterate carries the noise of the changes made after the first iteration (the
      // iteration no longer contracts; the first change is the correction proper), which IDA's
      // error estimate, corrector minus predictor, would see: at A02's flat passages the
      // velocities of the extra degrees of freedom carry noise of eps cond c_j from the nearly
      // singular solves, growing as the step shrinks, and no step passed the error test. So
      // the error test of this solve (IDA's ewt, restored at the next solve's first
      // iteration) does not ask for less than the sum of those changes (laterChanges), taken
      // at the level of the largest of each role (spreadNoise), nor for less than the noise the
      // predictor carries (predictorNoise).
      e->solveAtNoise = true;
      e->stalledMove = size > kStalledMove;
      e->spreadNoise();
      e->widen(view(ewt), true);
      return SUN_NLS_SUCCESS;
    }
    if (verdict == SUN_NLS_SUCCESS) e->widen(view(ewt), false);
    return verdict;
  }

  // The noise of a solve accepted at noise, per unknown: the largest weighted sum of later
  // changes among the differential unknowns of its role (position, velocity, first-order), in
  // each unknown's own weight. The noise of a nearly singular solve lies along the matrix's
  // near-null directions, which mix all the extra degrees of freedom of A02's flat row: which
  // unknown shows it in this solve's last iterations is chance, and the next solve shows it in
  // another (measured: a coupler's WZ off by 300 tolerances from a history whose recorded
  // noise in that unknown was 1e-6 of the tolerance, docs/integrators.md).
  void spreadNoise() {
    double level[4] = {0.0, 0.0, 0.0, 0.0};  // per DaeProblem::Role
    for (Eigen::Index i = 0; i < laterChanges.size(); ++i) {
      const int r = static_cast<int>(problem->role(static_cast<int>(i)));
      if (problem->differential(static_cast<int>(i)))
        level[r] = std::max(level[r], laterChanges(i) * baseWeights(i));
    }
    for (Eigen::Index i = 0; i < laterChanges.size(); ++i)
      if (problem->differential(static_cast<int>(i)))
        laterChanges(i) =
            level[static_cast<int>(problem->role(static_cast<int>(i)))] / baseWeights(i);
  }

  // The error test of a converged solve does not ask for less than the noise it carries: its
  // own later changes (atNoise) and the predictor's share of the noise of the solutions it
  // interpolates (predictorNoise). A run that never stalls has neither: unchanged.
  void widen(Eigen::Map<Eigen::VectorXd> w, bool atNoise) const {
    const bool history = predictorNoise.size() == w.size();
    if (!atNoise && !history) return;
    for (Eigen::Index i = 0; i < w.size(); ++i) {
      if (!problem->differential(static_cast<int>(i))) continue;
      const double noise = (atNoise ? laterChanges(i) : 0.0) + (history ? predictorNoise(i) : 0.0);
      w(i) = 1.0 / (1.0 / w(i) + noise);
    }
  }

  // predictorNoise of the attempt IDA is solving (order k, step h): IDA's predictor is the
  // polynomial through the last k+1 accepted solutions at t_n + h, so the noise of solution j
  // enters it times |L_j(t_n + h)|, its Lagrange weight (up to 31 at order 5 with equal steps):
  // at A02's flat passages the noise of one accepted solution, extrapolated, failed the error
  // test of every later attempt whatever its step (docs/integrators.md, "DSTIFF and ABAM").
  void updatePredictorNoise() {
    predictorNoise.resize(0);
    int k = 1;
    realtype h = 0.0;
    IDAGetCurrentOrder(ida, &k);
    IDAGetCurrentStep(ida, &h);
    const int nodes = std::min(k + 1, static_cast<int>(acceptedTimes.size()));
    bool noisy = false;
    for (int j = 0; j < nodes; ++j) noisy = noisy || acceptedNoise[j].size() > 0;
    if (!noisy || h == 0.0) return;
    const double tNew = acceptedTimes[0] + h;
    for (int j = 0; j < nodes; ++j) {
      if (acceptedNoise[j].size() == 0) continue;
      double weight = 1.0;
      for (int l = 0; l < nodes; ++l)
        if (l != j) weight *= (tNew - acceptedTimes[l]) / (acceptedTimes[j] - acceptedTimes[l]);
      if (predictorNoise.size() == 0) predictorNoise.setZero(acceptedNoise[j].size());
      predictorNoise += std::abs(weight) * acceptedNoise[j];
    }
  }

  // After an accepted step (the last solve was its corrector): its time and noise join the
  // history.
  void recordAccepted(double t) {
    acceptedTimes.push_front(t);
    acceptedNoise.push_front(solveAtNoise ? laterChanges : Eigen::VectorXd());
    if (acceptedTimes.size() > kHistory) {
      acceptedTimes.pop_back();
      acceptedNoise.pop_back();
    }
  }

  // The round-off floor of each unknown's Newton change, as BdfIntegrator::withinRoundOff
  // (kRoundOffUlps), c_j taken as 1/h (IDA's c_j is alpha_s / h, alpha_s >= 1: the smaller).
  double largestPosition(const Eigen::Ref<const Eigen::VectorXd>& y) const {
    double largest = 0.0;
    for (Eigen::Index i = 0; i < y.size(); ++i)
      if (position[i]) largest = std::max(largest, std::abs(y(i)));
    return largest;
  }
  double currentCj() const {
    realtype h = 0.0;
    IDAGetCurrentStep(ida, &h);
    return h != 0.0 ? std::max(1.0, 1.0 / std::abs(h)) : 1.0;
  }
  double roundOff(Eigen::Index i, double yi, double positionSize, double cjNow) const {
    return velocity[i] ? kRoundOffUlps * kEps * (1.0 + std::max(std::abs(yi), positionSize)) * cjNow
                       : kRoundOffUlps * kEps * (1.0 + std::abs(yi));
  }
  // Every differential unknown's last change (del) at or below its round-off floor at the
  // iterate it was computed from (yWork, the residual's argument): nothing left to converge.
  bool withinRoundOff(const Eigen::Ref<const Eigen::VectorXd>& del) const {
    if (yWork.size() != del.size()) return false;
    const double positionSize = largestPosition(yWork), cjNow = currentCj();
    for (Eigen::Index i = 0; i < del.size(); ++i)
      if (problem->differential(static_cast<int>(i)) &&
          !(std::abs(del(i)) <= roundOff(i, yWork(i), positionSize, cjNow)))
        return false;
    return true;
  }

  // IDA's error weights 1 / (rtol |y_i| + atol_i), as IDASVtolerances would set them; kept in
  // baseWeights for convergenceTest. IDA calls this before every step.
  static int errorWeights(N_Vector y, N_Vector ewt, void* user) {
    auto* e = static_cast<Engine*>(user);
    const auto ys = view(y);
    auto w = view(ewt);
    for (Eigen::Index i = 0; i < ys.size(); ++i) {
      double tol = e->rtol * std::abs(ys(i)) + e->absTol(i);
      if (!(tol > 0.0)) return -1;
      w(i) = 1.0 / tol;
    }
    e->baseWeights = w;
    return 0;
  }

  static void errorHandler(int, const char*, const char*, char* message, void* user) {
    static_cast<Engine*>(user)->lastMessage = message;  // reported through failure()
  }
};

IdaIntegrator::IdaIntegrator(DaeProblem& problem, const MultistepSettings& settings)
    : problem_(problem), settings_(settings) {}

IdaIntegrator::~IdaIntegrator() = default;

void IdaIntegrator::start(double t0, const Eigen::VectorXd& y0, const Eigen::VectorXd& yp0) {
  const int n = problem_.size();
  engine_ = std::make_unique<Engine>();
  Engine& e = *engine_;
  e.problem = &problem_;
  SUNContext_Create(nullptr, &e.context);
  for (N_Vector* v : {&e.yy, &e.yp, &e.id, &e.atol, &e.work, &e.weights, &e.localErrors})
    *v = N_VNew_Serial(n, e.context);
  // Every vector IDA makes is cloned from these two and inherits the norm.
  for (N_Vector v : {e.yy, e.yp, e.id, e.atol, e.work, e.weights, e.localErrors}) {
    v->ops->nvwrmsnorm = &Engine::largestWeighted;
    v->ops->nvwrmsnormmask = &Engine::largestWeightedMasked;
  }
  Engine::view(e.yy) = y0;
  Engine::view(e.yp) = yp0;
  auto id = Engine::view(e.id);
  auto atol = Engine::view(e.atol);
  for (int i = 0; i < n; ++i) {
    id(i) = problem_.differential(i) ? 1.0 : 0.0;
    atol(i) = problem_.errorControlled(i) ? settings_.error : kUncontrolledTolerance;
  }
  e.ida = IDACreate(e.context);
  IDASetErrHandlerFn(e.ida, &Engine::errorHandler, &e);
  IDAInit(e.ida, &Engine::residual, t0, e.yy, e.yp);
  IDASetUserData(e.ida, &e);
  // Our own Newton solver object, so that its convergence test can be wrapped: IDA installs
  // its test when the solver is attached, and convergenceTest() calls it first.
  e.newton = SUNNonlinSol_Newton(e.yy, e.context);
  IDASetNonlinearSolver(e.ida, e.newton);
  const auto* content = static_cast<SUNNonlinearSolverContent_Newton>(e.newton->content);
  e.idaTest = content->CTest;
  e.idaTestData = content->ctest_data;
  SUNNonlinSolSetConvTestFn(e.newton, &Engine::convergenceTest, &e);
  // ERROR is both relative and absolute, as GSTIFF's ERROR (1 + |y|) weighting.
  e.rtol = settings_.error;
  e.absTol = atol;
  e.velocity.assign(n, 0);
  e.position.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    e.velocity[i] = problem_.role(i) == DaeProblem::Role::Velocity;
    e.position[i] = problem_.role(i) == DaeProblem::Role::Position;
  }
  IDAWFtolerances(e.ida, &Engine::errorWeights);
  IDASetId(e.ida, e.id);
  IDASetSuppressAlg(e.ida, SUNTRUE);

  e.sparse = problem_.sparse() && n >= BdfIntegrator::kSparseThreshold;
  if (e.sparse) {
    e.sparseJac = *problem_.pattern();
    if (settings_.pivotOrder != PivotOrder::Default)
      e.klu.setOptions(KluLinearSolver::optionsFor(settings_.pivotOrder));
    e.klu.analyze(e.sparseJac);
    e.matrix = SUNSparseMatrix(n, n, 1, CSC_MAT, e.context);
  } else {
    e.matrix = SUNDenseMatrix(n, n, e.context);
  }
  e.linear = SUNLinSolNewEmpty(e.context);
  e.linear->content = &e;
  e.linear->ops->gettype = &Engine::type;
  e.linear->ops->getid = &Engine::identity;
  e.linear->ops->initialize = &Engine::initialize;
  e.linear->ops->setup = &Engine::setup;
  e.linear->ops->solve = &Engine::solve;
  e.linear->ops->lastflag = &Engine::lastFlag;
  e.linear->ops->free = &Engine::release;
  IDASetLinearSolver(e.ida, e.linear, e.matrix);
  IDASetJacFn(e.ida, &Engine::jacobian);

  IDASetMaxOrd(e.ida, std::clamp(settings_.kmax, 1, 5));
  if (std::isfinite(settings_.hmax) && settings_.hmax > 0) IDASetMaxStep(e.ida, settings_.hmax);
  // HMIN as GSTIFF's default: without a floor, a residual that cannot be evaluated past some
  // time makes IDA creep towards that time with ever smaller steps instead of failing.
  IDASetMinStep(e.ida, settings_.hmin > 0 ? settings_.hmin
                                          : std::max(1e-14, 1e-10 * std::min(settings_.hmax, 1e3)));
  if (settings_.hinit > 0) IDASetInitStep(e.ida, settings_.hinit);
  IDASetMaxNonlinIters(e.ida, std::max(1, settings_.maxit));
  IDASetNonlinConvCoef(e.ida, kNewtonConvergence);

  e.acceptedTimes.assign(1, t0);
  e.acceptedNoise.assign(1, Eigen::VectorXd());
  t_ = tPrevious_ = lastStepStart_ = t0;
  y_ = y0;
  yp_ = yp0;
  spanFromEntry_ = false;
  countedBefore_ = {};
  stats_ = {};
  failure_ = {};
  outcome_ = IdaOutcome::Ok;
}

// Stepping across a singular instant (docs/integrators.md, as BdfIntegrator::step): a step
// accepted on a stalled move is not handed to the caller; the next one is taken at once. When
// IDA then fails (repeated corrector or error-test failures), it is re-initialised, once per
// call, at the state the call started from (which the caller has seen) with a first step twice
// as long as the way to where it failed, across it. A re-initialised IDA starts again at order
// 1 without its history.
bool IdaIntegrator::step(double tout) {
  Engine& e = *engine_;
  const double eps = 1e-12 * std::max(1.0, std::abs(tout));
  if (t_ >= tout - eps) return true;
  IDASetStopTime(e.ida, tout);
  const double tEntry = t_;
  bool saved = false, returned = false;
  for (;;) {
    double tReturned = t_;
    const int flag = IDASolve(e.ida, tout, &tReturned, e.yy, e.yp, IDA_ONE_STEP);
    if (flag < 0) {
      double tStuck = t_;
      IDAGetCurrentTime(e.ida, &tStuck);
      if (saved && !returned && tStuck > tEntry &&
          (flag == IDA_CONV_FAIL || flag == IDA_ERR_FAIL)) {
        readStatistics();
        countedBefore_ = stats_;
        ++countedBefore_.rejectedSteps;
        Engine::view(e.yy) = yEntry_;
        Engine::view(e.yp) = ypEntry_;
        IDAReInit(e.ida, tEntry, e.yy, e.yp);
        IDASetInitStep(e.ida, std::min(2.0 * (tStuck - tEntry), tout - tEntry));
        IDASetStopTime(e.ida, tout);
        e.acceptedTimes.assign(1, tEntry);
        e.acceptedNoise.assign(1, Eigen::VectorXd());
        t_ = tEntry;
        y_ = yEntry_;
        yp_ = ypEntry_;
        returned = true;
        continue;
      }
      recordFailure(flag);
      readStatistics();
      return false;
    }
    double tCurrent = tReturned, hLast = 0.0;
    IDAGetCurrentTime(e.ida, &tCurrent);
    IDAGetLastStep(e.ida, &hLast);
    lastStepStart_ = tCurrent - hLast;
    e.recordAccepted(tCurrent);
    if (e.stalledMove && !saved && !returned) {  // the entry state may be needed
      yEntry_ = y_;
      ypEntry_ = yp_;
      saved = true;
    }
    t_ = std::abs(tReturned - tout) <= eps ? tout : tReturned;
    y_ = Engine::view(e.yy);
    yp_ = Engine::view(e.yp);
    readStatistics();
    if (observingSteps()) {
      // DEBUG/EPRINT: IDA takes its rejected attempts inside IDASolve (counted in the
      // statistics), so each accepted step is reported as its attempt (order, start, step size)
      // and its acceptance; without the attempt line the order, time and step of DSTIFF were
      // missing from the .msg (docs/validation.md, "IFToMM A02", DSTIFF at N = 40).
      IDAGetErrWeights(e.ida, e.weights);
      IDAGetEstLocalErrors(e.ida, e.localErrors);
      notifyStep(
          {StepInfo::Event::Attempt, stats_.steps, stats_.order, lastStepStart_, hLast, 0.0});
      notifyStep({StepInfo::Event::Accepted, stats_.steps, stats_.order, lastStepStart_, hLast,
                  N_VWrmsNorm(e.localErrors, e.weights)});
    }
    if (e.stalledMove && !returned && t_ < tout - eps) continue;  // not handed over yet
    tPrevious_ = tEntry;
    spanFromEntry_ = saved;
    return true;
  }
}

void IdaIntegrator::interpolate(double s, Eigen::VectorXd& y, Eigen::VectorXd& yp) const {
  Engine& e = *engine_;
  if (s == t_) {
    y = y_;
    yp = yp_;
    return;
  }
  if (s < lastStepStart_ && spanFromEntry_ && s >= tPrevious_) {
    // Before IDA's last step, after the state handed over last (step(): the steps taken at
    // once after a stalled move): the cubic Hermite through both ends.
    const double span = t_ - tPrevious_, x = (s - tPrevious_) / span;
    const HermiteWeights w = hermiteWeights(x);
    y = w.h00 * yEntry_ + w.h10 * span * ypEntry_ + w.h01 * y_ + w.h11 * span * yp_;
    yp = (w.d00 * yEntry_ + w.d01 * y_) / span + w.d10 * ypEntry_ + w.d11 * yp_;
    return;
  }
  IDAGetDky(e.ida, s, 0, e.work);
  y = Engine::view(e.work);
  IDAGetDky(e.ida, s, 1, e.work);
  yp = Engine::view(e.work);
}

void IdaIntegrator::readStatistics() {
  Engine& e = *engine_;
  long value = 0;
  // IDAReInit (step()) resets IDA's counters: the runs before it are in countedBefore_.
  IDAGetNumSteps(e.ida, &value);
  stats_.steps = countedBefore_.steps + value;
  IDAGetNumErrTestFails(e.ida, &value);
  stats_.rejectedSteps = countedBefore_.rejectedSteps + value;
  IDAGetNumNonlinSolvConvFails(e.ida, &value);
  stats_.newtonFailures = countedBefore_.newtonFailures + value;
  IDAGetNumResEvals(e.ida, &value);
  stats_.residualEvaluations = countedBefore_.residualEvaluations + value;
  stats_.jacobianEvaluations = e.jacobianEvaluations;
  int order = 1;
  IDAGetLastOrder(e.ida, &order);
  stats_.order = order;
  double h = 0.0;
  IDAGetLastStep(e.ida, &h);
  stats_.stepSize = h;
}

void IdaIntegrator::recordFailure(int flag) {
  Engine& e = *engine_;
  switch (flag) {
    case IDA_TOO_MUCH_WORK: outcome_ = IdaOutcome::TooMuchWork; break;
    case IDA_TOO_MUCH_ACC: outcome_ = IdaOutcome::TooMuchAccuracy; break;
    case IDA_ERR_FAIL: outcome_ = IdaOutcome::ErrorTestFailures; break;
    case IDA_CONV_FAIL: outcome_ = IdaOutcome::ConvergenceFailures; break;
    case IDA_LSETUP_FAIL:
    case IDA_LSOLVE_FAIL: outcome_ = IdaOutcome::LinearSolverFailed; break;
    case IDA_RES_FAIL:
    case IDA_REP_RES_ERR:
    case IDA_FIRST_RES_FAIL: outcome_ = IdaOutcome::ResidualFailed; break;
    case IDA_CONSTR_FAIL: outcome_ = IdaOutcome::ConstraintFailures; break;
    default: outcome_ = IdaOutcome::OtherFailure; break;
  }
  static const char* const kReasons[] = {
      "",
      "too many steps without reaching the output time",
      "the requested accuracy cannot be reached in floating point",
      "the local error stays above the tolerance (repeated error-test failures)",
      "the corrector did not converge (repeated Newton failures)",
      "the Newton matrix is singular",
      "the equations could not be evaluated (a non-finite value)",
      "the constraints on the unknowns were violated",
      "the integrator failed",
  };
  double tCurrent = t_, h = 0.0;
  IDAGetCurrentTime(e.ida, &tCurrent);
  IDAGetCurrentStep(e.ida, &h);
  failure_ = {};
  failure_.time = tCurrent;
  failure_.stepSize = h;
  failure_.reason = kReasons[static_cast<int>(outcome_)];
  // The worst equation: the residual of the step IDA could not take, predicted by a forward
  // Euler step from the last accepted state (at the accepted state itself every residual is
  // converged away and says nothing about the cause).
  const Eigen::VectorXd yPredicted = y_ + h * yp_;
  problem_.residual(t_ + h, yPredicted, yp_, e.gWork);
  for (int i = 0; i < e.gWork.size(); ++i) {
    const double r = std::abs(e.gWork(i));
    if (failure_.worstEquation < 0 || !std::isfinite(r) || r > failure_.worstResidual) {
      failure_.worstEquation = i;
      failure_.worstResidual = r;
      if (!std::isfinite(r)) break;
    }
  }
  // The worst variable: the largest weighted local-error estimate of the last attempt.
  if (IDAGetEstLocalErrors(e.ida, e.localErrors) == IDA_SUCCESS &&
      IDAGetErrWeights(e.ida, e.weights) == IDA_SUCCESS) {
    const auto ele = Engine::view(e.localErrors);
    const auto w = Engine::view(e.weights);
    for (int i = 0; i < ele.size(); ++i) {
      const double c = std::abs(ele(i) * w(i));
      if (problem_.differential(i) && (failure_.worstVariable < 0 || c > failure_.worstChange)) {
        failure_.worstVariable = i;
        failure_.worstChange = std::abs(ele(i));
      }
    }
  }
}

}  // namespace openmss::solvers
