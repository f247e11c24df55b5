/* C-style UCON routines for tests/user/ucon_routine_test.cpp, loaded the way a user's library
 * is. PAR(1) selects the constraint F(q) = 0 (PAR[0] here), PAR(2) is part A, then:
 *   1: F = z_A - PAR(3)                      (variables: A 13; the JPRIM INPLANE of a CM)
 *   2: F = |r_A - (PAR(3), PAR(4), PAR(5))| - PAR(6)  (A 11, 12, 13; GCON DM - L)
 *   3: F = (z axis of A) . (z axis of B), B = PAR(3)  (A 311..313, B 311..313; JPRIM
 *      PERPENDICULAR between the CM markers)
 * Ucosub returns F, dF/dq and d2F/dq2 (30 x 30, column-major) as IDRSEL asks.
 * Nan_ucon: Ucosub, but NaN from TIME >= PAR(NPAR). Stop_ucon: ERRMES STOP from TIME >=
 * PAR(NPAR). Novar_ucon never calls UCOVAR. Angle_ucon declares code 14 (not supported).
 * Time_ucon depends on TIME (refused). */
#include <math.h>

#include "user/openmss_usersub.h"

#define X(m, n) xmatrx[(m) + 30 * (n)]

static void declare(const struct sAdamsUcon* u) {
  const int a = (int)u->PAR[1];
  const int mode = (int)u->PAR[0];
  if (mode == 1) {
    const int parts[1] = {a}, codes[1] = {13};
    c_ucovar(u->ID, 1, parts, 1, codes);
  } else if (mode == 2) {
    const int parts[3] = {a, a, a}, codes[3] = {11, 12, 13};
    c_ucovar(u->ID, 3, parts, 3, codes);
  } else {
    const int b = (int)u->PAR[2];
    const int parts[6] = {a, a, a, b, b, b}, codes[6] = {311, 312, 313, 311, 312, 313};
    c_ucovar(u->ID, 6, parts, 6, codes);
  }
}

void Ucosub(const struct sAdamsUcon* u, double time, const double* q, const int* idrsel,
            int iflag, double* scalar, double* array, double* xmatrx) {
  const double* p = u->PAR;
  (void)time;
  if (iflag == 3) declare(u);
  if (iflag != 0) return;
  if (p[0] == 1.0) {
    if (idrsel[0]) *scalar = q[0] - p[2];
    if (idrsel[1]) array[0] = 1.0;
  } else if (p[0] == 2.0) {
    const double d[3] = {q[0] - p[2], q[1] - p[3], q[2] - p[4]};
    const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (idrsel[0]) *scalar = r - p[5];
    if (idrsel[1])
      for (int k = 0; k < 3; ++k) array[k] = d[k] / r;
    if (idrsel[2])
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) X(k, l) = ((k == l ? 1.0 : 0.0) - d[k] * d[l] / (r * r)) / r;
  } else {
    if (idrsel[0]) *scalar = q[0] * q[3] + q[1] * q[4] + q[2] * q[5];
    if (idrsel[1])
      for (int k = 0; k < 3; ++k) {
        array[k] = q[k + 3];
        array[k + 3] = q[k];
      }
    if (idrsel[2])
      for (int k = 0; k < 3; ++k) X(k, k + 3) = X(k + 3, k) = 1.0;
  }
}

void Nan_ucon(const struct sAdamsUcon* u, double time, const double* q, const int* idrsel,
              int iflag, double* scalar, double* array, double* xmatrx) {
  Ucosub(u, time, q, idrsel, iflag, scalar, array, xmatrx);
  if (iflag == 0 && time >= u->PAR[u->NPAR - 1]) *scalar = NAN;
}

void Stop_ucon(const struct sAdamsUcon* u, double time, const double* q, const int* idrsel,
               int iflag, double* scalar, double* array, double* xmatrx) {
  Ucosub(u, time, q, idrsel, iflag, scalar, array, xmatrx);
  if (iflag == 0) c_errmes(time >= u->PAR[u->NPAR - 1], "the rope snapped", u->ID, "STOP");
}

void Novar_ucon(const struct sAdamsUcon* u, double time, const double* q, const int* idrsel,
                int iflag, double* scalar, double* array, double* xmatrx) {
  (void)u, (void)time, (void)q, (void)idrsel, (void)iflag, (void)array, (void)xmatrx;
  *scalar = 0.0;
}

void Angle_ucon(const struct sAdamsUcon* u, double time, const double* q, const int* idrsel,
                int iflag, double* scalar, double* array, double* xmatrx) {
  const int parts[1] = {(int)u->PAR[1]}, codes[1] = {14};
  (void)time, (void)q, (void)idrsel, (void)array, (void)xmatrx;
  if (iflag == 3) c_ucovar(u->ID, 1, parts, 1, codes);
  *scalar = 0.0;
}

/* Time_ucon: Ucosub's mode 1 with a height rising at PAR(4) per second, F = z_A - PAR(3) -
 * PAR(4) TIME: rheonomic, which the model build refuses. */
void Time_ucon(const struct sAdamsUcon* u, double time, const double* q, const int* idrsel,
               int iflag, double* scalar, double* array, double* xmatrx) {
  Ucosub(u, time, q, idrsel, iflag, scalar, array, xmatrx);
  if (iflag == 0 && idrsel[0]) *scalar -= u->PAR[3] * time;
}
