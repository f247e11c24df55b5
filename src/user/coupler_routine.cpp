#include "user/coupler_routine.hpp"

#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "user/difference_step.hpp"
#include "user/openmss_usersub.h"
#include "user/plain_routine.hpp"

namespace openmss::user {
namespace {

// COUSUB(ID, TIME, PAR, NPAR, DISP, NDISP, IFLAG, PHI); COUXX and COUXX2 the same with DFDA
// (NDISP values) and D2FDA2 (NDISP x NDISP) as the last argument.
using F77Cousub = void(int* id, double* time, double* par, int* npar, double* disp, int* ndisp,
                       int* iflag, double* out);
using CCousub = void(const sAdamsCoupler*, double time, double* disp, int iflag, double* out);

// The last evaluation on this thread: the equation's value, its row and its acceleration term
// read the routine at the same displacements, once.
struct CouplerCache {
  unsigned long serial = 0;  // Coupler::serial_, unique for the process's life
  double time = 0.0;
  int order = -1;
  double disp[3], phi, first[3], second[9];
};
thread_local CouplerCache cache_;

class Coupler final : public CouplerRoutine {
 public:
  Coupler(const CouplerDescription& d, std::unique_ptr<PlainRoutine> routines[3])
      : d_(d), serial_(++serials) {
    for (int k = 0; k < 3; ++k) r_[k] = std::move(routines[k]);
    s_ = sAdamsCoupler{};
    s_.ID = static_cast<int>(d_.element.id);
    s_.NPAR = static_cast<int>(d_.element.par.size());
    s_.PAR = d_.element.par.empty() ? nullptr : d_.element.par.data();
    s_.NJOINT = d_.count;
    for (int k = 0; k < 3; ++k) {
      s_.JOINTS[k] = k < d_.count ? d_.joints[k] : 0;
      s_.TYPE[k] = k < d_.count ? d_.types[k] : ' ';
    }
  }

  // IFLAG = 1 then 3 (ADAMS's initialization) at zero displacements, every routine present.
  std::string initialize() const {
    double disp[3] = {}, out[9];
    for (int iflag : {1, 3})
      for (const auto& r : r_)
        if (r) raw(*r, 0.0, disp, iflag, out);
    return fatalError();
  }

  void evaluate(double time, const double* disp, int n, int order, double* phi, double* first,
                double* second) const override;

 private:
  std::string fatalError() const {
    for (const auto& r : r_)
      if (r && !r->fatalError().empty()) return r->fatalError();
    return {};
  }
  bool raw(const PlainRoutine& r, double time, const double* disp, int iflag, double* out) const {
    double d[3] = {0.0, 0.0, 0.0};  // a copy: FORTRAN may write its arguments
    std::memcpy(d, disp, sizeof(double) * static_cast<size_t>(d_.count));
    return r.call(time, [&] {
      if (r.fortran()) {
        int id = s_.ID, npar = s_.NPAR, n = d_.count, ifl = iflag;
        double t = time;
        std::vector<double> par = d_.element.par;
        par.push_back(0.0);  // never an empty array
        r.function<F77Cousub>()(&id, &t, par.data(), &npar, d, &n, &ifl, out);
      } else {
        r.function<CCousub>()(&s_, time, d, iflag, out);
      }
    });
  }
  // Routine k at disp, its `size` outputs checked finite; false once stopped.
  bool value(int k, double time, const double* disp, double* out, int size) const {
    return raw(*r_[k], time, disp, 0, out) && r_[k]->finite(out, size, time);
  }
  bool compute(double time, const double* disp, int order, CouplerCache& c) const;
  bool firstByDifferences(double time, const double* disp, double* first) const;
  bool secondByDifferences(double time, const double* disp, double* second) const;

  static inline std::atomic<unsigned long> serials{0};
  CouplerDescription d_;
  std::unique_ptr<PlainRoutine> r_[3];
  unsigned long serial_;
  sAdamsCoupler s_{};
};

void Coupler::evaluate(double time, const double* disp, int n, int order, double* phi,
                       double* first, double* second) const {
  CouplerCache& c = cache_;
  const size_t bytes = sizeof(double) * static_cast<size_t>(n);
  const bool hit = c.serial == serial_ && c.time == time && c.order >= order &&
                   std::memcmp(c.disp, disp, bytes) == 0;
  if (!hit) {
    c.serial = 0;
    if (!compute(time, disp, order, c)) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      c.phi = nan;
      for (int k = 0; k < 9; ++k) c.first[k % 3] = c.second[k] = nan;
    }
    c.serial = serial_;
    c.time = time;
    c.order = order;
    std::memcpy(c.disp, disp, bytes);
  }
  *phi = c.phi;
  if (order >= 1) std::memcpy(first, c.first, bytes);
  if (order >= 2) std::memcpy(second, c.second, bytes * static_cast<size_t>(n));
}

bool Coupler::compute(double time, const double* disp, int order, CouplerCache& c) const {
  const int n = d_.count;
  if (!value(0, time, disp, &c.phi, 1)) return false;
  if (order >= 1 &&
      !(r_[1] ? value(1, time, disp, c.first, n) : firstByDifferences(time, disp, c.first)))
    return false;
  if (order >= 2 &&
      !(r_[2] ? value(2, time, disp, c.second, n * n) : secondByDifferences(time, disp, c.second)))
    return false;
  return true;
}

// d phi / d disp_k by central differences of COUSUB, step cbrt(eps) max(1, |x|) as for the
// evaluation subroutines (docs/user-subroutines.md, "The protocol").
bool Coupler::firstByDifferences(double time, const double* disp, double* first) const {
  double d[3], plus, minus;
  for (int k = 0; k < d_.count; ++k) {
    std::memcpy(d, disp, sizeof d);
    const double h = differenceStep(disp[k]);
    d[k] = disp[k] + h;
    if (!value(0, time, d, &plus, 1)) return false;
    d[k] = disp[k] - h;
    if (!value(0, time, d, &minus, 1)) return false;
    first[k] = (plus - minus) / (2.0 * h);
  }
  return true;
}

// The second partials: central differences of COUXX (step cbrt(eps) max(1, |x|)) when the
// library has it, else second differences of COUSUB with step eps^(1/4) max(1, |x|), which
// balances their truncation (h^2) and rounding (eps / h^2) errors at about 1e-8 relative.
bool Coupler::secondByDifferences(double time, const double* disp, double* second) const {
  const int n = d_.count;
  double d[3];
  if (r_[1]) {
    double plus[3], minus[3];
    for (int l = 0; l < n; ++l) {
      std::memcpy(d, disp, sizeof d);
      const double h = differenceStep(disp[l]);
      d[l] = disp[l] + h;
      if (!value(1, time, d, plus, n)) return false;
      d[l] = disp[l] - h;
      if (!value(1, time, d, minus, n)) return false;
      for (int k = 0; k < n; ++k) second[k + n * l] = (plus[k] - minus[k]) / (2.0 * h);
    }
    return true;
  }
  const double rel = std::sqrt(std::sqrt(DBL_EPSILON));
  double h[3];
  for (int k = 0; k < n; ++k) h[k] = differenceStep(disp[k], rel);
  for (int k = 0; k < n; ++k)
    for (int l = k; l < n; ++l) {
      double f[4];
      const double sk[4] = {1, 1, -1, -1}, sl[4] = {1, -1, 1, -1};
      for (int m = 0; m < 4; ++m) {
        std::memcpy(d, disp, sizeof d);
        d[k] += sk[m] * h[k];
        d[l] += sl[m] * h[l];
        if (!value(0, time, d, &f[m], 1)) return false;
      }
      second[k + n * l] = second[l + n * k] = (f[0] - f[1] - f[2] + f[3]) / (4.0 * h[k] * h[l]);
    }
  return true;
}

}  // namespace

std::shared_ptr<const CouplerRoutine> loadCouplerRoutine(
    const CouplerDescription& coupler, const RoutineName names[3], const bool explicitly[3],
    bool partialRoutines, const std::string& baseDirectory, std::string& error) {
  static const char* const kAdams[3] = {"COUSUB", "COUXX", "COUXX2"};
  std::unique_ptr<PlainRoutine> routines[3];
  for (int k = 0; k < 3; ++k) {
    if (k > 0 && !explicitly[k] && !partialRoutines) continue;
    ResolvedRoutine r;
    std::string why;
    if (!resolveRoutine(kAdams[k], names[k], baseDirectory, r, why)) {
      if (k == 0 || explicitly[k]) {
        error = why;
        return nullptr;
      }
      continue;  // optional: the solver differences COUSUB instead
    }
    routines[k] = std::make_unique<PlainRoutine>(kAdams[k], coupler.element.subject, std::move(r),
                                                 coupler.element.data);
  }
  auto c = std::make_shared<Coupler>(coupler, routines);
  error = c->initialize();
  if (!error.empty()) return nullptr;
  return c;
}

}  // namespace openmss::user
