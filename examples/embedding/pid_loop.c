/* A PID loop closed around a plant data set through the OpenMSS embedding API
 * (docs/embedding.md, "The PID example"): the ADAMS/Controls use case. The plant
 * (pendulum_plant.adm) exports its torque input as PINPUT/1 and its angle and rate as
 * POUTPUT/1. Every H seconds the program reads the outputs, computes the torque of a PID
 * controller and sets it as the plant input, which holds until the next sample (a zero-order
 * hold: openmss_advance integrates one communication interval with the inputs constant):
 *
 *   e_k = REF - angle_k,   u_k = KP e_k + KI S_k - KD rate_k,   S_(k+1) = S_k + H e_k
 *
 * Build:  cc pid_loop.c $(pkg-config --cflags --libs openmss) -o pid_loop
 * Run:    ./pid_loop pendulum_plant.adm [OUTPUT_DIR] [--compare pendulum_pid.adm]
 * It prints the angle, rate and torque every 1/4 s. With --compare it also runs the data set
 * that holds the same controller written with VARIABLE, DIFF and DELAY, reads its angle and rate
 * (VARIABLE/2 and /3) at every sample time, prints the largest difference and exits with status
 * 3 when it exceeds TOLERANCE. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "openmss/openmss.h"

enum { SAMPLES = 256 };            /* 4 s */
static const double H = 1.0 / 64;  /* communication interval (a power of two: exact times) */
static const double REF = 0.5, KP = 20.0, KI = 10.0, KD = 3.0;
/* Both runs integrate with these settings (docs/embedding.md, "The same loop in one data set"):
 * SI2 controls the error of the rates the controller reads as well as of the angles; HMIN
 * below the default lets the data-set run shrink its first step after each sample time, where
 * its torque jumps inside the integration, until the jump costs less than ERROR. */
static const char* const INTEGRATOR = "INTEGRATOR/GSTIFF, SI2, ERROR=1e-11, HMIN=1e-14";
static const double TOLERANCE = 1e-8;

static int failed(const char* what) {
  fprintf(stderr, "pid_loop: %s failed: %s\n", what, openmss_last_error());
  return 1;
}

/* The embedded loop: angle and rate at every sample time into angle[], rate[]. */
static int run_loop(const char* plant, const char* outdir, double* angle, double* rate) {
  openmss_solver* s = NULL;
  if (openmss_open(plant, outdir, &s) != OPENMSS_OK) return failed("openmss_open");
  double sum = 0.0; /* S_k */
  int status = 0;
  if (openmss_command(s, INTEGRATOR) != OPENMSS_OK || openmss_initialize(s) != OPENMSS_OK) {
    status = failed("setting up the plant");
    goto done;
  }
  for (int k = 0; k <= SAMPLES; ++k) {
    double y[2];
    if (openmss_get_poutput(s, 1, y, 2) != OPENMSS_OK) {
      status = failed("openmss_get_poutput");
      goto done;
    }
    angle[k] = y[0];
    rate[k] = y[1];
    if (k == SAMPLES) break;
    const double e = REF - y[0];
    const double u = KP * e + KI * sum - KD * y[1];
    sum += H * e;
    if (k % 16 == 0) printf("%8.4f %18.12f %18.12f %18.12f\n", k * H, y[0], y[1], u);
    if (openmss_set_pinput(s, 1, &u, 1) != OPENMSS_OK) {
      status = failed("openmss_set_pinput");
      goto done;
    }
    if (openmss_advance(s, (k + 1) * H, 1) != OPENMSS_OK) {
      status = failed("openmss_advance");
      goto done;
    }
  }
  printf("%8.4f %18.12f %18.12f\n", SAMPLES * H, angle[SAMPLES], rate[SAMPLES]);
done:
  openmss_close(s);
  return status;
}

/* The same loop in one data set: its VARIABLE/2 and /3 at the same sample times. */
static int run_reference(const char* dataset, const char* outdir, double* angle, double* rate) {
  openmss_solver* s = NULL;
  if (openmss_open(dataset, outdir, &s) != OPENMSS_OK) return failed("openmss_open");
  int status = 0;
  if (openmss_command(s, INTEGRATOR) != OPENMSS_OK || openmss_initialize(s) != OPENMSS_OK) {
    status = failed("setting up the reference");
    goto done;
  }
  for (int k = 0; k <= SAMPLES; ++k) {
    if (openmss_variable(s, 2, &angle[k]) != OPENMSS_OK ||
        openmss_variable(s, 3, &rate[k]) != OPENMSS_OK) {
      status = failed("openmss_variable");
      goto done;
    }
    if (k < SAMPLES && openmss_advance(s, (k + 1) * H, 1) != OPENMSS_OK) {
      status = failed("openmss_advance");
      goto done;
    }
  }
done:
  openmss_close(s);
  return status;
}

int main(int argc, char** argv) {
  const char* plant = NULL;
  const char* outdir = ".";
  const char* compare = NULL;
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "--compare") == 0 && i + 1 < argc)
      compare = argv[++i];
    else if (plant == NULL)
      plant = argv[i];
    else
      outdir = argv[i];
  }
  if (plant == NULL) {
    fprintf(stderr, "usage: pid_loop PLANT.adm [OUTPUT_DIR] [--compare PID.adm]\n");
    return 1;
  }
  printf("OpenMSS %s; PID loop, H = %g s\n", openmss_version(), H);
  static double angle[SAMPLES + 1], rate[SAMPLES + 1], angle2[SAMPLES + 1], rate2[SAMPLES + 1];
  if (run_loop(plant, outdir, angle, rate) != 0) return 1;
  if (compare == NULL) return 0;
  if (run_reference(compare, outdir, angle2, rate2) != 0) return 1;
  double worst = 0.0;
  int count = 0;
  for (int k = 0; k <= SAMPLES; ++k) {
    worst = fmax(worst, fmax(fabs(angle[k] - angle2[k]), fabs(rate[k] - rate2[k])));
    count += 2;
  }
  printf("compared %d values at %d sample times: largest difference %.3e (tolerance %.0e)\n",
         count, SAMPLES + 1, worst, TOLERANCE);
  return worst <= TOLERANCE ? 0 : 3;
}
