#include "user/contact_routines.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "user/difference_step.hpp"
#include "user/openmss_usersub.h"
#include "user/plain_routine.hpp"

namespace openmss::user {
namespace {

using F77Cnfsub = void(int* id, double* time, double* par, int* npar, double* loci, double* ni,
                       double* locj, double* nj, double* gap, double* gapdot, double* gapdotdot,
                       double* area, int* dflag, int* iflag, double* values);
using F77Cffsub = void(int* id, double* time, double* par, int* npar, double* loci, double* locj,
                       double* x, double* xdot, double* nforce, double* area, int* dflag,
                       int* iflag, double* values);

// What CNFSUB and CFFSUB share: the struct, the call under the guard, the partials protocol.
// `Input` is the point's arguments; raw() calls the routine once; `inputOf(k)` the argument
// that partial k (1, 2) is taken in.
template <class Interface, class Input>
class ContactRoutine : public Interface, public PlainRoutine {
 public:
  ContactRoutine(const char* adamsName, const ContactElementData& e, ResolvedRoutine r)
      : PlainRoutine(adamsName, e.element.subject, std::move(r), e.element.data), e_(e) {
    s_.contact = {static_cast<int>(e_.element.id),
                  static_cast<int>(e_.igeom.size()),
                  static_cast<int>(e_.jgeom.size()),
                  e_.igeom.data(),
                  e_.jgeom.data(),
                  nullptr,
                  nullptr};
    s_.NPAR = static_cast<int>(e_.element.par.size());
    s_.PAR = e_.element.par.empty() ? nullptr : e_.element.par.data();
    par_ = e_.element.par;
    if (par_.empty()) par_.push_back(0.0);
  }

  // IFLAG = 1 then 3 (ADAMS's initialization), at zero arguments.
  std::string initialize() const {
    Input in{};
    double v[3];
    for (int iflag : {1, 3}) raw(0.0, in, 0, iflag, v);
    return fatalError();
  }

  void evaluate(double time, const Input& in, bool partials, double values[3]) const override {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    values[0] = nan;
    values[1] = values[2] = unsetPartial();
    bool ok = raw(time, in, partials ? 1 : 0, 0, values) && finite(values, 1, time);
    if (ok && partials) {
      for (int k = 1; k <= 2; ++k)
        if (isUnsetPartial(values[k])) values[k] = difference(time, in, k);
      ok = finite(values + 1, 2, time);
    }
    if (!partials) values[1] = values[2] = 0.0;
    if (!ok && !fatalError().empty()) values[0] = values[1] = values[2] = nan;
  }

 protected:
  virtual bool raw(double time, const Input& in, int dflag, int iflag, double* values) const = 0;
  virtual double& inputOf(Input& in, int k) const = 0;
  // d values[0] / d input k by central differences, DFLAG = 0.
  double difference(double time, const Input& in, int k) const {
    Input a = in, b = in;
    const double base = inputOf(a, k), h = differenceStep(base);
    inputOf(a, k) = base + h;
    inputOf(b, k) = base - h;
    double plus[3], minus[3];
    raw(time, a, 0, 0, plus);
    raw(time, b, 0, 0, minus);
    return (plus[0] - minus[0]) / (2.0 * h);
  }

  ContactElementData e_;
  sAdamsContactFriction s_{};
  std::vector<double> par_;  // never empty: FORTRAN gets a valid PAR
};

class Normal final : public ContactRoutine<ContactNormalRoutine, ContactNormalInput> {
 public:
  Normal(const ContactElementData& e, ResolvedRoutine r)
      : ContactRoutine("CNFSUB", e, std::move(r)) {}

 private:
  bool raw(double time, const ContactNormalInput& in, int dflag, int iflag,
           double* values) const override {
    // Copies: the routine may write its arguments (FORTRAN passes everything by reference).
    ContactNormalInput c = in;
    return call(time, [&] {
      if (fortran()) {
        int id = s_.contact.ID, npar = s_.NPAR, df = dflag, ifl = iflag;
        double t = time;
        std::vector<double> par = par_;
        function<F77Cnfsub>()(&id, &t, par.data(), &npar, c.loci, c.ni, c.locj, c.nj, &c.gap,
                              &c.gapdot, &c.gapdotdot, &c.area, &df, &ifl, values);
      } else {
        function<adams_c_Cnfsub>()(&s_, time, c.loci, c.ni, c.locj, c.nj, c.gap, c.gapdot,
                                   c.gapdotdot, c.area, dflag, iflag, values);
      }
    });
  }
  double& inputOf(ContactNormalInput& in, int k) const override {
    return k == 1 ? in.gap : in.gapdot;
  }
};

class Friction final : public ContactRoutine<ContactFrictionRoutine, ContactFrictionInput> {
 public:
  Friction(const ContactElementData& e, ResolvedRoutine r)
      : ContactRoutine("CFFSUB", e, std::move(r)) {}

 private:
  bool raw(double time, const ContactFrictionInput& in, int dflag, int iflag,
           double* values) const override {
    ContactFrictionInput c = in;
    return call(time, [&] {
      if (fortran()) {
        int id = s_.contact.ID, npar = s_.NPAR, df = dflag, ifl = iflag;
        double t = time;
        std::vector<double> par = par_;
        function<F77Cffsub>()(&id, &t, par.data(), &npar, c.loci, c.locj, c.x, c.xdot, &c.nforce,
                              &c.area, &df, &ifl, values);
      } else {
        function<adams_c_Cffsub>()(&s_, time, c.loci, c.locj, c.x, c.xdot, c.nforce, c.area, dflag,
                                   iflag, values);
      }
    });
  }
  double& inputOf(ContactFrictionInput& in, int k) const override {
    return k == 1 ? in.xdot[0] : in.nforce;
  }
};

template <class R>
std::shared_ptr<R> load(const char* adamsName, const ContactElementData& element,
                        const RoutineName& routine, const std::string& baseDirectory,
                        std::string& error) {
  ResolvedRoutine resolved;
  if (!resolveRoutine(adamsName, routine, baseDirectory, resolved, error)) return nullptr;
  auto r = std::make_shared<R>(element, std::move(resolved));
  error = r->initialize();
  if (!error.empty()) return nullptr;
  return r;
}

}  // namespace

std::shared_ptr<const ContactNormalRoutine> loadContactNormalRoutine(
    const ContactElementData& element, const RoutineName& routine, const std::string& baseDirectory,
    std::string& error) {
  return load<Normal>("CNFSUB", element, routine, baseDirectory, error);
}

std::shared_ptr<const ContactFrictionRoutine> loadContactFrictionRoutine(
    const ContactElementData& element, const RoutineName& routine, const std::string& baseDirectory,
    std::string& error) {
  return load<Friction>("CFFSUB", element, routine, baseDirectory, error);
}

}  // namespace openmss::user
