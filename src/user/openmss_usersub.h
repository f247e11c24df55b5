/* OpenMSS user-written subroutines: the C interface a user library compiles against
 * (docs/language.md, "User-written subroutines"). Names, argument order and types follow the
 * C-style ("mixed case") interface of ADAMS/Solver, so that a GSE written for it compiles
 * unchanged: the solver passes an element description by pointer and scalars by value; the
 * routine reads its states and inputs back through the utility subroutines below, which the
 * openmss program exports.
 *
 * Only what a GSE needs is offered; every utility reports unsupported requests through its
 * error flag rather than guessing. */
#ifndef OPENMSS_USERSUB_H
#define OPENMSS_USERSUB_H

#ifdef __cplusplus
extern "C" {
#endif

/* The GSE statement as the routines see it. Field order and types are those of ADAMS's
 * sAdamsGSE (binary compatibility); U, Y, X, IC, XD and ICD are ARRAY ids (0 = none). */
struct sAdamsGSE {
  int ID;
  int NPAR;
  const double* PAR;
  int NI;
  int NO;
  int U;
  int Y;
  int NS;
  int X;
  int IC;
  int STATIC_HOLD;
  int IMPLICIT;
  int STATICS_ONLY;
  int ND;
  int XD;
  int ICD;
  double SAMPLE_OFFSET;
};

/* The four routines of a GSE (default exported names Gse_deriv, Gse_output, Gse_update,
 * Gse_sample). */
typedef void adams_c_GSE_DERIV(const struct sAdamsGSE* gse, double time, int dflag, int iflag,
                               int ns, double* xdot);
typedef void adams_c_GSE_OUTPUT(const struct sAdamsGSE* gse, double time, int dflag, int iflag,
                                int no, double* y);
typedef void adams_c_GSE_UPDATE(const struct sAdamsGSE* gse, double time, int dflag, int iflag,
                                int nd, double* xd);
typedef void adams_c_GSE_SAMP(const struct sAdamsGSE* gse, double time, int iflag,
                              double* sample_step);

/* Values of the calling element's data. SYSARY("ARRAY", {id}, 1, ...) returns the X, XD or U
 * array of the calling GSE or the numbers of an IC/constant ARRAY; SYSFNC("ARYVAL", {id, n},
 * 2, ...) one entry of them. *errflg is nonzero when the request is not supported. */
void c_sysary(const char* fncnam, const int* ipar, int nsize, double* states, int* nstates,
              int* errflg);
void c_sysfnc(const char* fncnam, const int* ipar, int nsize, double* state, int* errflg);
/* Analytic partials of the current routine's outputs with respect to the array a previous
 * SYSARY("ARRAY", {id}) read (X or U): column-major, outputs x array entries. Used only when
 * c_adams_needs_partials said so. */
void c_syspar(const char* fncnam, const int* ipar, int nsize, const double* partials,
              int npartl, int* errflg);
void c_adams_needs_partials(int* eval_jac);

/* The calling GSE's sizes and values, without naming arrays. */
int c_gse_ns(void);
int c_gse_nd(void);
int c_gse_ni(void);
int c_gse_no(void);
void c_gse_x(double* x, int ns);
void c_gse_xd(double* xd, int nd);
void c_gse_u(double* u, int ni);

/* Time of the last call's evaluation (OpenMSS: the time the routine was called with). */
void c_timget(double* time);

/* Messages: when errflg is nonzero the message is reported with the element id; endflg
 * "STOP" or "ERROR" makes the error fatal (the run stops with it). */
void c_errmes(int errflg, const char* mesage, int id, const char* endflg);
void c_usrmes(int msgflg, const char* mesage, int id, const char* msgtyp);

#ifdef __cplusplus
}
#endif

#endif /* OPENMSS_USERSUB_H */
