/* A user library with its own state, for tests/user/savsub_test.cpp (docs/user-subroutines.md,
 * "SAVSUB and RELSUB"): REQSUB reports how many output steps it has been evaluated at (a
 * counter the solver does not know), SAVSUB writes the counter to the save file, RELSUB reads
 * it back. */
#include <unistd.h>

#include "user/openmss_usersub.h"

static double counter = 0.0;

void Reqsub(const struct sAdamsRequest* r, double time, int iflag, double* out) {
  (void)r;
  if (iflag == 0) counter += 1.0; /* evaluations, not the dependency pass (IFLAG 1, 3) */
  out[0] = 0.0;
  out[1] = counter;
  out[2] = time;
  for (int k = 3; k < 8; ++k) out[k] = 0.0;
}

void Savsub(int iunit, int* ierr) {
  *ierr = write(iunit, &counter, sizeof counter) == (ssize_t)sizeof counter ? 0 : 1;
}

void Relsub(int iunit, int* ierr) {
  double saved = 0.0;
  *ierr = read(iunit, &saved, sizeof saved) == (ssize_t)sizeof saved ? 0 : 1;
  if (*ierr == 0) counter = saved;
}
