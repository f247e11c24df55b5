#include "user/curve_routine.hpp"

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "user/openmss_usersub.h"
#include "user/plain_routine.hpp"

namespace openmss::user {
namespace {

using F77Cursub = void(int* id, double* par, int* npar, double* alpha, int* iord, int* iflag,
                       double* values);

// The last point on this thread: its three components are asked for one after the other.
struct CurveCache {
  unsigned long owner = 0;  // Curve::serial_: unique for the process's life
  double alpha = 0.0;
  double d[5][3];
};
thread_local CurveCache cache_;

class Curve final : public CurveEvaluator, public PlainRoutine {
 public:
  Curve(const ElementData& e, const CurveShape& shape, ResolvedRoutine r)
      : PlainRoutine("CURSUB", e.subject, std::move(r), e.data),
        e_(e),
        shape_(shape),
        serial_(++serials) {
    setArgumentName("ALPHA");
    s_ = {static_cast<int>(e_.id),
          static_cast<int>(e_.par.size()),
          e_.par.empty() ? nullptr : e_.par.data(),
          shape.closed ? 1 : 0,
          shape.order,
          shape.minPar,
          shape.maxPar};
  }

  std::string initialize() const {
    double v[3];
    for (int iflag : {1, 3}) raw(shape_.minPar, 0, iflag, v);
    return fatalError();
  }

  // The routine's IORD = 0, 1, 2 at alpha; the third and fourth derivatives (the Newton matrix
  // and acceleration terms of PTCV/CVCV read them) are differences of its second derivative, step
  // 1e-4 (MAXPAR - MINPAR): their error, h^2 |C(5)| / 6 + eps |C''| / h^2, measured 5e-8 for a
  // circle of radius 0.8 over 0..2 pi. A closed curve repeats with period MAXPAR - MINPAR.
  void derivatives(double alpha, int comp, double out[5]) const override {
    const double span = shape_.maxPar - shape_.minPar;
    if (shape_.closed) alpha -= span * std::floor((alpha - shape_.minPar) / span);
    CurveCache& c = cache_;
    if (c.owner != serial_ || !(c.alpha == alpha)) {
      c.owner = 0;
      for (int iord = 0; iord < 3; ++iord) value(alpha, iord, c.d[iord]);
      const double h = 1e-4 * span;
      double plus[3], minus[3];
      value(alpha + h, 2, plus);
      value(alpha - h, 2, minus);
      for (int k = 0; k < 3; ++k) {
        c.d[3][k] = (plus[k] - minus[k]) / (2.0 * h);
        c.d[4][k] = (plus[k] - 2.0 * c.d[2][k] + minus[k]) / (h * h);
      }
      c.owner = serial_;
      c.alpha = alpha;
    }
    for (int k = 0; k < 5; ++k) out[k] = c.d[k][comp];
  }

 private:
  void value(double alpha, int iord, double* v) const {
    v[0] = v[1] = v[2] = std::numeric_limits<double>::quiet_NaN();
    if (!raw(alpha, iord, 0, v) || !finite(v, 3, alpha))
      v[0] = v[1] = v[2] = std::numeric_limits<double>::quiet_NaN();
  }

  // TIME does not enter a curve: messages give ALPHA in its place.
  bool raw(double alpha, int iord, int iflag, double* v) const {
    return call(alpha, [&] {
      if (fortran()) {
        int id = static_cast<int>(e_.id), npar = static_cast<int>(e_.par.size()), io = iord,
            ifl = iflag;
        double a = alpha;
        std::vector<double> par = e_.par;
        if (par.empty()) par.push_back(0.0);
        function<F77Cursub>()(&id, par.data(), &npar, &a, &io, &ifl, v);
      } else {
        function<adams_c_Cursub>()(&s_, alpha, iord, iflag, v);
      }
    });
  }

  static inline std::atomic<unsigned long> serials{0};
  ElementData e_;
  CurveShape shape_;
  unsigned long serial_;
  sAdamsCurve s_{};
};

}  // namespace

std::shared_ptr<const BSplineCurve> loadCurveRoutine(const ElementData& element,
                                                     const CurveShape& shape,
                                                     const RoutineName& routine,
                                                     const std::string& baseDirectory,
                                                     std::string& error) {
  ResolvedRoutine resolved;
  if (!resolveRoutine("CURSUB", routine, baseDirectory, resolved, error)) return nullptr;
  auto c = std::make_shared<Curve>(element, shape, std::move(resolved));
  error = c->initialize();
  if (!error.empty()) return nullptr;
  return std::make_shared<const BSplineCurve>(c, shape.minPar, shape.maxPar, shape.closed);
}

}  // namespace openmss::user
