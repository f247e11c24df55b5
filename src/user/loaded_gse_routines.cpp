#include "user/loaded_gse_routines.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <limits>

#include "common/ascii_case.hpp"
#include "user/element_call.hpp"
#include "user/gse_call.hpp"
#include "user/old_gse_routines.hpp"
#include "user/openmss_usersub.h"

namespace openmss::user {
namespace {

class LoadedGse;

// What the utility subroutines read while one routine of one GSE runs. Set around every call
// (thread-local: a routine evaluated on another thread sees its own element).
struct CallContext {
  const LoadedGse* gse = nullptr;
  const GseArguments* args = nullptr;
  bool initialization = false;      // IFLAG pass: SYSARY and friends return zeros
  int rows = 0;                     // number of values the running routine returns
  GsePartials* partials = nullptr;  // non-null: the routine may supply partials (SYSPAR)
};
thread_local CallContext* current = nullptr;

class ContextScope {
 public:
  explicit ContextScope(CallContext& c) : saved_(current) { current = &c; }
  ~ContextScope() { current = saved_; }
  ContextScope(const ContextScope&) = delete;
  ContextScope& operator=(const ContextScope&) = delete;

 private:
  CallContext* saved_;
};

class LoadedGse final : public GseRoutines {
 public:
  explicit LoadedGse(const GseDescription& d) : d_(d) {
    s_ = sAdamsGSE{};
    s_.ID = static_cast<int>(d_.id);
    s_.NPAR = static_cast<int>(d_.par.size());
    s_.PAR = d_.par.data();
    s_.NI = d_.ni;
    s_.NO = d_.no;
    s_.U = static_cast<int>(d_.uArray);
    s_.Y = static_cast<int>(d_.yArray);
    s_.NS = d_.ns;
    s_.X = static_cast<int>(d_.xArray);
    s_.IC = static_cast<int>(d_.icArray);
    s_.STATIC_HOLD = d_.staticHold ? 1 : 0;
    s_.ND = d_.nd;
    s_.XD = static_cast<int>(d_.xdArray);
    s_.ICD = static_cast<int>(d_.icdArray);
  }

  std::vector<std::shared_ptr<Library>> libraries;
  adams_c_GSE_DERIV* deriv = nullptr;
  adams_c_GSE_OUTPUT* output = nullptr;
  adams_c_GSE_UPDATE* updateRoutine = nullptr;
  adams_c_GSE_SAMP* sample = nullptr;

  const GseDescription& description() const { return d_; }

  void derivatives(const GseArguments& a, double* xdot, GsePartials* partials) const override {
    run(a, d_.ns, partials, false, xdot,
        [&](int iflag) { deriv(&s_, a.time, a.perturbed ? 1 : 0, iflag, d_.ns, xdot); });
  }
  void outputs(const GseArguments& a, double* y, GsePartials* partials) const override {
    run(a, d_.no, partials, false, y,
        [&](int iflag) { output(&s_, a.time, a.perturbed ? 1 : 0, iflag, d_.no, y); });
  }
  bool hasUpdate() const override { return updateRoutine != nullptr; }
  void update(const GseArguments& a, double* xdNext) const override {
    run(a, d_.nd, nullptr, false, xdNext,
        [&](int iflag) { updateRoutine(&s_, a.time, 0, iflag, d_.nd, xdNext); });
  }
  std::optional<double> sampleStep(double time) const override {
    if (!sample) return std::nullopt;
    double step = 0.0;
    const std::vector<double> zeros(static_cast<size_t>(std::max({d_.ns, d_.nd, d_.ni, 1})), 0.0);
    GseArguments a{time, zeros.data(), zeros.data(), zeros.data(), false};
    run(a, 1, nullptr, false, &step, [&](int iflag) { sample(&s_, time, iflag, &step); });
    return step;
  }
  std::string fatalError() const override { return fatal_; }

  // ADAMS's first call of every routine (IFLAG = 1): initialization and declaration of what
  // it reads; the values it returns are ignored.
  std::string initialize() const {
    const size_t n = static_cast<size_t>(std::max({d_.ns, d_.nd, d_.ni, d_.no, 1}));
    std::vector<double> zeros(n, 0.0), out(n, 0.0);
    GseArguments a{0.0, zeros.data(), zeros.data(), zeros.data(), false};
    if (deriv)
      run(a, d_.ns, nullptr, true, out.data(),
          [&](int f) { deriv(&s_, 0.0, 0, f, d_.ns, out.data()); });
    if (output)
      run(a, d_.no, nullptr, true, out.data(),
          [&](int f) { output(&s_, 0.0, 0, f, d_.no, out.data()); });
    if (updateRoutine)
      run(a, d_.nd, nullptr, true, out.data(),
          [&](int f) { updateRoutine(&s_, 0.0, 0, f, d_.nd, out.data()); });
    if (sample)
      run(a, 1, nullptr, true, out.data(), [&](int f) { sample(&s_, 0.0, f, out.data()); });
    return fatal_;
  }

  // The values of ARRAY/id as the running routine may read them (null: not readable).
  const double* arrayValues(long id, int& size, bool& zeros) const {
    const GseArguments& a = *current->args;
    // The element's own arrays: zeros in the initialization pass, as ADAMS's SYSARY gives.
    zeros = current->initialization;
    const struct {
      long id;
      int size;
      const double* values;
    } own[] = {{d_.xArray, d_.ns, a.x}, {d_.xdArray, d_.nd, a.xd}, {d_.uArray, d_.ni, a.u}};
    for (const auto& o : own)
      if (o.id == id && o.size > 0) {
        size = o.size;
        return o.values;
      }
    zeros = false;
    for (const auto& [arrayId, numbers] : d_.constantArrays)
      if (arrayId == id) return size = static_cast<int>(numbers.size()), numbers.data();
    size = 0;
    return nullptr;
  }

  void fatal(const std::string& text) const {
    if (fatal_.empty()) fatal_ = text;
  }

 private:
  template <class Call>
  void run(const GseArguments& a, int rows, GsePartials* partials, bool initialization, double* out,
           const Call& call) const {
    CallContext c{this, &a, initialization, rows, partials};
    {
      ContextScope scope(c);
      call(initialization ? 1 : 0);
    }
    if (fatal_.empty() || initialization) return;
    // A routine that stopped the run: no trustworthy value, so none at all. The integrator
    // fails on the NaN and names this GSE's equation; the message says why, once.
    std::fill(out, out + rows, std::numeric_limits<double>::quiet_NaN());
    if (!fatalShown_) {
      std::fprintf(stderr, "openmss: %s\n", fatal_.c_str());
      fatalShown_ = true;
    }
  }

  GseDescription d_;
  sAdamsGSE s_;
  mutable std::string fatal_;
  mutable bool fatalShown_ = false;
};

}  // namespace

std::shared_ptr<const GseRoutines> loadGseRoutines(const GseDescription& description,
                                                   const GseRoutineNames& names,
                                                   const std::string& baseDirectory,
                                                   std::vector<std::string>& errors) {
  detail::anchorUtilities();
  // The old interface (GSESUB, GSEXX, ...) when ROUTINE names a library, or the default one,
  // that has GSESUB and none of the new routines (docs/user-subroutines.md).
  if (names.deriv.name.empty() && names.output.name.empty() &&
      names.deriv.library == names.output.library &&
      prefersOldGseInterface(names.deriv.library, baseDirectory))
    return loadOldGseRoutines(description, names.deriv.library, baseDirectory, errors);
  auto gse = std::make_shared<LoadedGse>(description);
  const size_t errorsBefore = errors.size();
  std::vector<std::pair<std::string, std::shared_ptr<Library>>> opened;
  bool noLibraryReported = false;
  auto library = [&](const RoutineName& r) -> std::shared_ptr<Library> {
    const std::string name = r.library.empty() ? defaultLibrary() : r.library;
    if (name.empty()) {
      if (noLibraryReported) return nullptr;  // once per statement, not once per routine
      noLibraryReported = true;
      errors.push_back(
          "no user library: the GSE names none (INTERFACE=lib::name or "
          "ROUTINE=lib::) and no default library was given (openmss run "
          "--user-library PATH)");
      return nullptr;
    }
    for (const auto& [n, lib] : opened)
      if (n == name) return lib;
    std::string why;
    std::shared_ptr<Library> lib = Library::open(name, baseDirectory, why);
    if (!lib) errors.push_back("cannot load user library " + name + ": " + why);
    opened.push_back({name, lib});
    if (lib) gse->libraries.push_back(lib);
    return lib;
  };
  // One routine: its C-style name (or the INTERFACE name) from its library. A FORTRAN-style
  // export of the same routine gets its own explanation: its argument list differs.
  auto find = [&](const RoutineName& r, const std::vector<std::string>& defaults,
                  bool required) -> void* {
    // An optional routine (GSE_SAMP) is looked for only where a library is named.
    if (!required && r.library.empty() && defaultLibrary().empty()) return nullptr;
    std::shared_ptr<Library> lib = library(r);
    if (!lib) return nullptr;
    const std::vector<std::string> tried = r.name.empty() ? defaults : std::vector{r.name};
    for (const std::string& n : tried)
      if (void* p = lib->symbol(n)) return p;
    if (!required) return nullptr;
    std::string fortran;
    for (const std::string& n :
         {toUpperAscii(tried[0]), toLowerAscii(tried[0]), toLowerAscii(tried[0]) + "_"})
      if (lib->symbol(n)) fortran = n;
    errors.push_back("user library " + lib->path() + " exports no routine " + tried[0] +
                     (fortran.empty() ? std::string()
                                      : " (it has " + fortran +
                                            ", a FORTRAN-style routine; OpenMSS calls GSE "
                                            "routines with the C-style argument list only)"));
    return nullptr;
  };
  const GseDescription& d = description;
  if (d.ns > 0) gse->deriv = asFunction<adams_c_GSE_DERIV>(find(names.deriv, {"Gse_deriv"}, true));
  if (d.no > 0)
    gse->output = asFunction<adams_c_GSE_OUTPUT>(find(names.output, {"Gse_output"}, true));
  if (d.nd > 0) {
    gse->updateRoutine = asFunction<adams_c_GSE_UPDATE>(find(names.update, {"Gse_update"}, true));
    gse->sample = asFunction<adams_c_GSE_SAMP>(
        find(names.sample, {"Gse_sample", "Gse_samp"}, !names.sample.name.empty()));
  }
  if (errors.size() > errorsBefore) return nullptr;
  const std::string fatal = gse->initialize();
  if (!fatal.empty()) {
    errors.push_back("its routines stopped during initialization (IFLAG = 1): " + fatal);
    return nullptr;
  }
  return gse;
}

}  // namespace openmss::user

// ---- The utility subroutines as a GSE routine sees them --------------------------------
// utility_subroutines.cpp exports c_sysary & co. and hands a call here while a GSE routine
// runs (gse_call.hpp).

namespace openmss::user::detail {

bool gseCallActive() { return current != nullptr; }

void gseSysary(const char* fncnam, const int* ipar, int nsize, double* states, int* nstates,
               int* errflg) {
  *errflg = 1;
  *nstates = 0;
  if (!current || !fncnam || toUpperAscii(fncnam) != "ARRAY" || nsize < 1) return;
  int size = 0;
  bool zeros = false;
  const double* v = current->gse->arrayValues(ipar[0], size, zeros);
  if (!v) return;
  for (int k = 0; k < size; ++k) states[k] = zeros ? 0.0 : v[k];
  *nstates = size;
  *errflg = 0;
}

void gseSysfnc(const char* fncnam, const int* ipar, int nsize, double* state, int* errflg) {
  *errflg = 1;
  *state = 0.0;
  if (!current || !fncnam || toUpperAscii(fncnam) != "ARYVAL" || nsize < 2) return;
  int size = 0;
  bool zeros = false;
  const double* v = current->gse->arrayValues(ipar[0], size, zeros);
  if (!v || ipar[1] < 1 || ipar[1] > size) return;
  *state = zeros ? 0.0 : v[ipar[1] - 1];
  *errflg = 0;
}

void gseSyspar(const char* fncnam, const int* ipar, int nsize, const double* partials, int npartl,
               int* errflg) {
  *errflg = 1;
  if (!current || !current->partials || !fncnam || toUpperAscii(fncnam) != "ARRAY" || nsize < 1)
    return;
  const GseDescription& d = current->gse->description();
  const int rows = current->rows;
  std::optional<std::vector<double>>* block = nullptr;
  int cols = 0;
  if (ipar[0] == d.xArray && d.ns > 0) {
    block = &current->partials->dx;
    cols = d.ns;
  } else if (ipar[0] == d.uArray && d.ni > 0) {
    block = &current->partials->du;
    cols = d.ni;
  }
  if (!block || npartl != rows * cols) return;
  *block = std::vector<double>(partials, partials + npartl);
  *errflg = 0;
}

void gseNeedsPartials(int* eval_jac) {
  *eval_jac = current && current->partials && !current->initialization ? 1 : 0;
}

int gseNs() { return current ? current->gse->description().ns : 0; }
int gseNd() { return current ? current->gse->description().nd : 0; }
int gseNi() { return current ? current->gse->description().ni : 0; }
int gseNo() { return current ? current->gse->description().no : 0; }

void copyArray(long id, double* out, int n) {
  if (!current) return;
  int size = 0;
  bool zeros = false;
  const double* v = current->gse->arrayValues(id, size, zeros);
  for (int k = 0; k < n && k < size && v; ++k) out[k] = zeros ? 0.0 : v[k];
}
void gseX(double* x, int ns) {
  if (current) copyArray(current->gse->description().xArray, x, ns);
}
void gseXd(double* xd, int nd) {
  if (current) copyArray(current->gse->description().xdArray, xd, nd);
}
void gseU(double* u, int ni) {
  if (current) copyArray(current->gse->description().uArray, u, ni);
}

void gseTimget(double* time) { *time = current ? current->args->time : 0.0; }

void gseErrmes(int errflg, const char* mesage, int id, const char* endflg) {
  if (!errflg) return;
  const std::string end = endflg ? toUpperAscii(endflg) : "";
  const std::string text = std::string("ERRMES from the routine of GSE/") + std::to_string(id) +
                           ": " + (mesage ? mesage : "");
  if (current && (end.rfind("STOP", 0) == 0 || end.rfind("ERROR", 0) == 0)) {
    current->gse->fatal(text);
    return;
  }
  std::fprintf(stderr, "openmss: %s\n", text.c_str());
}

}  // namespace openmss::user::detail
