#include "user/ucon_routine.hpp"

#include <atomic>
#include <cstring>
#include <limits>
#include <vector>

#include "user/openmss_usersub.h"
#include "user/plain_routine.hpp"

namespace openmss::user {
namespace {

// UCOSUB(ID, TIME, Q, PAR, NPAR, IDRSEL, IFLAG, SCALAR, ARRAY, XMATRX), every argument by
// reference; XMATRX is DOUBLE PRECISION XMATRX(30, 30).
using F77Ucosub = void(int* id, double* time, double* q, double* par, int* npar, int* idrsel,
                       int* iflag, double* scalar, double* array, double* xmatrx);

constexpr int kMax = kMaxUconVariables;

// The UCON whose initialization runs on this thread: UCOVAR stores into it.
struct Declaration {
  long id = 0;
  UconVariables* out = nullptr;
  int calls = 0;
  std::string error;
};
thread_local Declaration declaring;

// The last evaluation on this thread: the equation's value, its row and its acceleration term
// read the routine at the same q, once.
struct UconCache {
  unsigned long serial = 0;
  double time = 0.0;
  int order = -1;
  double q[kMax], value, first[kMax], second[kMax * kMax];
};
thread_local UconCache cache_;

class Ucon final : public UserConstraintRoutine {
 public:
  Ucon(const ElementData& element, std::unique_ptr<PlainRoutine> routine)
      : element_(element), r_(std::move(routine)), serial_(++serials) {
    par_ = element_.par;
    par_.push_back(0.0);  // never an empty array
    s_ = sAdamsUcon{};
    s_.ID = static_cast<int>(element_.id);
    s_.NPAR = static_cast<int>(element_.par.size());
    s_.PAR = element_.par.empty() ? nullptr : element_.par.data();
  }

  // IFLAG = 1 then 3 (ADAMS's initialization, UCOVAR at 3) at q = 0.
  std::string initialize(UconVariables& declared) {
    const Declaration saved = declaring;
    declaring = {element_.id, &declared, 0, {}};
    double q[kMax] = {}, scalar = 0.0, array[kMax], xmatrx[kMax * kMax];
    for (int iflag : {1, 3})
      if (!raw(0.0, q, iflag, 0, &scalar, array, xmatrx)) break;
    const Declaration d = declaring;
    declaring = saved;
    if (!r_->fatalError().empty()) return r_->fatalError();
    if (!d.error.empty()) return r_->who() + ": " + d.error;
    if (d.calls == 0)
      return r_->who() + " did not call UCOVAR when IFLAG = 3: the constraint has no variables";
    s_.NQ = static_cast<int>(declared.codes.size());
    return {};
  }

  void evaluate(double time, const double* q, int n, int order, double* value, double* first,
                double* second) const override {
    UconCache& c = cache_;
    const size_t bytes = sizeof(double) * static_cast<size_t>(n);
    const bool hit = c.serial == serial_ && c.time == time && c.order >= order &&
                     std::memcmp(c.q, q, bytes) == 0;
    if (!hit) {
      c.serial = 0;
      if (!raw(time, q, 0, order, &c.value, c.first, c.second) || !r_->finite(&c.value, 1, time) ||
          (order >= 1 && !r_->finite(c.first, n, time)) ||
          (order >= 2 && !r_->finite(c.second, kMax * kMax, time))) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        c.value = nan;
        for (int k = 0; k < kMax; ++k) c.first[k] = nan;
        for (int k = 0; k < kMax * kMax; ++k) c.second[k] = nan;
      }
      c.serial = serial_;
      c.time = time;
      c.order = order;
      std::memcpy(c.q, q, bytes);
    }
    *value = c.value;
    if (order >= 1) std::memcpy(first, c.first, bytes);
    if (order >= 2)
      for (int l = 0; l < n; ++l)
        for (int k = 0; k < n; ++k) second[k + n * l] = c.second[k + kMax * l];
  }

 private:
  // One call; the outputs zeroed first, since ADAMS lets the routine leave symbolically zero
  // partials unset. IDRSEL asks for the value and the partials up to `order`.
  bool raw(double time, const double* q, int iflag, int order, double* scalar, double* array,
           double* xmatrx) const {
    double copy[kMax] = {};  // a copy: FORTRAN may write its arguments
    const int n = s_.NQ;
    if (n > 0) std::memcpy(copy, q, sizeof(double) * static_cast<size_t>(n));
    *scalar = 0.0;
    std::memset(array, 0, sizeof(double) * kMax);
    std::memset(xmatrx, 0, sizeof(double) * kMax * kMax);
    int idrsel[3] = {1, order >= 1 ? 1 : 0, order >= 2 ? 1 : 0};
    return r_->call(time, [&] {
      if (r_->fortran()) {
        int id = s_.ID, npar = s_.NPAR, ifl = iflag;
        double t = time;
        std::vector<double> par = par_;
        r_->function<F77Ucosub>()(&id, &t, copy, par.data(), &npar, idrsel, &ifl, scalar, array,
                                  xmatrx);
      } else {
        r_->function<adams_c_Ucosub>()(&s_, time, copy, idrsel, iflag, scalar, array, xmatrx);
      }
    });
  }

  static inline std::atomic<unsigned long> serials{0};
  ElementData element_;
  std::vector<double> par_;
  std::unique_ptr<PlainRoutine> r_;
  unsigned long serial_;
  sAdamsUcon s_{};
};

}  // namespace

std::shared_ptr<const UserConstraintRoutine> loadUserConstraintRoutine(
    const ElementData& element, const RoutineName& name, const std::string& baseDirectory,
    UconVariables& declared, std::string& error) {
  ResolvedRoutine r;
  if (!resolveRoutine("UCOSUB", name, baseDirectory, r, error)) return nullptr;
  auto u = std::make_shared<Ucon>(
      element,
      std::make_unique<PlainRoutine>("UCOSUB", element.subject, std::move(r), element.data));
  declared = {};
  error = u->initialize(declared);
  if (!error.empty()) return nullptr;
  return u;
}

}  // namespace openmss::user

extern "C" {

// UCOVAR: only inside UCOSUB's initialization, for its own UCON id; the last call wins.
void c_ucovar(int id, int nparts, const int* lparts, int nvars, const int* lvars) {
  using openmss::user::declaring;
  auto& d = declaring;
  if (!d.out) return;  // not during a UCON initialization: nothing to declare into
  ++d.calls;
  if (id != d.id) {
    d.error = "UCOVAR was called with ID = " + std::to_string(id) + ", not the UCON's id";
    return;
  }
  if (nparts != nvars || nvars < 1 || nvars > openmss::user::kMaxUconVariables) {
    d.error = "UCOVAR was called with NPARTS = " + std::to_string(nparts) +
              " and NVARS = " + std::to_string(nvars) + "; they must be equal and between 1 and 30";
    return;
  }
  d.error.clear();
  d.out->parts.assign(lparts, lparts + nparts);
  d.out->codes.assign(lvars, lvars + nvars);
}

void ucovar_(const int* id, const int* nparts, const int* lparts, const int* nvars,
             const int* lvars) {
  c_ucovar(*id, *nparts, lparts, *nvars, lvars);
}

}  // extern "C"
