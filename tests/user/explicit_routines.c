/* C-style routines with explicit arguments for tests/user/field_routine_test.cpp and
 * curve_routine_test.cpp, loaded the way a user's library is.
 *
 * Fiesub: the linear FIELD law, operation for operation as the solver evaluates a FIELD with
 * KMATRIX/CMATRIX/LENGTH/FORCE (so that the two agree to the last bit), plus a cubic term:
 *   field(r) = F(r) - sum_c K(r,c) (disp(c) - L(c)) - sum_c C(r,c) velo(c) - g disp(r)^3
 *   K(r,c) = PAR(r) on the diagonal, PAR(6) off it; C(r,c) = PAR(7+r), PAR(13) off it;
 *   L = PAR(14..19), F = PAR(20..25), PAR(26) nonzero: partials given when DFLAG is set;
 *   g = PAR(27) (0 for the comparison with the matrix FIELD). PAR counts from 0 here.
 * Nan_fie: Fiesub, but NaN from TIME >= PAR(28). Stop_fie: ERRMES STOP from TIME >= PAR(28). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "user/openmss_usersub.h"

static double kOf(const double* p, int r, int c) { return r == c ? p[r] : p[6]; }
static double cOf(const double* p, int r, int c) { return r == c ? p[7 + r] : p[13]; }

static void field(const double* p, int npar, const double* d, const double* v, int dflag,
                  double* f, double* kd, double* cd) {
  const double g = npar > 27 ? p[27] : 0.0;
  for (int r = 0; r < 6; ++r) {
    double sum = p[20 + r];
    for (int c = 0; c < 6; ++c) {
      if (kOf(p, r, c) != 0.0) sum = sum - kOf(p, r, c) * (d[c] - p[14 + c]);
      if (cOf(p, r, c) != 0.0) sum = sum - cOf(p, r, c) * v[c];
    }
    if (g != 0.0) sum = sum - g * d[r] * d[r] * d[r];
    f[r] = sum;
  }
  if (!dflag || p[26] == 0.0) return; /* no partials: the solver differences */
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 6; ++c) {
      kd[r + 6 * c] = -kOf(p, r, c) - (r == c ? 3.0 * g * d[r] * d[r] : 0.0);
      cd[r + 6 * c] = -cOf(p, r, c);
    }
}

void Fiesub(const struct sAdamsField* f, double time, double* disp, double* velo, int dflag,
            int iflag, double* result, double* dfddis, double* dfdvel) {
  (void)time;
  (void)iflag;
  field(f->PAR, f->NPAR, disp, velo, dflag, result, dfddis, dfdvel);
}

void Nan_fie(const struct sAdamsField* f, double time, double* disp, double* velo, int dflag,
             int iflag, double* result, double* dfddis, double* dfdvel) {
  (void)iflag;
  field(f->PAR, f->NPAR, disp, velo, dflag, result, dfddis, dfdvel);
  if (time >= f->PAR[28]) result[1] = NAN;
}

void Stop_fie(const struct sAdamsField* f, double time, double* disp, double* velo, int dflag,
              int iflag, double* result, double* dfddis, double* dfdvel) {
  (void)iflag;
  field(f->PAR, f->NPAR, disp, velo, dflag, result, dfddis, dfdvel);
  c_errmes(time >= f->PAR[28], "the field broke", f->ID, "STOP");
}

/* Units_var: the model-query utilities, PAR(0) selecting the value: 0..3 GTUNTS's scales
 * (time, length, force, mass), 4 its exists flag, 5 GETMOD, 6 GETINM, 7 the character code of
 * GTUNTS's units[PAR(1)], 8 whether units[12] ends the text. GETMOD is called in every pass
 * (it is declared like a SYSFNC). */
void Units_var(const struct sAdamsVariable* v, double time, int dflag, int iflag,
               double* result) {
  int exists = 0, mode = 0, inm = 0;
  double scales[4] = {0.0, 0.0, 0.0, 0.0};
  char units[13];
  const int what = (int)v->PAR[0];
  (void)time;
  (void)dflag;
  (void)iflag;
  c_gtunts(&exists, scales, units);
  c_getmod(&mode);
  c_getinm(&inm);
  if (what < 4) *result = scales[what];
  else if (what == 4) *result = exists;
  else if (what == 5) *result = mode;
  else if (what == 6) *result = inm;
  else if (what == 7) *result = (unsigned char)units[(int)v->PAR[1] % 12];
  else *result = units[12] == '\0';
}

/* Cursub: a circle of radius PAR(0) about the origin in the x-y plane, alpha the angle from
 * the bottom (0, -R, 0) towards +x: (R sin a, -R cos a, 0) and its derivatives in alpha. */
static void circle(double r, double a, int iord, double* v) {
  const double s = sin(a), c = cos(a);
  v[2] = 0.0;
  if (iord == 0) {
    v[0] = r * s;
    v[1] = -r * c;
  } else if (iord == 1) {
    v[0] = r * c;
    v[1] = r * s;
  } else {
    v[0] = -r * s;
    v[1] = r * c;
  }
}
void Cursub(const struct sAdamsCurve* c, double alpha, int iord, int iflag, double* values) {
  (void)iflag;
  circle(c->PAR[0], alpha, iord, values);
}
/* Nan_cur: the circle, NaN beyond alpha = PAR(1). */
void Nan_cur(const struct sAdamsCurve* c, double alpha, int iord, int iflag, double* values) {
  (void)iflag;
  circle(c->PAR[0], alpha, iord, values);
  if (alpha > c->PAR[1]) values[0] = NAN;
}

/* Spline_read: "x y" pairs, one a line, from FILENAME; BLOCK=DOUBLE doubles every y. */
void Spline_read(const struct sAdamsSpline* s, int* ierr) {
  double x[100], y[100], z[1] = {0.0}, scale = 1.0;
  int n = 0, err = 0;
  FILE* f = fopen(s->FILENAME, "r");
  *ierr = 1;
  if (!f) return;
  if (s->BLOCKNAME && strcmp(s->BLOCKNAME, "DOUBLE") == 0) scale = 2.0;
  while (n < 100 && fscanf(f, "%lf %lf", &x[n], &y[n]) == 2) {
    y[n] *= scale;
    ++n;
  }
  fclose(f);
  c_put_spline(s->ID, n, 1, x, y, z, &err);
  *ierr = err;
}

/* The old GSE interface: x1' = x2, x2' = w^2 (u - x1) - 2 zeta w x2, y = x1 (PAR = w, zeta),
 * the system of gse_test_routines.c, with its exact partials (column-major). */
void Gsesub(const struct sAdamsGSE* g, double time, int dflag, int iflag, int ns,
            const double* x, int ni, const double* u, int no, double* xdot, double* y) {
  const double w = g->PAR[0], zeta = g->PAR[1];
  (void)time;
  (void)dflag;
  (void)iflag;
  if (ns != 2 || ni != 1 || no != 1) {
    c_errmes(1, "GSESUB needs NS=2, NI=1, NO=1", g->ID, "STOP");
    return;
  }
  xdot[0] = x[1];
  xdot[1] = w * w * (u[0] - x[0]) - 2.0 * zeta * w * x[1];
  y[0] = x[0];
}
void Gsexx(const struct sAdamsGSE* g, double time, int iflag, int ns, const double* x, int ni,
           const double* u, int no, double* d) {
  const double w = g->PAR[0], zeta = g->PAR[1];
  (void)time, (void)iflag, (void)ns, (void)x, (void)ni, (void)u, (void)no;
  d[0] = 0.0;
  d[1] = -w * w;
  d[2] = 1.0;
  d[3] = -2.0 * zeta * w;
}
void Gsexu(const struct sAdamsGSE* g, double time, int iflag, int ns, const double* x, int ni,
           const double* u, int no, double* d) {
  (void)time, (void)iflag, (void)ns, (void)x, (void)ni, (void)u, (void)no;
  d[0] = 0.0;
  d[1] = g->PAR[0] * g->PAR[0];
}
void Gseyx(const struct sAdamsGSE* g, double time, int iflag, int ns, const double* x, int ni,
           const double* u, int no, double* d) {
  (void)g, (void)time, (void)iflag, (void)ns, (void)x, (void)ni, (void)u, (void)no;
  d[0] = 1.0;
  d[1] = 0.0;
}
void Gseyu(const struct sAdamsGSE* g, double time, int iflag, int ns, const double* x, int ni,
           const double* u, int no, double* d) {
  (void)g, (void)time, (void)iflag, (void)ns, (void)x, (void)ni, (void)u, (void)no;
  d[0] = 0.0;
}
