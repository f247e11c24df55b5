#pragma once
// The equations of one GSE as the mechanics sees them: plain callables on numbers, whatever
// provides them (a loaded user library: user/loaded_gse_routines.hpp; a test double). The
// numerical core never sees a library handle or a symbol name (docs/theory.md, "GSE").
//
//   x'  = f(x, xd, u, t)            derivatives   (ns)
//   y   = g(x, xd, u, t)            outputs       (no)
//   xd+ = h(x, xd, u, t)            update        (nd), at sample times only

#include <optional>
#include <string>
#include <vector>

namespace openmss::user {

// The values one evaluation reads (sizes fixed per element: ns, nd, ni).
struct GseArguments {
  double time = 0.0;
  const double* x = nullptr;   // continuous states
  const double* xd = nullptr;  // discrete states
  const double* u = nullptr;   // inputs (the VARIABLEs of the U array)
  bool perturbed = false;      // ADAMS's DFLAG: a call made to form partial derivatives
};

// Partial derivatives a routine supplied itself (ADAMS_NEEDS_PARTIALS / SYSPAR): column-major
// blocks rows x ns (dx) and rows x ni (du); a block the routine did not supply stays unset.
struct GsePartials {
  std::optional<std::vector<double>> dx, du;
};

class GseRoutines {
 public:
  virtual ~GseRoutines() = default;
  // x' (ns values). With `partials`, the routine is offered to supply d x'/dx and d x'/du.
  virtual void derivatives(const GseArguments& a, double* xdot, GsePartials* partials) const = 0;
  // y (no values), likewise.
  virtual void outputs(const GseArguments& a, double* y, GsePartials* partials) const = 0;
  // xd at the next sample (nd values); only called when hasUpdate().
  virtual bool hasUpdate() const = 0;
  virtual void update(const GseArguments& a, double* xdNext) const = 0;
  // The time to the next sample as the element's own routine gives it (GSE_SAMP), if any.
  virtual std::optional<double> sampleStep(double time) const = 0;
  // The first fatal error a routine reported while evaluating (ERRMES with STOP), or empty.
  virtual std::string fatalError() const = 0;
};

}  // namespace openmss::user
