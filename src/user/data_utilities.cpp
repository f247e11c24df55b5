// Data-access utilities user routines call: AKISPL, CUBSPL (SPLINE), GTCURV (CURVE), GTARAY
// (ARRAY), GTSTRG (STRING), GTUNTS (UNITS), GETMOD and GETINM (the analysis mode), in C (c_akispl,
// ...) and under their gfortran names. They read the model of the routine that is running
// (element_call.hpp); outside a routine, or for an id the model lacks, the error flag is set. The
// interpolation is the expression functions' own (common/spline.hpp, common/bspline_curve.hpp), so
// a routine and an expression agree.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <string>

#include "user/element_call.hpp"
#include "user/openmss_usersub.h"

namespace {

namespace d = openmss::user::detail;

void spline(openmss::SplineMethod method, double x, double z, int id, int iord, double* array,
            int* errflg) {
  *errflg = 1;
  array[0] = 0.0;
  const openmss::user::ModelData* m = d::elementModelData();
  if (!m || iord < 0 || iord > 2) return;
  auto it = m->splines.find(id);
  if (it == m->splines.end()) return;
  const openmss::SplinePartials p = it->second->evaluate(method, x, z, 0);
  // iord 0: y; 1: dy/dx, dy/dz; 2: d2y/dx2, d2y/dxdz, d2y/dz2 (docs/user-subroutines.md).
  if (iord == 0) {
    array[0] = p.g;
  } else if (iord == 1) {
    array[0] = p.gx;
    array[1] = p.gz;
  } else {
    array[0] = p.gxx;
    array[1] = p.gxz;
    array[2] = p.gzz;
  }
  *errflg = 0;
}

}  // namespace

void openmss::user::detail::anchorDataUtilities() {}

extern "C" {

void c_akispl(double xval, double zval, int id, int iord, double* array, int* errflg) {
  spline(openmss::SplineMethod::Akima, xval, zval, id, iord, array, errflg);
}

void c_cubspl(double xval, double zval, int id, int iord, double* array, int* errflg) {
  spline(openmss::SplineMethod::Cubic, xval, zval, id, iord, array, errflg);
}

void c_gtcurv(int id, double alpha, int iord, double* array, int* istat) {
  *istat = 1;
  const openmss::user::ModelData* m = d::elementModelData();
  if (!m || iord < 0 || iord > 2) return;
  auto it = m->curves.find(id);
  if (it == m->curves.end()) return;
  for (int c = 0; c < 3; ++c) {
    double v[openmss::BSplineCurve::kDerivatives];
    it->second->derivatives(alpha, c, v);
    array[c] = v[iord];
  }
  *istat = 0;
}

void c_gtaray(int id, double* array, int* number, int* istat) {
  *istat = 1;
  *number = 0;
  const openmss::user::ModelData* m = d::elementModelData();
  if (!m) return;
  auto it = m->arrays.find(id);
  if (it == m->arrays.end()) return;
  std::copy(it->second.begin(), it->second.end(), array);
  *number = static_cast<int>(it->second.size());
  *istat = 0;
}

void c_gtstrg(int id, char* string, int* nchars, int* istat) {
  *istat = 1;
  *nchars = 0;
  const openmss::user::ModelData* m = d::elementModelData();
  if (!m) return;
  auto it = m->strings.find(id);
  if (it == m->strings.end()) return;
  std::memcpy(string, it->second.c_str(), it->second.size() + 1);
  *nchars = static_cast<int>(it->second.size());
  *istat = 0;
}

// GTUNTS: exists, the SI value of one time, length, force and mass unit, and their symbols (3
// characters each, blank-padded, 12 in all; C: NUL-terminated, so 13 bytes). ADAMS's layout is
// not public (docs/user-subroutines.md gives OpenMSS's).
void c_gtunts(int* exists, double* scales, char* units) {
  const openmss::user::ModelData* m = d::elementModelData();
  *exists = m && m->unitsGiven ? 1 : 0;
  for (int k = 0; k < 4; ++k) scales[k] = m ? m->unitScales[static_cast<std::size_t>(k)] : 1.0;
  const std::string names = m ? m->unitNames : std::string(12, ' ');
  std::memcpy(units, names.c_str(), names.size() + 1);
}

// GETMOD: MODE, the analysis code (1 kinematics, 3 initial conditions, 4 dynamics, 5 statics,
// 6 quasi-statics, 7 linear), read like SYSFNC("MODE"): declare it in the dependency pass.
// 0 outside an evaluation subroutine.
void c_getmod(int* mode) {
  double m = 0.0;
  d::elementMode(&m);
  *mode = static_cast<int>(std::lround(m));
}

// GETINM: 1 during the initial-conditions analysis (MODE 3), else 0 (OpenMSS's reading of the
// name; ADAMS's text is not public).
void c_getinm(int* mode) {
  int m = 0;
  c_getmod(&m);
  *mode = m == 3 ? 1 : 0;
}

// ---- gfortran names ----------------------------------------------------------------------

void gtunts_(int* exists, double* scales, char* units, std::size_t lunits) {
  char text[13];
  c_gtunts(exists, scales, text);
  std::memset(units, ' ', lunits);
  std::memcpy(units, text, std::min<std::size_t>(lunits, 12));
}
void getmod_(int* mode) { c_getmod(mode); }
void getinm_(int* mode) { c_getinm(mode); }

void akispl_(const double* xval, const double* zval, const int* id, const int* iord, double* array,
             int* errflg) {
  c_akispl(*xval, *zval, *id, *iord, array, errflg);
}
void cubspl_(const double* xval, const double* zval, const int* id, const int* iord, double* array,
             int* errflg) {
  c_cubspl(*xval, *zval, *id, *iord, array, errflg);
}
void gtcurv_(const int* id, const double* alpha, const int* iord, double* array, int* istat) {
  c_gtcurv(*id, *alpha, *iord, array, istat);
}
void gtaray_(const int* id, double* array, int* number, int* istat) {
  c_gtaray(*id, array, number, istat);
}
// CHARACTER*(*) STRING: blank-padded to its declared length, truncated when longer.
void gtstrg_(const int* id, char* string, int* nchars, int* istat, std::size_t lstring) {
  *istat = 1;
  *nchars = 0;
  const openmss::user::ModelData* m = d::elementModelData();
  if (!m) return;
  auto it = m->strings.find(*id);
  if (it == m->strings.end()) return;
  const std::size_t n = std::min(lstring, it->second.size());
  std::memset(string, ' ', lstring);
  std::memcpy(string, it->second.data(), n);
  *nchars = static_cast<int>(n);
  *istat = 0;
}

}  // extern "C"
