#pragma once
// User-written force laws of CONTACT (docs/user-subroutines.md, "CNFSUB and CFFSUB"): the
// mechanics calls them at each contact point with explicit arguments (no SYSFNC), so the model
// holds them behind these interfaces and needs nothing of the loader
// (src/user/contact_routines.cpp).

namespace openmss::user {

// What CNFSUB receives at one contact point, in ground coordinates.
struct ContactNormalInput {
  double loci[3];  // the point of I's surface
  double ni[3];    // I's outward normal there (from J towards I reversed: -n)
  double locj[3];  // the point of J's surface
  double nj[3];    // J's outward normal there (n: the normal force pushes I along it)
  double gap;      // signed distance: -penetration (negative while the solids overlap)
  double gapdot;   // its rate
  double gapdotdot;
  double area;
};

class ContactNormalRoutine {
 public:
  virtual ~ContactNormalRoutine() = default;
  // values[0]: the normal force (positive pushes the solids apart); with partials also
  // values[1] = d force / d gap and values[2] = d force / d gapdot. A stopped routine gives
  // NaN everywhere.
  virtual void evaluate(double time, const ContactNormalInput& in, bool partials,
                        double values[3]) const = 0;
};

// What CFFSUB receives at one contact point (ground coordinates): the slip is along the first
// axis of its frame, so xdot = (|v_slip|, 0, 0); x is (0, 0, 0) (no slip-displacement state).
struct ContactFrictionInput {
  double loci[3], locj[3];
  double x[3], xdot[3];
  double nforce;  // the normal force at the point
  double area;
};

class ContactFrictionRoutine {
 public:
  virtual ~ContactFrictionRoutine() = default;
  // values[0]: the friction force along the slip direction (negative opposes the slip); with
  // partials also values[1] = d values[0] / d xdot[0] and values[2] = d values[0] / d nforce.
  virtual void evaluate(double time, const ContactFrictionInput& in, bool partials,
                        double values[3]) const = 0;
};

}  // namespace openmss::user
