// The utility subroutines user routines call (user/openmss_usersub.h), exported from the
// program (ENABLE_EXPORTS) so that a user library resolves them at load: the C names
// (c_sysfnc, ...) and the gfortran names of the FORTRAN-77 ones (sysfnc_, ...: every argument
// by reference, each CHARACTER argument's length appended as a size_t, in order). Each one
// serves the routine running on this thread: a GSE routine (gse_call.hpp) or an element's
// evaluation subroutine (element_call.hpp).

#include <cctype>
#include <cstddef>
#include <cstdio>
#include <string>

#include "common/ascii_case.hpp"
#include "user/control_routine.hpp"
#include "user/element_call.hpp"
#include "user/gse_call.hpp"
#include "user/openmss_usersub.h"

namespace {

namespace d = openmss::user::detail;
using openmss::toUpperAscii;

// A FORTRAN CHARACTER argument: `length` characters, blank-padded, no terminator.
std::string fortranText(const char* text, std::size_t length) {
  if (!text) return {};
  std::string s(text, length);
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}
std::string trimmedUpper(const char* text) {
  std::string s = text ? toUpperAscii(text) : "";
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// ERRMES's end flag: STOP (MSC's examples), ERROR (its GSE examples), ABORT and FATAL stop
// the run; anything else only prints (docs/user-subroutines.md, "Errors").
bool stops(const std::string& endflg) {
  for (const char* word : {"STOP", "ERROR", "ABORT", "FATAL"})
    if (endflg.rfind(word, 0) == 0) return true;
  return false;
}

void errmes(int errflg, const std::string& message, int id, const std::string& endflg) {
  if (!errflg) return;
  if (d::gseCallActive()) {
    d::gseErrmes(errflg, message.c_str(), id, endflg.c_str());
    return;
  }
  const std::string text = "ERRMES (id " + std::to_string(id) + "): " + message;
  if (d::elementCallActive() && stops(toUpperAscii(endflg))) {
    d::elementFatal(text);
    return;
  }
  if (openmss::user::detail::controlCallActive() && stops(toUpperAscii(endflg))) {
    openmss::user::detail::controlFatal("CONSUB: " + text);  // control_routine.hpp
    return;
  }
  std::fprintf(stderr, "openmss: %s%s%s\n", d::elementCallActive() ? d::elementWho().c_str() : "",
               d::elementCallActive() ? ": " : "", text.c_str());
}

void usrmes(int msgflg, const std::string& message, int id, const std::string& msgtyp) {
  if (!msgflg) return;
  std::fprintf(stderr, "openmss: USRMES %s (id %d): %s\n", msgtyp.c_str(), id, message.c_str());
}

void sysfnc(const std::string& name, const int* ipar, int nsize, double* state, int* errflg) {
  *state = 0.0;
  *errflg = d::elementCallActive() && d::elementSysfnc(name, ipar, nsize, state) ? 0 : 1;
}

void sysary(const std::string& name, const int* ipar, int nsize, double* states, int* nstates,
            int* errflg) {
  *nstates = 0;
  *errflg = d::elementCallActive() && d::elementSysary(name, ipar, nsize, states, nstates) ? 0 : 1;
}

// ANALYS, DATOUT, MODIFY: ADAMS allows them only inside CONSUB (the CONTROL command; they
// reach the session through control_routine.hpp); from any other routine, or while an element
// routine runs inside an analysis CONSUB started, they do nothing and fail, saying so once per
// utility (docs/user-subroutines.md, "CONSUB").
void controlOnly(const char* name, int* istat) {
  *istat = 1;
  static thread_local std::string said;
  if (said.find(name) != std::string::npos) return;
  said += name;
  std::fprintf(stderr,
               "openmss: %s%s%s may be called only from CONSUB (the CONTROL command); it did "
               "nothing and returned istat = 1\n",
               d::elementCallActive() ? d::elementWho().c_str() : "",
               d::elementCallActive() ? ": " : "", name);
}

// CONSUB runs on this thread and no element or GSE routine of an analysis it started does.
bool inConsub() { return d::controlCallActive() && !d::elementCallActive() && !d::gseCallActive(); }

}  // namespace

void openmss::user::detail::anchorUtilitySubroutines() {}

extern "C" {

void c_sysary(const char* fncnam, const int* ipar, int nsize, double* states, int* nstates,
              int* errflg) {
  if (d::gseCallActive()) return d::gseSysary(fncnam, ipar, nsize, states, nstates, errflg);
  sysary(trimmedUpper(fncnam), ipar, nsize, states, nstates, errflg);
}

void c_sysfnc(const char* fncnam, const int* ipar, int nsize, double* state, int* errflg) {
  if (d::gseCallActive()) return d::gseSysfnc(fncnam, ipar, nsize, state, errflg);
  sysfnc(trimmedUpper(fncnam), ipar, nsize, state, errflg);
}

void c_syspar(const char* fncnam, const int* ipar, int nsize, const double* partials, int npartl,
              int* errflg) {
  if (d::gseCallActive()) return d::gseSyspar(fncnam, ipar, nsize, partials, npartl, errflg);
  *errflg = d::elementSyspar(trimmedUpper(fncnam), ipar, nsize, partials, npartl) ? 0 : 1;
}

void c_adams_needs_partials(int* eval_jac) {
  if (d::gseCallActive()) return d::gseNeedsPartials(eval_jac);
  *eval_jac = d::elementNeedsPartials() ? 1 : 0;
}

int c_gse_ns(void) { return d::gseNs(); }
int c_gse_nd(void) { return d::gseNd(); }
int c_gse_ni(void) { return d::gseNi(); }
int c_gse_no(void) { return d::gseNo(); }
void c_gse_x(double* x, int ns) { d::gseX(x, ns); }
void c_gse_xd(double* xd, int nd) { d::gseXd(xd, nd); }
void c_gse_u(double* u, int ni) { d::gseU(u, ni); }

void c_timget(double* time) {
  if (d::gseCallActive()) return d::gseTimget(time);
  *time = d::elementTime();
}

// TIMEGT: the older spelling of TIMGET, the same value (docs/user-subroutines.md).
void c_timegt(double* time) { c_timget(time); }

void c_analys(const char* antype, const char* cid, double timbeg, double timend, int init,
              int* istat) {
  if (!inConsub()) return controlOnly("ANALYS", istat);
  d::controlAnalys(trimmedUpper(antype), cid ? cid : "", timbeg, timend, init, istat);
}
void c_datout(int* istat) {
  if (!inConsub()) return controlOnly("DATOUT", istat);
  d::controlDatout(istat);
}
void c_modify(const char* comand, int* istat) {
  if (!inConsub()) return controlOnly("MODIFY", istat);
  d::controlModify(comand ? comand : "", istat);
}

void c_errmes(int errflg, const char* mesage, int id, const char* endflg) {
  errmes(errflg, mesage ? mesage : "", id, endflg ? endflg : "");
}

void c_usrmes(int msgflg, const char* mesage, int id, const char* msgtyp) {
  usrmes(msgflg, mesage ? mesage : "", id, msgtyp ? msgtyp : "");
}

// ---- gfortran names ----------------------------------------------------------------------

void sysfnc_(const char* fncnam, const int* ipar, const int* nsize, double* state, int* errflg,
             std::size_t lfncnam) {
  sysfnc(toUpperAscii(fortranText(fncnam, lfncnam)), ipar, *nsize, state, errflg);
}

void sysary_(const char* fncnam, const int* ipar, const int* nsize, double* states, int* nstates,
             int* errflg, std::size_t lfncnam) {
  sysary(toUpperAscii(fortranText(fncnam, lfncnam)), ipar, *nsize, states, nstates, errflg);
}

void syspar_(const char* fncnam, const int* ipar, const int* nsize, const double* partials,
             const int* npartl, int* errflg, std::size_t lfncnam) {
  *errflg =
      d::elementSyspar(toUpperAscii(fortranText(fncnam, lfncnam)), ipar, *nsize, partials, *npartl)
          ? 0
          : 1;
}

void adams_needs_partials_(int* eval_jac) { c_adams_needs_partials(eval_jac); }

void timget_(double* time) { c_timget(time); }
void timegt_(double* time) { c_timget(time); }

void analys_(const char* antype, const char* cid, const double* timbeg, const double* timend,
             const int* init, int* istat, std::size_t lantype, std::size_t lcid) {
  if (!inConsub()) return controlOnly("ANALYS", istat);
  d::controlAnalys(toUpperAscii(fortranText(antype, lantype)), fortranText(cid, lcid), *timbeg,
                   *timend, *init, istat);
}
void datout_(int* istat) { c_datout(istat); }
void modify_(const char* comand, int* istat, std::size_t lcomand) {
  if (!inConsub()) return controlOnly("MODIFY", istat);
  d::controlModify(fortranText(comand, lcomand), istat);
}

void errmes_(const int* errflg, const char* mesage, const int* id, const char* endflg,
             std::size_t lmesage, std::size_t lendflg) {
  errmes(*errflg, fortranText(mesage, lmesage), *id, fortranText(endflg, lendflg));
}

void usrmes_(const int* msgflg, const char* mesage, const int* id, const char* msgtyp,
             std::size_t lmesage, std::size_t lmsgtyp) {
  usrmes(*msgflg, fortranText(mesage, lmesage), *id, fortranText(msgtyp, lmsgtyp));
}

}  // extern "C"
