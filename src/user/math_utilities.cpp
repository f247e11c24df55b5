// General-function utilities user routines call (c_step, c_impact, ...; user/openmss_usersub.h)
// and their gfortran names: the same mathematics as the expression functions of the same
// name (expr/general_functions.hpp), so a routine and an expression agree to the last bit.
// Derivatives in x come from the second-order jets of expr/jet.hpp.

#include <cstddef>
#include <vector>

#include "expr/general_functions.hpp"
#include "user/element_call.hpp"
#include "user/openmss_usersub.h"

namespace {

using openmss::expr::Jet1;
using openmss::expr::Jet2;
namespace g = openmss::expr::general;

Jet2 c(double v) { return {v, 0.0, 0.0}; }
Jet2 seeded(double x) { return {x, 1.0, 0.0}; }

bool pick(const Jet2& j, int iord, double* value, int* errflg) {
  *errflg = iord < 0 || iord > 2 ? 1 : 0;
  *value = iord == 0 ? j.v : iord == 1 ? j.d1 : iord == 2 ? j.d2 : 0.0;
  return *errflg == 0;
}

// x, x0 [, w], then the coefficients, as the expression functions take them.
std::vector<Jet2> arguments(double x, const double* lead, int nlead, const double* par, int npar) {
  std::vector<Jet2> a{seeded(x)};
  for (int k = 0; k < nlead; ++k) a.push_back(c(lead[k]));
  for (int k = 0; k < npar; ++k) a.push_back(c(par[k]));
  return a;
}

// IMPACT / BISTOP: force and its partials in x and in dxdt (one Jet1 pass each).
template <class F>
void contact(const F& f, double x, double dxdt, double* vec, int* errflg) {
  const Jet1 dx = f(Jet1{x, 1.0}, Jet1{dxdt, 0.0});
  const Jet1 dv = f(Jet1{x, 0.0}, Jet1{dxdt, 1.0});
  vec[0] = dx.v;
  vec[1] = dx.d;
  vec[2] = dv.d;
  *errflg = 0;
}

}  // namespace

void openmss::user::detail::anchorMathUtilities() {}

extern "C" {

void c_step(double x, double x0, double h0, double x1, double h1, int iord, double* value,
            int* errflg) {
  if (x1 <= x0) {
    *errflg = 1;
    *value = 0.0;
    return;
  }
  pick(g::step(seeded(x), c(x0), c(h0), c(x1), c(h1)), iord, value, errflg);
}

void c_step5(double x, double x0, double h0, double x1, double h1, int iord, double* value,
             int* errflg) {
  if (x1 <= x0) {
    *errflg = 1;
    *value = 0.0;
    return;
  }
  pick(g::step5(seeded(x), c(x0), c(h0), c(x1), c(h1)), iord, value, errflg);
}

void c_havsin(double x, double x0, double h0, double x1, double h1, int iord, double* value,
              int* errflg) {
  if (x1 <= x0) {
    *errflg = 1;
    *value = 0.0;
    return;
  }
  pick(g::havsin(seeded(x), c(x0), c(h0), c(x1), c(h1)), iord, value, errflg);
}

void c_shf(double x, double x0, double a, double w, double phi, double b, int iord, double* value,
           int* errflg) {
  pick(g::shf(seeded(x), c(x0), c(a), c(w), c(phi), c(b)), iord, value, errflg);
}

void c_poly(double x, double x0, const double* par, int npar, int iord, double* value,
            int* errflg) {
  if (npar < 1) {
    *errflg = 1;
    *value = 0.0;
    return;
  }
  const std::vector<Jet2> a = arguments(x, &x0, 1, par, npar);
  pick(g::poly(a.data(), static_cast<int>(a.size())), iord, value, errflg);
}

void c_cheby(double x, double x0, const double* par, int npar, int iord, double* value,
             int* errflg) {
  if (npar < 1) {
    *errflg = 1;
    *value = 0.0;
    return;
  }
  const std::vector<Jet2> a = arguments(x, &x0, 1, par, npar);
  pick(g::cheby(a.data(), static_cast<int>(a.size())), iord, value, errflg);
}

void c_forcos(double x, double x0, double w, const double* par, int npar, int iord, double* value,
              int* errflg) {
  if (npar < 1) {
    *errflg = 1;
    *value = 0.0;
    return;
  }
  const double lead[2] = {x0, w};
  const std::vector<Jet2> a = arguments(x, lead, 2, par, npar);
  pick(g::fourierCosine(a.data(), static_cast<int>(a.size())), iord, value, errflg);
}

void c_forsin(double x, double x0, double w, const double* par, int npar, int iord, double* value,
              int* errflg) {
  if (npar < 1) {
    *errflg = 1;
    *value = 0.0;
    return;
  }
  const double lead[2] = {x0, w};
  const std::vector<Jet2> a = arguments(x, lead, 2, par, npar);
  pick(g::fourierSine(a.data(), static_cast<int>(a.size())), iord, value, errflg);
}

void c_impact(double x, double dxdt, double x1, double k, double e, double cmax, double d,
              int /*iord*/, double* vec, int* errflg) {
  contact(
      [&](const Jet1& u, const Jet1& v) {
        return g::impact(u, v, Jet1{x1, 0.0}, Jet1{k, 0.0}, Jet1{e, 0.0}, Jet1{cmax, 0.0},
                         Jet1{d, 0.0});
      },
      x, dxdt, vec, errflg);
}

void c_bistop(double x, double dxdt, double x1, double x2, double k, double e, double cmax,
              double d, int /*iord*/, double* vec, int* errflg) {
  contact(
      [&](const Jet1& u, const Jet1& v) {
        return g::bistop(u, v, Jet1{x1, 0.0}, Jet1{x2, 0.0}, Jet1{k, 0.0}, Jet1{e, 0.0},
                         Jet1{cmax, 0.0}, Jet1{d, 0.0});
      },
      x, dxdt, vec, errflg);
}

// Deterministic: the outputs must not depend on the machine's load.
void c_getcpu(double* cpu) { *cpu = 0.0; }

// ---- gfortran names (every argument by reference) ----------------------------------------

void step_(const double* x, const double* x0, const double* h0, const double* x1, const double* h1,
           const int* iord, double* value, int* errflg) {
  c_step(*x, *x0, *h0, *x1, *h1, *iord, value, errflg);
}
void step5_(const double* x, const double* x0, const double* h0, const double* x1, const double* h1,
            const int* iord, double* value, int* errflg) {
  c_step5(*x, *x0, *h0, *x1, *h1, *iord, value, errflg);
}
void havsin_(const double* x, const double* x0, const double* h0, const double* x1,
             const double* h1, const int* iord, double* value, int* errflg) {
  c_havsin(*x, *x0, *h0, *x1, *h1, *iord, value, errflg);
}
void shf_(const double* x, const double* x0, const double* a, const double* w, const double* phi,
          const double* b, const int* iord, double* value, int* errflg) {
  c_shf(*x, *x0, *a, *w, *phi, *b, *iord, value, errflg);
}
void poly_(const double* x, const double* x0, const double* par, const int* npar, const int* iord,
           double* value, int* errflg) {
  c_poly(*x, *x0, par, *npar, *iord, value, errflg);
}
void cheby_(const double* x, const double* x0, const double* par, const int* npar, const int* iord,
            double* value, int* errflg) {
  c_cheby(*x, *x0, par, *npar, *iord, value, errflg);
}
void forcos_(const double* x, const double* x0, const double* w, const double* par, const int* npar,
             const int* iord, double* value, int* errflg) {
  c_forcos(*x, *x0, *w, par, *npar, *iord, value, errflg);
}
void forsin_(const double* x, const double* x0, const double* w, const double* par, const int* npar,
             const int* iord, double* value, int* errflg) {
  c_forsin(*x, *x0, *w, par, *npar, *iord, value, errflg);
}
void impact_(const double* x, const double* dxdt, const double* x1, const double* k,
             const double* e, const double* cmax, const double* d, const int* iord, double* vec,
             int* errflg) {
  c_impact(*x, *dxdt, *x1, *k, *e, *cmax, *d, *iord, vec, errflg);
}
void bistop_(const double* x, const double* dxdt, const double* x1, const double* x2,
             const double* k, const double* e, const double* cmax, const double* d, const int* iord,
             double* vec, int* errflg) {
  c_bistop(*x, *dxdt, *x1, *x2, *k, *e, *cmax, *d, *iord, vec, errflg);
}
void getcpu_(double* cpu) { c_getcpu(cpu); }

}  // extern "C"
