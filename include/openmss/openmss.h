/* OpenMSS embedding API (the "callable solver"), C interface. docs/embedding.md.
 *
 * A program loads an ADAMS data set, sets the values of its plant inputs (the VARIABLEs that a
 * PINPUT lists), advances the dynamic analysis to a time, reads its plant outputs (POUTPUT),
 * any VARIABLE and any REQUEST, and saves or reloads the run state: what ADAMS/Controls does
 * with a Controls_Plant data set. Every function returns an openmss_status; on an error,
 * openmss_last_error() holds one line "file:line:col: error: STATEMENT/id: what. What to
 * change." and openmss_last_error_file()/_line() its location (the data set's line when the
 * error is in the data set). The message is per thread and kept until the next call on that
 * thread. A solver is not thread-safe; distinct solvers may run on distinct threads only if
 * their models load no user subroutines. Link with `pkg-config --cflags --libs openmss`. */
#ifndef OPENMSS_OPENMSS_H
#define OPENMSS_OPENMSS_H

#ifdef __cplusplus
extern "C" {
#endif

/* The library is built with hidden visibility; only these declarations are exported. */
#if defined(__GNUC__)
#define OPENMSS_API __attribute__((visibility("default")))
#else
#define OPENMSS_API
#endif

/* The interface version: bumped when a declaration here changes (the SONAME follows it). */
#define OPENMSS_API_VERSION 1

typedef struct openmss_solver openmss_solver; /* opaque */

typedef enum openmss_status {
  OPENMSS_OK = 0,
  OPENMSS_ERROR_ARGUMENT = 1, /* a null pointer, a wrong count, an id the model does not have */
  OPENMSS_ERROR_INPUT = 2,    /* the data set or a command is wrong (file:line in the message) */
  OPENMSS_ERROR_ANALYSIS = 3, /* an analysis failed (outputs up to its last good step stay) */
  OPENMSS_ERROR_FILE = 4,     /* a file cannot be read or written, or a save file is refused */
  OPENMSS_ERROR_STATE = 5     /* not possible now (a time before the current one, ...) */
} openmss_status;

/* "0.1.0": the library's version. */
OPENMSS_API const char* openmss_version(void);
/* The last error on this thread ("" after a success). */
OPENMSS_API const char* openmss_last_error(void);
/* Its file ("" when it is about no file) and 1-based line (0 when unknown). */
OPENMSS_API const char* openmss_last_error_file(void);
OPENMSS_API int openmss_last_error_line(void);

/* Reads, checks and builds the data set `dataset_path` (.adm); the outputs (<prefix>.msg, and
 * .req with OUTPUT/REQSAVE) go to `output_dir` (NULL: the current directory) with the data
 * set's base name as prefix. On success *solver is a new solver at time 0 (initial conditions
 * not yet solved); on failure *solver is NULL. */
OPENMSS_API openmss_status openmss_open(const char* dataset_path, const char* output_dir,
                                        openmss_solver** solver);
/* Ends the session (closes the output files, as STOP does) and frees the solver. NULL: no-op. */
OPENMSS_API void openmss_close(openmss_solver* solver);

/* Executes one ADAMS command (INTEGRATOR/GSTIFF, ERROR=1e-8; OUTPUT/REQSAVE; ...). */
OPENMSS_API openmss_status openmss_command(openmss_solver* solver, const char* command);

/* Solves the initial conditions (SIMULATE/INITIAL_CONDITIONS) unless they hold already, so
 * that outputs can be read before the first advance. */
OPENMSS_API openmss_status openmss_initialize(openmss_solver* solver);
/* The current simulated time. */
OPENMSS_API openmss_status openmss_time(const openmss_solver* solver, double* time);
/* Integrates the equations of motion from the current state to `end` (> the current time)
 * with `output_steps` (>= 1) output steps, as SIMULATE/DYNAMICS, END=end, STEPS=output_steps.
 * The integrator starts afresh from the current state: the plant inputs are held constant over
 * the call (a zero-order hold of the communication interval). */
OPENMSS_API openmss_status openmss_advance(openmss_solver* solver, double end, int output_steps);

/* The number of VARIABLEs PINPUT/id (POUTPUT/id) lists. */
OPENMSS_API openmss_status openmss_pinput_count(const openmss_solver* solver, long pinput_id,
                                                int* count);
OPENMSS_API openmss_status openmss_poutput_count(const openmss_solver* solver, long poutput_id,
                                                 int* count);
/* Sets the `count` plant inputs of PINPUT/id, in its VARIABLES= order. From now on each such
 * VARIABLE holds the value given instead of its FUNCTION (until set again). */
OPENMSS_API openmss_status openmss_set_pinput(openmss_solver* solver, long pinput_id,
                                              const double* values, int count);
/* Reads the `count` plant outputs of POUTPUT/id, in its VARIABLES= order, at the current
 * state. */
OPENMSS_API openmss_status openmss_get_poutput(const openmss_solver* solver, long poutput_id,
                                               double* values, int count);
/* The value of VARIABLE/id at the current state. */
OPENMSS_API openmss_status openmss_variable(const openmss_solver* solver, long variable_id,
                                            double* value);
/* The eight components of REQUEST/id at the current state, in the order of the data set's
 * REQUEST (DISPLACEMENT: DM, DX, DY, DZ, 0, PSI, THETA, PHI; VELOCITY, ACCELERATION, FORCE: the
 * magnitude, x, y, z, the angular magnitude, x, y, z; F1..F8 or REQSUB: the eight values), in
 * model units with angles in radians (the .req prints degrees). */
OPENMSS_API openmss_status openmss_request(const openmss_solver* solver, long request_id,
                                           double values[8]);

/* SAVE/STATES, FILE=path and RELOAD/STATES, FILE=path: the whole run state. The plant input
 * values are not in the file; they stay as last set. */
OPENMSS_API openmss_status openmss_save(openmss_solver* solver, const char* path);
OPENMSS_API openmss_status openmss_reload(openmss_solver* solver, const char* path);

#ifdef __cplusplus
}
#endif

#endif /* OPENMSS_OPENMSS_H */
