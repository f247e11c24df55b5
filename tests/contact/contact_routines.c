/* C-style CONTACT force laws for tests/contact/contact_user_law_test.cpp, loaded the way a
 * user's library is (docs/user-subroutines.md, "CNFSUB and CFFSUB").
 *
 * Cnfsub: the IMPACT law through the IMPACT utility, gap as x with x1 = 0:
 *   PAR = k, e, c, dmax [, no_partials [, t_bad]]: values = force, d/dgap, d/dgapdot, the
 *   partials left unset when PAR[4] is nonzero (the solver then differences).
 * Cffsub: ADAMS's Coulomb curve, f = -N STEP(s, -vs, -1, vs, 1) STEP(s, vs, mus, vd, mud):
 *   PAR = mus, mud, vs, vd [, no_partials]: values = f, df/ds, df/dN.
 * Nan_cnf: Cnfsub, but NaN from TIME >= PAR[5]. Stop_cnf: ERRMES STOP from TIME >= PAR[5]. */
#include <math.h>

#include "user/openmss_usersub.h"

void Cnfsub(const struct sAdamsContactFriction* cnf, double time, const double* loci,
            const double* ni, const double* locj, const double* nj, double gap, double gapdot,
            double gapdotdot, double area, int dflag, int iflag, double* values) {
  const double* p = cnf->PAR;
  double vec[3];
  int err = 0;
  (void)time, (void)loci, (void)ni, (void)locj, (void)nj, (void)gapdotdot, (void)area;
  values[0] = 0.0;
  if (iflag) return; /* initialization: nothing to set up */
  c_impact(gap, gapdot, 0.0, p[0], p[1], p[2], p[3], 0, vec, &err);
  c_errmes(err, "IMPACT failed", cnf->contact.ID, "STOP");
  values[0] = vec[0];
  if (dflag && !(cnf->NPAR > 4 && p[4] != 0.0)) {
    values[1] = vec[1];
    values[2] = vec[2];
  }
}

void Nan_cnf(const struct sAdamsContactFriction* cnf, double time, const double* loci,
             const double* ni, const double* locj, const double* nj, double gap, double gapdot,
             double gapdotdot, double area, int dflag, int iflag, double* values) {
  Cnfsub(cnf, time, loci, ni, locj, nj, gap, gapdot, gapdotdot, area, dflag, iflag, values);
  if (!iflag && time >= cnf->PAR[5]) values[0] = NAN;
}

void Stop_cnf(const struct sAdamsContactFriction* cnf, double time, const double* loci,
              const double* ni, const double* locj, const double* nj, double gap, double gapdot,
              double gapdotdot, double area, int dflag, int iflag, double* values) {
  Cnfsub(cnf, time, loci, ni, locj, nj, gap, gapdot, gapdotdot, area, dflag, iflag, values);
  c_errmes(!iflag && time >= cnf->PAR[5], "the contact broke", cnf->contact.ID, "STOP");
}

void Cffsub(const struct sAdamsContactFriction* cff, double time, const double* loci,
            const double* locj, const double* x, const double* xdot, double nforce, double area,
            int dflag, int iflag, double* values) {
  const double* p = cff->PAR;
  const double s = xdot[0];
  double a, da, b, db;
  int err = 0;
  (void)time, (void)loci, (void)locj, (void)x, (void)area;
  values[0] = 0.0;
  if (iflag) return;
  c_step(s, -p[2], -1.0, p[2], 1.0, 0, &a, &err);
  c_step(s, -p[2], -1.0, p[2], 1.0, 1, &da, &err);
  c_step(s, p[2], p[0], p[3], p[1], 0, &b, &err);
  c_step(s, p[2], p[0], p[3], p[1], 1, &db, &err);
  values[0] = -nforce * a * b;
  if (dflag && !(cff->NPAR > 4 && p[4] != 0.0)) {
    values[1] = -nforce * (da * b + a * db);
    values[2] = -a * b;
  }
}
