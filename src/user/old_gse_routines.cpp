#include "user/old_gse_routines.hpp"

#include <algorithm>
#include <limits>

#include "user/openmss_usersub.h"
#include "user/plain_routine.hpp"

namespace openmss::user {
namespace {

using F77Gsesub = void(int* id, double* time, double* par, int* npar, int* dflag, int* iflag,
                       int* nstate, double* states, int* ninput, double* input, int* noutpt,
                       double* stated, double* output);
using F77Partial = void(int* id, double* time, double* par, int* npar, int* iflag, int* nstate,
                        double* states, int* ninput, double* input, int* noutpt, double* derivs);
using CGsesub = void(const sAdamsGSE*, double time, int dflag, int iflag, int nstate,
                     const double* states, int ninput, const double* inputs, int noutput,
                     double* stated, double* output);
using CPartial = void(const sAdamsGSE*, double time, int iflag, int nstate, const double* states,
                      int ninput, const double* inputs, int noutputs, double* derivs);

std::string libraryName(const std::string& library) {
  return library.empty() ? defaultLibrary() : library;
}

class OldGse final : public GseRoutines {
 public:
  OldGse(const GseDescription& d, std::unique_ptr<PlainRoutine> main)
      : d_(d), main_(std::move(main)) {
    s_ = sAdamsGSE{};
    s_.ID = static_cast<int>(d_.id);
    s_.NPAR = static_cast<int>(d_.par.size());
    s_.PAR = d_.par.empty() ? nullptr : d_.par.data();
    s_.NI = d_.ni;
    s_.NO = d_.no;
    s_.U = static_cast<int>(d_.uArray);
    s_.Y = static_cast<int>(d_.yArray);
    s_.NS = d_.ns;
    s_.X = static_cast<int>(d_.xArray);
    s_.IC = static_cast<int>(d_.icArray);
    s_.STATIC_HOLD = d_.staticHold ? 1 : 0;
  }

  // GSEXX, GSEXU, GSEYX, GSEYU (null: not in the library).
  std::unique_ptr<PlainRoutine> partial[4];

  std::string initialize() const {
    const std::vector<double> zeros(size(), 0.0);
    GseArguments a{0.0, zeros.data(), zeros.data(), zeros.data(), false};
    std::vector<double> xdot(size()), y(size()), m(size() * size());
    for (int iflag : {1, 3}) {
      gsesub(a, iflag, xdot.data(), y.data());
      for (int k = 0; k < 4; ++k)
        if (partial[k]) partialCall(k, a, iflag, m.data());
    }
    return fatalError();
  }

  void derivatives(const GseArguments& a, double* xdot, GsePartials* partials) const override {
    std::vector<double> y(size());
    if (!gsesub(a, 0, xdot, y.data())) return nan(xdot, d_.ns);
    if (partials) fill(a, 0, 1, d_.ns, *partials);
  }
  void outputs(const GseArguments& a, double* y, GsePartials* partials) const override {
    std::vector<double> xdot(size());
    if (!gsesub(a, 0, xdot.data(), y)) return nan(y, d_.no);
    if (partials) fill(a, 2, 3, d_.no, *partials);
  }
  bool hasUpdate() const override { return false; }
  void update(const GseArguments&, double*) const override {}
  std::optional<double> sampleStep(double) const override { return std::nullopt; }
  std::string fatalError() const override {
    std::string f = main_->fatalError();
    for (const auto& p : partial)
      if (f.empty() && p) f = p->fatalError();
    return f;
  }

 private:
  size_t size() const { return static_cast<size_t>(std::max({d_.ns, d_.ni, d_.no, 1})); }
  static void nan(double* v, int n) {
    std::fill(v, v + n, std::numeric_limits<double>::quiet_NaN());
  }

  // One GSESUB call; false once the routine (or a partial routine) has stopped the run.
  bool gsesub(const GseArguments& a, int iflag, double* xdot, double* y) const {
    const bool ran = main_->call(a.time, [&] {
      std::vector<double> x(a.x, a.x + d_.ns), u(a.u, a.u + d_.ni);
      x.push_back(0.0);  // never an empty array
      u.push_back(0.0);
      if (main_->fortran()) {
        int id = s_.ID, npar = s_.NPAR, df = a.perturbed ? 1 : 0, ifl = iflag, ns = d_.ns,
            ni = d_.ni, no = d_.no;
        double t = a.time;
        std::vector<double> par = d_.par;
        par.push_back(0.0);
        main_->function<F77Gsesub>()(&id, &t, par.data(), &npar, &df, &ifl, &ns, x.data(), &ni,
                                     u.data(), &no, xdot, y);
      } else {
        main_->function<CGsesub>()(&s_, a.time, a.perturbed ? 1 : 0, iflag, d_.ns, x.data(), d_.ni,
                                   u.data(), d_.no, xdot, y);
      }
    });
    if (!ran || iflag != 0) return ran && fatalError().empty();
    return main_->finite(xdot, d_.ns, a.time) && main_->finite(y, d_.no, a.time) &&
           fatalError().empty();
  }

  bool partialCall(int k, const GseArguments& a, int iflag, double* out) const {
    const PlainRoutine& r = *partial[k];
    return r.call(a.time, [&] {
      std::vector<double> x(a.x, a.x + d_.ns), u(a.u, a.u + d_.ni);
      x.push_back(0.0);
      u.push_back(0.0);
      if (r.fortran()) {
        int id = s_.ID, npar = s_.NPAR, ifl = iflag, ns = d_.ns, ni = d_.ni, no = d_.no;
        double t = a.time;
        std::vector<double> par = d_.par;
        par.push_back(0.0);
        r.function<F77Partial>()(&id, &t, par.data(), &npar, &ifl, &ns, x.data(), &ni, u.data(),
                                 &no, out);
      } else {
        r.function<CPartial>()(&s_, a.time, iflag, d_.ns, x.data(), d_.ni, u.data(), d_.no, out);
      }
    });
  }

  // The partials of `rows` outputs from routines kx (d/dx) and ku (d/du), where present.
  void fill(const GseArguments& a, int kx, int ku, int rows, GsePartials& p) const {
    if (partial[kx] && d_.ns > 0) {
      std::vector<double> m(static_cast<size_t>(rows * d_.ns));
      if (partialCall(kx, a, 0, m.data()) && partial[kx]->finite(m.data(), rows * d_.ns, a.time))
        p.dx = std::move(m);
    }
    if (partial[ku] && d_.ni > 0) {
      std::vector<double> m(static_cast<size_t>(rows * d_.ni));
      if (partialCall(ku, a, 0, m.data()) && partial[ku]->finite(m.data(), rows * d_.ni, a.time))
        p.du = std::move(m);
    }
  }

  GseDescription d_;
  sAdamsGSE s_;
  std::unique_ptr<PlainRoutine> main_;
};

}  // namespace

bool prefersOldGseInterface(const std::string& library, const std::string& baseDirectory) {
  const std::string name = libraryName(library);
  if (name.empty()) return false;
  std::string why;
  const std::shared_ptr<Library> lib = Library::open(name, baseDirectory, why);
  if (!lib) return false;  // the new interface's loader says why
  for (const char* n : {"Gse_deriv", "Gse_output"})
    if (lib->symbol(n)) return false;
  for (const char* n : {"Gsesub", "gsesub_", "GSESUB", "gsesub"})
    if (lib->symbol(n)) return true;
  return false;
}

std::shared_ptr<const GseRoutines> loadOldGseRoutines(const GseDescription& description,
                                                      const std::string& library,
                                                      const std::string& baseDirectory,
                                                      std::vector<std::string>& errors) {
  const std::string subject = "GSE/" + std::to_string(description.id);
  if (description.nd > 0) {
    errors.push_back(
        "the old GSE interface (GSESUB) has no discrete states: ND must be 0, or give the "
        "GSE_DERIV/GSE_OUTPUT/GSE_UPDATE/GSE_SAMP routines");
    return nullptr;
  }
  const RoutineName lib{library, ""};
  ResolvedRoutine main;
  std::string error;
  if (!resolveRoutine("GSESUB", lib, baseDirectory, main, error)) {
    errors.push_back(error);
    return nullptr;
  }
  auto gse = std::make_shared<OldGse>(
      description, std::make_unique<PlainRoutine>("GSESUB", subject, std::move(main), nullptr));
  const char* names[4] = {"GSEXX", "GSEXU", "GSEYX", "GSEYU"};
  for (int k = 0; k < 4; ++k) {
    ResolvedRoutine r;
    std::string ignored;  // optional: without it the solver differences GSESUB
    if (resolveRoutine(names[k], lib, baseDirectory, r, ignored))
      gse->partial[k] = std::make_unique<PlainRoutine>(names[k], subject, std::move(r), nullptr);
  }
  const std::string fatal = gse->initialize();
  if (!fatal.empty()) {
    errors.push_back("its routines stopped during initialization (IFLAG = 1): " + fatal);
    return nullptr;
  }
  return gse;
}

}  // namespace openmss::user
