/* C-style evaluation subroutines for tests/user/element_routine_test.cpp, loaded the way a
 * user's library is. Each mirrors a function expression written in the test, operation for
 * operation, so that the two agree to the last bit:
 *   spring-damper  F = -k (DZ(i,j) - L) - c VZ(i,j)          PAR = k, c, L, i, j, partials
 *   variable       V = a DZ(i,j) + b TIME                    PAR = a, b, i, j, partials
 *   diff           y' = -a DIF(d) + VARVAL(v)                PAR = a, d, v, partials
 *   request        F2..F4 = DZ, VZ, VARVAL(v); F6..F8 = DIF(d), TIME, DZ VZ
 *   motion         s = A sin(w t)                            PAR = A, w
 * "partials" nonzero: the routine gives its partials through SYSPAR when asked. */
#include <math.h>
#include <stddef.h>

#include "user/openmss_usersub.h"

static double fnc(const char* name, int a, int b, int n) {
  int ipar[2] = {a, b}, err = 0;
  double v = 0.0;
  c_sysfnc(name, ipar, n, &v, &err);
  if (err) c_errmes(1, "SYSFNC failed", a, "STOP");
  return v;
}
static void par1(const char* name, int a, int b, int n, double dvalue) {
  int ipar[2] = {a, b}, err = 0;
  c_syspar(name, ipar, n, &dvalue, 1, &err);
}
static int wantPartials(int npar, const double* par, int at) {
  int need = 0;
  if (npar <= at || par[at] == 0.0) return 0;
  c_adams_needs_partials(&need);
  return need;
}

static double spring(int npar, const double* p, int* i, int* j) {
  *i = (int)p[3];
  *j = (int)p[4];
  const double dz = fnc("DZ", *i, *j, 2), vz = fnc("VZ", *i, *j, 2);
  if (wantPartials(npar, p, 5)) {
    par1("DZ", *i, *j, 2, -p[0]);
    par1("VZ", *i, *j, 2, -p[1]);
  }
  return -p[0] * (dz - p[2]) - p[1] * vz;
}

void Sfosub(const struct sAdamsSforce* s, double time, int dflag, int iflag, double* result) {
  int i, j;
  (void)time;
  (void)dflag;
  (void)iflag;
  *result = spring(s->NPAR, s->PAR, &i, &j);
}

void Gfosub(const struct sAdamsGforce* g, double time, int dflag, int iflag, double* result) {
  int i, j;
  (void)time;
  (void)dflag;
  (void)iflag;
  for (int k = 0; k < 6; ++k) result[k] = 0.0;
  result[2] = spring(g->NPAR, g->PAR, &i, &j);
}

void Vfosub(const struct sAdamsVforce* v, double time, int dflag, int iflag, double* result) {
  int i, j;
  (void)time;
  (void)dflag;
  (void)iflag;
  result[0] = 0.0;
  result[1] = 0.0;
  result[2] = spring(v->NPAR, v->PAR, &i, &j);
}

void Varsub(const struct sAdamsVariable* v, double time, int dflag, int iflag, double* result) {
  const double* p = v->PAR;
  const int i = (int)p[2], j = (int)p[3];
  const double dz = fnc("DZ", i, j, 2);
  (void)dflag;
  (void)iflag;
  if (wantPartials(v->NPAR, p, 4)) par1("DZ", i, j, 2, p[0]);
  *result = p[0] * dz + p[1] * time;
}

void Difsub(const struct sAdamsDiff* d, double time, int dflag, int iflag, double* result) {
  const double* p = d->PAR;
  const int id = (int)p[1], v = (int)p[2];
  const double y = fnc("DIF", id, 0, 1), w = fnc("VARVAL", v, 0, 1);
  (void)time;
  (void)dflag;
  (void)iflag;
  if (wantPartials(d->NPAR, p, 3)) {
    par1("DIF", id, 0, 1, -p[0]);
    par1("VARVAL", v, 0, 1, 1.0);
  }
  *result = -p[0] * y + w;
}

void Reqsub(const struct sAdamsRequest* r, double time, int iflag, double* out) {
  const double* p = r->PAR;
  const int i = (int)p[0], j = (int)p[1], v = (int)p[2], d = (int)p[3];
  const double dz = fnc("DZ", i, j, 2), vz = fnc("VZ", i, j, 2);
  (void)iflag;
  out[0] = 0.0;
  out[1] = dz;
  out[2] = vz;
  out[3] = fnc("VARVAL", v, 0, 1);
  out[4] = 0.0;
  out[5] = fnc("DIF", d, 0, 1);
  out[6] = time;
  out[7] = dz * vz;
}

void Motsub(const struct sAdamsMotion* m, double time, int iord, int iflag, double* result) {
  const double a = m->PAR[0], w = m->PAR[1];
  (void)iflag;
  *result = iord == 0 ? a * sin(w * time) : iord == 1 ? a * w * cos(w * time)
                                                      : -(a * w * w) * sin(w * time);
}

void Sensub(const struct sAdamsSensor* s, double time, int iflag, double* out) {
  (void)time;
  (void)iflag;
  *out = fnc("DZ", (int)s->PAR[0], (int)s->PAR[1], 2) - s->VALUE;
}

/* SYSARY("TDISP") and the utilities: F = IMPACT(DZ, VZ, x1, k, e, cmax, d) + STEP(TIME, 0, 0,
 * 1, h), PAR = i, j, x1, k, e, cmax, d, h, partials. */
void Impact_sfo(const struct sAdamsSforce* s, double time, int dflag, int iflag,
                double* result) {
  const double* p = s->PAR;
  int ipar[2] = {(int)p[0], (int)p[1]}, n = 0, err = 0;
  double disp[3], vel[3], imp[3], st = 0.0;
  (void)dflag;
  (void)iflag;
  c_sysary("TDISP", ipar, 2, disp, &n, &err);
  c_sysary("TVEL", ipar, 2, vel, &n, &err);
  c_impact(disp[2], vel[2], p[2], p[3], p[4], p[5], p[6], 0, imp, &err);
  c_step(time, 0.0, 0.0, 1.0, p[7], 0, &st, &err);
  if (wantPartials(s->NPAR, p, 8)) {
    const double dd[3] = {0.0, 0.0, imp[1]}, dv[3] = {0.0, 0.0, imp[2]};
    c_syspar("TDISP", ipar, 2, dd, 3, &err);
    c_syspar("TVEL", ipar, 2, dv, 3, &err);
  }
  *result = imp[0] + st;
}

/* Model data: AKISPL(TIME, 0, PAR[0]) + the sum of ARRAY/PAR[1] + the length of STRING/PAR[2]
 * + the x of CURVE/PAR[3] at alpha = 0.25 (PAR[3] = 0: no curve). */
void Data_var(const struct sAdamsVariable* v, double time, int dflag, int iflag,
              double* result) {
  double a[3] = {0.0, 0.0, 0.0}, values[16], c[3] = {0.0, 0.0, 0.0}, sum = 0.0;
  int err = 0, n = 0, nch = 0;
  char text[256];
  (void)dflag;
  (void)iflag;
  c_akispl(time, 0.0, (int)v->PAR[0], 0, a, &err);
  if (err) c_errmes(1, "AKISPL failed", v->ID, "STOP");
  c_gtaray((int)v->PAR[1], values, &n, &err);
  if (err) c_errmes(1, "GTARAY failed", v->ID, "STOP");
  for (int k = 0; k < n; ++k) sum += values[k];
  c_gtstrg((int)v->PAR[2], text, &nch, &err);
  if (err) c_errmes(1, "GTSTRG failed", v->ID, "STOP");
  if (v->PAR[3] != 0.0) c_gtcurv((int)v->PAR[3], 0.25, 0, c, &err);
  *result = a[0] + sum + (double)nch + c[0];
}

/* Bad user code, each from TIME >= PAR[0] on; until then the spring of PAR[1..]. */
void Nan_sfo(const struct sAdamsSforce* s, double time, int dflag, int iflag, double* result) {
  int i, j;
  (void)dflag;
  *result = spring(s->NPAR - 1, s->PAR + 1, &i, &j);
  if (!iflag && time >= s->PAR[0]) *result = NAN;
}
void Stop_sfo(const struct sAdamsSforce* s, double time, int dflag, int iflag, double* result) {
  int i, j;
  (void)dflag;
  *result = spring(s->NPAR - 1, s->PAR + 1, &i, &j);
  if (!iflag && time >= s->PAR[0]) c_errmes(1, "the spring broke", s->ID, "STOP");
}
/* Read through a pointer the compiler cannot see is null: a real SIGSEGV, not a trap. */
static double* volatile nowhere = NULL;
void Crash_sfo(const struct sAdamsSforce* s, double time, int dflag, int iflag,
               double* result) {
  int i, j;
  (void)dflag;
  *result = spring(s->NPAR - 1, s->PAR + 1, &i, &j);
  if (!iflag && time >= s->PAR[0]) *result = *nowhere;
}

/* VTORQUE: a torsional spring-damper about z, T_z = -k (AZ(i,j) - a0) - c WZ(i,j) (torque on I
 * in RM's axes), PAR = k, c, a0, i, j; the partials come from central differences. */
void Vtosub(const struct sAdamsVtorque* v, double time, int dflag, int iflag, double* result) {
  const double* p = v->PAR;
  const int i = (int)p[3], j = (int)p[4];
  (void)time;
  (void)dflag;
  (void)iflag;
  result[0] = 0.0;
  result[1] = 0.0;
  result[2] = -p[0] * (fnc("AZ", i, j, 2) - p[2]) - p[1] * fnc("WZ", i, j, 2);
}

/* USRMES from a REQSUB: one message printed (MSGFLG true) and one not (false); F3 = TIME. */
void Usrmes_req(const struct sAdamsRequest* r, double time, int iflag, double* out) {
  for (int k = 0; k < 8; ++k) out[k] = 0.0;
  out[1] = time;
  if (iflag != 0) return;
  c_usrmes(1, "C REQSUB says hello", r->ID, "INFO");
  c_usrmes(0, "never printed", r->ID, "INFO");
}
