#pragma once
// User subroutines the mechanics calls with explicit arguments instead of through SYSFNC:
// FIESUB (FIELD with FUNCTION=USER) and COUSUB/COUXX/COUXX2 (COUPLER with FUNCTION=USER),
// docs/user-subroutines.md. The model holds them behind these interfaces so that the mechanics
// needs nothing of the loader (src/user/field_routine.cpp, coupler_routine.cpp).

namespace openmss::user {

class FieldRoutine {
 public:
  virtual ~FieldRoutine() = default;
  // FIESUB at (disp, velo) of I relative to J in J's axes: field = force and torque on I in
  // J's axes; with partials also dfddis and dfdvel, 6x6 column-major (d field_r / d disp_c at
  // r + 6c). A stopped routine gives NaN everywhere.
  virtual void evaluate(double time, const double disp[6], const double velo[6], bool partials,
                        double field[6], double dfddis[36], double dfdvel[36]) const = 0;
};

class CouplerRoutine {
 public:
  virtual ~CouplerRoutine() = default;
  // COUSUB phi(disp) over the n coupled joints' displacements; order >= 1 adds COUXX's
  // d phi / d disp (n values), order 2 COUXX2's second partials (n x n column-major).
  virtual void evaluate(double time, const double* disp, int n, int order, double* phi,
                        double* first, double* second) const = 0;
};

// UCOSUB (UCON with FUNCTION=USER): the constraint F(q) = 0 over the part variables q that
// UCOVAR declared (docs/user-subroutines.md, "UCON"). order >= 1 adds ARRAY, dF/dq (n values),
// order 2 XMATRX, d2F/dq2 (n x n column-major). A stopped routine gives NaN everywhere.
class UserConstraintRoutine {
 public:
  virtual ~UserConstraintRoutine() = default;
  virtual void evaluate(double time, const double* q, int n, int order, double* value,
                        double* first, double* second) const = 0;
};

}  // namespace openmss::user
