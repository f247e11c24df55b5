/* CONSUB drivers for tests/user/consub_test.cpp, C style (docs/user-subroutines.md, "CONSUB").
 * Consub: the study "simulate to PAR[0], SFORCE/1 FUNCTION=PAR[2], simulate to PAR[1]", output
 * by DATOUT after each analysis. The others misbehave, each in one way the session must
 * contain. */
#include <math.h>
#include <stdio.h>

#include "user/openmss_usersub.h"

void Consub(const struct sAdamsControl* con) {
  int istat = 0;
  char command[80];
  if (con->NPAR != 3) {
    c_errmes(1, "Consub needs USER(t1, t2, force)", 0, "STOP");
    return;
  }
  c_analys("DYNAMICS", "first", 0.0, con->PAR[0], 1, &istat);
  if (istat != 0) c_errmes(1, "the first ANALYS failed", 1, "STOP");
  c_datout(&istat);
  snprintf(command, sizeof command, "SFORCE/1, FUNCTION=%.17g", con->PAR[2]);
  c_modify(command, &istat);
  if (istat != 0) c_errmes(1, "MODIFY failed", 2, "STOP");
  c_analys("DYNAMICS", "second", con->PAR[0], con->PAR[1], 0, &istat);
  if (istat != 0) c_errmes(1, "the second ANALYS failed", 3, "STOP");
  c_datout(&istat);
}

/* ERRMES with STOP, then a MODIFY that must do nothing (istat = 1). */
void Consub_errmes(const struct sAdamsControl* con) {
  int istat = 0;
  (void)con;
  c_errmes(1, "the user's routine gives up", 7, "STOP");
  c_modify("SFORCE/1, FUNCTION=5", &istat);
  if (istat == 0) c_modify("SFORCE/1, FUNCTION=6", &istat); /* would show as a wrong force */
}

/* ANALYS to a NaN end time: refused (istat = 1), which the routine reports with ERRMES. */
void Consub_nan(const struct sAdamsControl* con) {
  int istat = 0;
  (void)con;
  c_analys("DYNAMICS", "nan", 0.0, nan(""), 1, &istat);
  if (istat != 0) c_errmes(1, "ANALYS refused a NaN end time", 8, "STOP");
}

/* A crash inside CONSUB. */
void Consub_crash(const struct sAdamsControl* con) {
  /* A null pointer the compiler cannot prove null (PAR[0] is never that large). */
  volatile int* nowhere = con->PAR[0] > 1e300 ? (volatile int*)&con->NPAR : (volatile int*)0;
  *nowhere = 1;
}
