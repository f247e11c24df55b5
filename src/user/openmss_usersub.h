/* OpenMSS user-written subroutines: the C interface a user library compiles against
 * (docs/language.md, "User-written subroutines"). Names, argument order and types follow the
 * C-style ("mixed case") interface of ADAMS/Solver, so that a GSE written for it compiles
 * unchanged: the solver passes an element description by pointer and scalars by value; the
 * routine reads its states and inputs back through the utility subroutines below, which the
 * openmss program exports.
 *
 * Every utility reports unsupported requests through its error flag rather than guessing.
 * FORTRAN-77 libraries call the same utilities under their gfortran names (sysfnc_, sysary_,
 * errmes_, ...), all arguments by reference, string lengths appended (docs/user-subroutines.md). */
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

/* ---- Evaluation subroutines of FUNCTION=USER(...) elements (docs/user-subroutines.md) ----
 * The element as a C-style routine sees it; field order and types are ADAMS's (binary
 * compatibility). Marker and element ids are the data set's. */
struct sAdamsSforce {
  int ID;
  int NPAR;
  const double* PAR;
  int I;
  int J;
  int ACTION_ONLY;
  const char* Type; /* "TRANSLATION" or "ROTATION" */
};
struct sAdamsVforce {
  int ID;
  int NPAR;
  const double* PAR;
  int I;
  int JFLOAT;
  int RM;
};
struct sAdamsVtorque {
  int ID;
  int NPAR;
  const double* PAR;
  int I;
  int JFLOAT;
  int RM;
};
struct sAdamsGforce {
  int ID;
  int NPAR;
  const double* PAR;
  int I;
  int RM;
  int JFLOAT;
};
struct sAdamsVariable {
  int ID;
  int NPAR;
  const double* PAR;
  double IC;
};
struct sAdamsDiff {
  int ID;
  int NPAR;
  const double* PAR;
  int STATIC_HOLD;
  int IMPLICIT;
  double IC_R1;
  double IC_R2;
};
struct sAdamsMotion {
  int ID;
  int NPAR;
  const double* PAR;
  int JOINT;
  const char* Type;
  int I;
  int J;
  char Which[2];
  const char* DVA;
};
struct sAdamsRequest {
  int ID;
  int NPAR;
  const double* PAR;
  const char* COMMENT;
  const char* TITLE[8];
};
struct sAdamsSensor {
  int ID;
  int NPAR;
  const double* PAR;
  double VALUE;
  double Error;
  char Logic[2];
};

typedef void adams_c_Sfosub(const struct sAdamsSforce* sforce, double time, int dflag, int iflag,
                            double* result);
typedef void adams_c_Vfosub(const struct sAdamsVforce* vforce, double time, int dflag, int iflag,
                            double* result);
typedef void adams_c_Vtosub(const struct sAdamsVtorque* vtorque, double time, int dflag,
                            int iflag, double* result);
typedef void adams_c_Gfosub(const struct sAdamsGforce* gforce, double time, int dflag, int iflag,
                            double* result);
typedef void adams_c_Varsub(const struct sAdamsVariable* variable, double time, int dflag,
                            int iflag, double* result);
typedef void adams_c_Difsub(const struct sAdamsDiff* diff, double time, int dflag, int iflag,
                            double* result);
typedef void adams_c_Motsub(const struct sAdamsMotion* motion, double time, int iord, int iflag,
                            double* result);
typedef void adams_c_Reqsub(const struct sAdamsRequest* request, double time, int iflag,
                            double* output);
typedef void adams_c_Sensub(const struct sAdamsSensor* sensor, double time, int iflag,
                            double* output);
typedef void adams_c_Sevsub(const struct sAdamsSensor* sensor, double time, int iflag,
                            double* output);

/* FIELD with FUNCTION=USER: disp and velo are I's displacement (x, y, z, AX, AY, AZ) and
 * velocity relative to J in J's axes; field the force and torque on I in J's axes; dfddis and
 * dfdvel (wanted when dflag is nonzero) the 6x6 partials, column-major: d field(r) / d disp(c)
 * at dfddis[r + 6c], as the FORTRAN DFDDIS(6,6) holds them. */
struct sAdamsField {
  int ID;
  int NPAR;
  const double* PAR;
  int I;
  int J;
};
typedef void adams_c_Fiesub(const struct sAdamsField* field, double time, double* disp,
                            double* velo, int dflag, int iflag, double* result, double* dfddis,
                            double* dfdvel);

/* CONTACT with NORMAL_FUNCTION=USER / FRICTION_FUNCTION=USER (docs/user-subroutines.md,
 * "CNFSUB and CFFSUB"), called at each contact point. Cnfsub: loci/locj the points of I's and
 * J's surfaces, ni/nj their outward normals (ground), gap the signed distance (negative while
 * the solids overlap), gapdot its rate; values[0] the normal force (positive pushes apart),
 * values[1] and values[2] its partials in gap and gapdot (read when dflag is nonzero).
 * Cffsub: xdot[0] the slip speed (xdot[1], xdot[2], x 0), nforce the normal force; values[0]
 * the friction force along the slip (negative opposes it), values[1] and values[2] its partials
 * in xdot[0] and nforce. Field order as ADAMS's structs. */
struct sAdamsContact {
  int ID;
  int nIGEOM;
  int nJGEOM;
  int* IGEOM;
  int* JGEOM;
  int* IFLIP_GEOM;
  int* JFLIP_GEOM;
};
struct sAdamsContactFriction {
  struct sAdamsContact contact;
  int NPAR;
  const double* PAR;
};
typedef void adams_c_Cnfsub(const struct sAdamsContactFriction* cnf, double time,
                            const double* loci, const double* ni, const double* locj,
                            const double* nj, double gap, double gapdot, double gapdotdot,
                            double area, int dflag, int iflag, double* values);
typedef void adams_c_Cffsub(const struct sAdamsContactFriction* cff, double time,
                            const double* loci, const double* locj, const double* x,
                            const double* xdot, double nforce, double area, int dflag, int iflag,
                            double* values);

/* CURVE with FUNCTION=USER: values = x, y, z of the curve at alpha (iord 0) or their iord-th
 * derivative in alpha (1, 2). */
struct sAdamsCurve {
  int ID;
  int NPAR;
  const double* PAR;
  int CLOSED;
  int ORDER;
  double MINPAR;
  double MAXPAR;
};
typedef void adams_c_Cursub(const struct sAdamsCurve* curve, double alpha, int iord, int iflag,
                            double* values);

/* COUPLER with FUNCTION=USER: disp holds the coupled joints' displacements (TYPE[k] 'T' or
 * 'R'); Cousub returns phi (the constraint phi = 0), Couxx d phi / d disp (NJOINT values),
 * Couxx2 the second partials (NJOINT x NJOINT, column-major). */
struct sAdamsCoupler {
  int ID;
  int NPAR;
  const double* PAR;
  int NJOINT;
  int JOINTS[3];
  char TYPE[3];
};
typedef void adams_c_Cousub(const struct sAdamsCoupler* coupler, double time, double* disp,
                            int iflag, double* phi);
typedef void adams_c_Couxx(const struct sAdamsCoupler* coupler, double time, double* disp,
                           int iflag, double* dfda);
typedef void adams_c_Couxx2(const struct sAdamsCoupler* coupler, double time, double* disp,
                            int iflag, double* d2fda2);

/* UCON/id, FUNCTION=USER(...): with IFLAG = 3 the routine declares its variables with c_ucovar
 * (LPARTS[k] a PART id, LVARS[k] its code: 11, 12, 13 the CM's x, y, z in ground; 111..113,
 * 211..213, 311..313 the ground components of the part's x, y, z axis). With IFLAG = 0 it gets
 * their values in q (NQ of them) and returns, as IDRSEL[0], IDRSEL[1], IDRSEL[2] ask (1: wanted,
 * 0: not), the constraint value F (*scalar), dF/dq (array, NQ values) and d2F/dq2 (xmatrx, 30 x
 * 30 column-major: d2F/dq_m dq_n at m + 30 n). ADAMS has no C-style UCOSUB: this interface is
 * OpenMSS's (docs/user-subroutines.md, "UCON"). */
struct sAdamsUcon {
  int ID;
  int NPAR;
  const double* PAR;
  int NQ;
};
typedef void adams_c_Ucosub(const struct sAdamsUcon* ucon, double time, const double* q,
                            const int* idrsel, int iflag, double* scalar, double* array,
                            double* xmatrx);
void c_ucovar(int id, int nparts, const int* lparts, int nvars, const int* lvars);

/* SPLINE/id, FILE=..., BLOCK=...: the reader stores the data with c_put_spline. */
struct sAdamsSpline {
  int ID;
  const char* FILENAME;
  const char* BLOCKNAME;
};
typedef void adams_c_Spline_read(const struct sAdamsSpline* spline, int* ierr);
void c_put_spline(int id, int nxvals, int nzvals, const double* xvals, const double* yvals,
                  const double* zvals, int* errflg);

/* General functions: the iord-th derivative (0, 1, 2) in x of the expression function of the
 * same name; *errflg nonzero on a bad argument. IMPACT and BISTOP return in vec[0] the force,
 * vec[1] its partial in x and vec[2] its partial in dxdt (iord is ignored). */
void c_step(double x, double x0, double h0, double x1, double h1, int iord, double* value,
            int* errflg);
void c_step5(double x, double x0, double h0, double x1, double h1, int iord, double* value,
             int* errflg);
void c_havsin(double x, double x0, double h0, double x1, double h1, int iord, double* value,
              int* errflg);
void c_shf(double x, double x0, double a, double w, double phi, double b, int iord, double* value,
           int* errflg);
void c_poly(double x, double x0, const double* par, int npar, int iord, double* value,
            int* errflg);
void c_cheby(double x, double x0, const double* par, int npar, int iord, double* value,
             int* errflg);
void c_forcos(double x, double x0, double w, const double* par, int npar, int iord,
              double* value, int* errflg);
void c_forsin(double x, double x0, double w, const double* par, int npar, int iord,
              double* value, int* errflg);
void c_impact(double x, double dxdt, double x1, double k, double e, double cmax, double d,
              int iord, double* vec, int* errflg);
void c_bistop(double x, double dxdt, double x1, double x2, double k, double e, double cmax,
              double d, int iord, double* vec, int* errflg);
/* Model data of the calling routine's model: SPLINE/id by Akima or cubic interpolation (iord 0:
 * array[0] = y; 1: dy/dx, dy/dz; 2: d2y/dx2, d2y/dxdz, d2y/dz2), CURVE/id (x, y, z or their
 * iord-th derivative in alpha), the values of an IC or constant ARRAY/id, STRING/id. */
void c_akispl(double xval, double zval, int id, int iord, double* array, int* errflg);
void c_cubspl(double xval, double zval, int id, int iord, double* array, int* errflg);
void c_gtcurv(int id, double alpha, int iord, double* array, int* istat);
void c_gtaray(int id, double* array, int* number, int* istat);
void c_gtstrg(int id, char* string, int* nchars, int* istat);
/* Rotation coordinates from system sys1 to sys2: EULER (3-1-3), EULPAR, RODPAR, COSINES
 * (column by column), YPR, B123 ... B323 (body-fixed sequences); *istat nonzero on an
 * unknown system. */
void c_rcnvrt(const char* sys1, const double* coord1, const char* sys2, double* coord2,
              int* istat);
/* Point coordinates from system sys1 to sys2: CARTESIAN (x, y, z), CYLINDRICAL (r, theta, z),
 * SPHERICAL (rho, phi, theta); theta the azimuth from +x, phi the angle from +z; *istat
 * nonzero on an unknown system. */
void c_tcnvrt(const char* sys1, const double* coord1, const char* sys2, double* coord2,
              int* istat);
/* TIMGET's older name: the time of the last converged step. */
void c_timegt(double* time);
/* CONSUB, the driver of the CONTROL command (CONTROL/FUNCTION=USER(r1, ..., r30)
 * [, ROUTINE=lib::name]): C style `void Consub(const struct sAdamsControl* con)`, or FORTRAN 77
 * `SUBROUTINE CONSUB(PAR, NPAR)`. Field order as ADAMS's sAdamsControl. */
struct sAdamsControl {
  int NPAR;
  const double* PAR;
};
/* Analysis control, inside CONSUB only (docs/user-subroutines.md, "CONSUB"): ANALYS runs an
 * analysis ("TRANSIENT", "DYNAMICS", "KINEMATICS", "STATIC"/"STATICS") from timbeg (the current
 * time) to timend without writing output, init nonzero solving the initial conditions again
 * first; DATOUT writes one output step at the current state; MODIFY executes one command.
 * *istat = 0 when done. Outside CONSUB they do nothing, print why once, and set *istat = 1. */
void c_analys(const char* antype, const char* cid, double timbeg, double timend, int init,
              int* istat);
void c_datout(int* istat);
void c_modify(const char* comand, int* istat);
/* The model's UNITS: *exists nonzero when a UNITS statement was given; scales[4] the SI value
 * of one time, length, force and mass unit; units (13 bytes) their symbols, 3 characters each,
 * blank-padded, NUL-terminated (SYSTEM=NONE: scales 1, blanks). */
void c_gtunts(int* exists, double* scales, char* units);
/* The analysis mode (1 kinematics, 3 initial conditions, 4 dynamics, 5 statics, 6 quasi-statics,
 * 7 linear), read like SYSFNC("MODE"): call it in the dependency pass too. GETINM: 1 during the
 * initial-conditions analysis, else 0. */
void c_getmod(int* mode);
void c_getinm(int* mode);
/* Deterministic CPU time: always 0 (OpenMSS outputs are bit-identical run to run). */
void c_getcpu(double* cpu);

#ifdef __cplusplus
}
#endif

#endif /* OPENMSS_USERSUB_H */
