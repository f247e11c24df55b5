/* User-written GSE routines for the tests (tests/user/gse_test.cpp), compiled into the shared
 * library openmss_test_gse against the C interface users compile against.
 *
 * Gse_deriv / Gse_output: the second-order linear system x'' + 2 zeta w x' + w^2 x = w^2 u
 * as x1' = x2, x2' = w^2 (u - x1) - 2 zeta w x2, y = x1, with PAR = (w, zeta, partials):
 * partials != 0 supplies the exact partials through SYSPAR when asked, 0 leaves them to the
 * solver's differences.
 *
 * Discrete_*: the sampled scalar system xd[k+1] = a xd[k] + b u, y = xd, PAR = (a, b[, T]);
 * Discrete_sample returns T.
 *
 * Failing_deriv: stops at initialization with ERRMES, as a routine that rejects its PAR does. */
#include "user/openmss_usersub.h"

void Gse_deriv(const struct sAdamsGSE* gse, double time, int dflag, int iflag, int ns,
               double* xdot) {
  double x[2] = {0.0, 0.0}, u[1] = {0.0};
  int n = 0, err = 0, wants = 0;
  const double w = gse->PAR[0], zeta = gse->PAR[1];
  (void)time;
  (void)dflag;
  c_sysary("ARRAY", &gse->X, 1, x, &n, &err);
  c_errmes(err || n != 2, "cannot read the X array", gse->ID, "STOP");
  c_sysary("ARRAY", &gse->U, 1, u, &n, &err);
  c_errmes(err || n != 1, "cannot read the U array", gse->ID, "STOP");
  if (iflag || ns != 2) return;
  xdot[0] = x[1];
  xdot[1] = w * w * (u[0] - x[0]) - 2.0 * zeta * w * x[1];
  c_adams_needs_partials(&wants);
  if (wants && gse->PAR[2] != 0.0) {
    const double a[4] = {0.0, -w * w, 1.0, -2.0 * zeta * w}; /* column-major 2 x 2 */
    const double b[2] = {0.0, w * w};
    c_syspar("ARRAY", &gse->X, 1, a, 4, &err);
    c_errmes(err, "SYSPAR of X refused", gse->ID, "STOP");
    c_syspar("ARRAY", &gse->U, 1, b, 2, &err);
    c_errmes(err, "SYSPAR of U refused", gse->ID, "STOP");
  }
}

void Gse_output(const struct sAdamsGSE* gse, double time, int dflag, int iflag, int no,
                double* y) {
  double x[2] = {0.0, 0.0};
  int err = 0, wants = 0;
  (void)time;
  (void)dflag;
  c_gse_x(x, c_gse_ns());
  if (iflag || no != 1) return;
  y[0] = x[0];
  c_adams_needs_partials(&wants);
  if (wants && gse->PAR[2] != 0.0) {
    const double c[2] = {1.0, 0.0};
    c_syspar("ARRAY", &gse->X, 1, c, 2, &err);
  }
}

void Discrete_update(const struct sAdamsGSE* gse, double time, int dflag, int iflag, int nd,
                     double* xd) {
  double now[1] = {0.0}, u = 0.0;
  int n = 0, err = 0;
  const int entry[2] = {gse->U, 1};
  (void)time;
  (void)dflag;
  c_sysary("ARRAY", &gse->XD, 1, now, &n, &err);
  c_sysfnc("ARYVAL", entry, 2, &u, &err);
  c_errmes(err, "cannot read the input", gse->ID, "STOP");
  if (iflag || nd != 1) return;
  xd[0] = gse->PAR[0] * now[0] + gse->PAR[1] * u;
}

void Discrete_output(const struct sAdamsGSE* gse, double time, int dflag, int iflag, int no,
                     double* y) {
  double xd[1] = {0.0};
  (void)gse;
  (void)time;
  (void)dflag;
  c_gse_xd(xd, 1);
  if (iflag || no != 1) return;
  y[0] = xd[0];
}

void Discrete_sample(const struct sAdamsGSE* gse, double time, int iflag, double* step) {
  (void)time;
  (void)iflag;
  *step = gse->PAR[2];
}

void Failing_deriv(const struct sAdamsGSE* gse, double time, int dflag, int iflag, int ns,
                   double* xdot) {
  (void)time;
  (void)dflag;
  (void)ns;
  (void)xdot;
  c_errmes(iflag && gse->PAR[0] < 0.0, "PAR(1) must not be negative", gse->ID, "STOP");
}

/* Stopping_output: y = x1 until TIME passes PAR(4), then ERRMES with STOP, as a routine does
 * when its model leaves the range it is valid for. */
void Stopping_output(const struct sAdamsGSE* gse, double time, int dflag, int iflag, int no,
                     double* y) {
  double x[2] = {0.0, 0.0};
  (void)dflag;
  c_gse_x(x, 2);
  if (iflag || no != 1) return;
  y[0] = x[0];
  c_errmes(time > gse->PAR[3], "the model left its range", gse->ID, "STOP");
}
