/* An ELLIPSOID of unequal scales dropped on a BOX (a CONTACT pair of the FCL narrow phase)
 * through the installed libopenmss (tests/capi/installed_example_test.sh): the library opens its
 * FCL module from LIBDIR/openmss (docs/architecture.md, "FCL module"). Exits 1 with the
 * library's message on any error; prints the final height, which the script checks is above the
 * free fall's (the contact held the solid up). Usage: fcl_contact DATASET OUTPUT_DIR */
#include <openmss/openmss.h>
#include <stdio.h>

int main(int argc, char** argv) {
  openmss_solver* solver = NULL;
  double z = 0.0;
  if (argc != 3 || openmss_open(argv[1], argv[2], &solver) != OPENMSS_OK ||
      openmss_initialize(solver) != OPENMSS_OK || openmss_advance(solver, 0.05, 5) != OPENMSS_OK ||
      openmss_variable(solver, 1, &z) != OPENMSS_OK) {
    fprintf(stderr, "fcl_contact: %s\n", openmss_last_error());
    openmss_close(solver);
    return 1;
  }
  printf("height %.6f\n", z);
  openmss_close(solver);
  return 0;
}
