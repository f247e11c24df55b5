/* C-style COUPLER routines for tests/user/coupler_routine_test.cpp, loaded the way a user's
 * library is. With d the NJOINT joint displacements and PAR = r1, r2, r3, g [, tstop]:
 *   phi = r1 d1 + r2 d2 [+ r3 d3] + g d2^3
 * summed in that order, so that with g = 0 it is the operations of COUPLER's SCALES equation.
 * Couxx and Couxx2 give its exact first and second partials (column-major NJOINT x NJOINT).
 * Nan_cou: Cousub, but NaN from TIME >= PAR(4). Stop_cou: ERRMES STOP from TIME >= PAR(4). */
#include <math.h>

#include "user/openmss_usersub.h"

static double cubicOf(const struct sAdamsCoupler* c) { return c->NPAR > 3 ? c->PAR[3] : 0.0; }

void Cousub(const struct sAdamsCoupler* c, double time, double* disp, int iflag, double* phi) {
  double sum = 0.0;
  const double g = cubicOf(c);
  (void)time;
  (void)iflag;
  for (int k = 0; k < c->NJOINT; ++k) sum = sum + c->PAR[k] * disp[k];
  if (g != 0.0) sum = sum + g * disp[1] * disp[1] * disp[1];
  *phi = sum;
}

void Couxx(const struct sAdamsCoupler* c, double time, double* disp, int iflag, double* dfda) {
  (void)time;
  (void)iflag;
  for (int k = 0; k < c->NJOINT; ++k) dfda[k] = c->PAR[k];
  dfda[1] += 3.0 * cubicOf(c) * disp[1] * disp[1];
}

void Couxx2(const struct sAdamsCoupler* c, double time, double* disp, int iflag, double* d2) {
  const int n = c->NJOINT;
  (void)time;
  (void)iflag;
  for (int k = 0; k < n * n; ++k) d2[k] = 0.0;
  d2[1 + n * 1] = 6.0 * cubicOf(c) * disp[1];
}

void Nan_cou(const struct sAdamsCoupler* c, double time, double* disp, int iflag, double* phi) {
  Cousub(c, time, disp, iflag, phi);
  if (time >= c->PAR[4]) *phi = NAN;
}

void Stop_cou(const struct sAdamsCoupler* c, double time, double* disp, int iflag, double* phi) {
  Cousub(c, time, disp, iflag, phi);
  c_errmes(time >= c->PAR[4], "the coupler broke", c->ID, "STOP");
}
