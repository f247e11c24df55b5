#include "user/field_routine.hpp"

#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "user/difference_step.hpp"
#include "user/openmss_usersub.h"
#include "user/plain_routine.hpp"

namespace openmss::user {
namespace {

using F77Fiesub = void(int* id, double* time, double* par, int* npar, double* disp, double* velo,
                       int* dflag, int* iflag, double* field, double* dfddis, double* dfdvel);

// The last evaluation on this thread: the Newton matrix's colour passes evaluate every element
// at the same state, and the routine is called once for them all.
struct FieldCache {
  unsigned long serial = 0;  // Field::serial_, unique for the process's life
  double time = 0.0;
  bool partials = false;
  double disp[6], velo[6], field[6], kd[36], cd[36];
};
thread_local FieldCache cache_;

class Field final : public FieldRoutine, public PlainRoutine {
 public:
  Field(const ElementData& e, ResolvedRoutine r)
      : PlainRoutine("FIESUB", e.subject, std::move(r), e.data), e_(e), serial_(++serials) {
    npar_ = static_cast<int>(e_.par.size());
    s_ = {static_cast<int>(e_.id), npar_, e_.par.empty() ? nullptr : e_.par.data(),
          static_cast<int>(e_.i), static_cast<int>(e_.j)};
  }

  // IFLAG = 1 then 3 (ADAMS's initialization), at zero displacement and velocity.
  std::string initialize() const {
    double disp[6] = {}, velo[6] = {}, f[6], kd[36], cd[36];
    for (int iflag : {1, 3}) raw(0.0, disp, velo, 0, iflag, f, kd, cd);
    return fatalError();
  }

  void evaluate(double time, const double disp[6], const double velo[6], bool partials,
                double field[6], double dfddis[36], double dfdvel[36]) const override;

 private:
  bool raw(double time, const double* disp, const double* velo, int dflag, int iflag, double* field,
           double* dfddis, double* dfdvel) const {
    // Copies: the routine may write its arguments (FORTRAN passes everything by reference).
    double d[6], v[6];
    std::memcpy(d, disp, sizeof d);
    std::memcpy(v, velo, sizeof v);
    return call(time, [&] {
      if (fortran()) {
        int id = static_cast<int>(e_.id), npar = npar_, df = dflag, ifl = iflag;
        double t = time;
        std::vector<double> par = e_.par;
        if (par.empty()) par.push_back(0.0);
        function<F77Fiesub>()(&id, &t, par.data(), &npar, d, v, &df, &ifl, field, dfddis, dfdvel);
      } else {
        function<adams_c_Fiesub>()(&s_, time, d, v, dflag, iflag, field, dfddis, dfdvel);
      }
    });
  }

  void compute(double time, const double* disp, const double* velo, bool partials, double* field,
               double* kd, double* cd) const;
  void difference(double time, const double* disp, const double* velo, bool ofVelocity,
                  double* out) const;

  static inline std::atomic<unsigned long> serials{0};
  ElementData e_;
  unsigned long serial_;
  int npar_ = 0;
  sAdamsField s_{};
};

void Field::evaluate(double time, const double disp[6], const double velo[6], bool partials,
                     double field[6], double dfddis[36], double dfdvel[36]) const {
  FieldCache& c = cache_;
  const bool hit = c.serial == serial_ && c.time == time && (c.partials || !partials) &&
                   std::memcmp(c.disp, disp, sizeof c.disp) == 0 &&
                   std::memcmp(c.velo, velo, sizeof c.velo) == 0;
  if (!hit) {
    c.serial = 0;
    compute(time, disp, velo, partials, c.field, c.kd, c.cd);
    c.serial = serial_;
    c.time = time;
    c.partials = partials;
    std::memcpy(c.disp, disp, sizeof c.disp);
    std::memcpy(c.velo, velo, sizeof c.velo);
  }
  std::memcpy(field, c.field, sizeof c.field);
  if (partials) {
    std::memcpy(dfddis, c.kd, sizeof c.kd);
    std::memcpy(dfdvel, c.cd, sizeof c.cd);
  }
}

void Field::compute(double time, const double* disp, const double* velo, bool partials,
                    double* field, double* kd, double* cd) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k < 36; ++k) kd[k] = cd[k] = unsetPartial();
  for (int k = 0; k < 6; ++k) field[k] = nan;
  const bool ok =
      raw(time, disp, velo, partials ? 1 : 0, 0, field, kd, cd) && finite(field, 6, time);
  if (ok && partials) {
    // A matrix with any entry left unset comes whole from central differences.
    bool kSet = true, cSet = true;
    for (int k = 0; k < 36; ++k) {
      kSet = kSet && !isUnsetPartial(kd[k]);
      cSet = cSet && !isUnsetPartial(cd[k]);
    }
    if (!kSet) difference(time, disp, velo, false, kd);
    if (!cSet) difference(time, disp, velo, true, cd);
    if (finite(kd, 36, time) && finite(cd, 36, time)) return;
  }
  if (fatalError().empty()) return;
  for (int k = 0; k < 6; ++k) field[k] = nan;
  for (int k = 0; k < 36; ++k) kd[k] = cd[k] = nan;
}

// Column c of d field / d disp (or velo) by central differences, step cbrt(eps) max(1, |x|)
// as for the evaluation subroutines (docs/user-subroutines.md, "The protocol"), DFLAG = 0.
void Field::difference(double time, const double* disp, const double* velo, bool ofVelocity,
                       double* out) const {
  double d[6], v[6], plus[6], minus[6], kd[36], cd[36];
  for (int col = 0; col < 6; ++col) {
    std::memcpy(d, disp, sizeof d);
    std::memcpy(v, velo, sizeof v);
    double* x = ofVelocity ? v : d;
    const double base = x[col];
    const double h = differenceStep(base);
    x[col] = base + h;
    raw(time, d, v, 0, 0, plus, kd, cd);
    x[col] = base - h;
    raw(time, d, v, 0, 0, minus, kd, cd);
    for (int r = 0; r < 6; ++r) out[r + 6 * col] = (plus[r] - minus[r]) / (2.0 * h);
  }
}

}  // namespace

std::shared_ptr<const FieldRoutine> loadFieldRoutine(const ElementData& element,
                                                     const RoutineName& routine,
                                                     const std::string& baseDirectory,
                                                     std::string& error) {
  ResolvedRoutine resolved;
  if (!resolveRoutine("FIESUB", routine, baseDirectory, resolved, error)) return nullptr;
  auto f = std::make_shared<Field>(element, std::move(resolved));
  error = f->initialize();
  if (!error.empty()) return nullptr;
  return f;
}

}  // namespace openmss::user
