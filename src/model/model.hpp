#pragma once
// The Model: a validated, flat, index-based description of the mechanism, built once from a
// Dataset and immutable during an analysis. Cross references are indices into the vectors
// below (never ids); ids are kept for output and diagnostics.

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "common/bspline_curve.hpp"
#include "common/source_location.hpp"
#include "common/spline.hpp"
#include "expr/expression.hpp"
#include "model/analysis_settings.hpp"
#include "model/analysis_status.hpp"
#include "model/contact.hpp"
#include "model/measure.hpp"
#include "user/element_interfaces.hpp"
#include "user/gse_routines.hpp"

namespace openmss::model {

struct Units {
  double ucf = 1.0;                     // Force * UCF = Mass * Acceleration
  // Unit names as the UNITS statement gives them (canonical words).
  std::string length = "METER", mass = "KILOGRAM", time = "SECOND", force = "NEWTON";
  std::string description = "m, kg, s, N";
  bool given = false;  // a UNITS statement was read (GTUNTS)
};

struct Part {
  long id = 0;
  bool ground = false;
  double mass = 0.0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the CM, in body (CM marker) axes
  // Pose of the body frame (origin at the CM, axes of the CM marker) at the data set's
  // configuration, in ground.
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
  // Initial velocities as given: translational in ground axes, angular in CM-marker axes.
  std::array<std::optional<double>, 3> velocity;
  std::array<std::optional<double>, 3> angularVelocity;
  // EXACT=X:Y:Z:PSI:THETA:PHI: coordinates (CM position in ground, 3-1-3 angles of the body
  // frame) the position initial conditions hold (heavily weighted, docs/theory.md §7).
  std::array<bool, 6> exact{};
  int body = -1;  // index of the moving body in the state (-1 for ground)
  SourceLocation where;
};

struct Marker {
  long id = 0;
  int part = -1;
  // Pose in the part's body frame (origin at the CM, CM-marker axes).
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
  // FLOATING: a marker without a fixed pose on its part. Only the JFLOAT of VFORCE, VTORQUE
  // and GFORCE may name one (the reaction goes to its part at the I marker's location).
  bool floating = false;
  SourceLocation where;
};

enum class JointType {
  Revolute, Spherical, Universal, Hooke, Translational, Cylindrical, Fixed,
  Convel, Planar, RackPin, Screw
};
const char* jointTypeName(JointType t);

struct Joint {
  long id = 0;
  JointType type = JointType::Revolute;
  int iMarker = -1;
  int jMarker = -1;
  double pitchDiameter = 0.0;  // RACKPIN PD
  double pitch = 0.0;          // SCREW PITCH (travel per turn)
  // Joint initial conditions (IC on revolute/translational, ICTRAN/ICROT on cylindrical):
  // displacement and velocity of I relative to J, held during the initial-condition analysis.
  std::optional<double> icTranslation, icTranslationVelocity, icRotation, icRotationVelocity;
  SourceLocation where;
};

// JPRIM: a joint primitive, constraint equations between two markers (docs/theory.md §5).
enum class JPrimType { AtPoint, InLine, InPlane, Orientation, ParallelAxes, Perpendicular };
const char* jprimTypeName(JPrimType t);

struct JPrim {
  long id = 0;
  JPrimType type = JPrimType::AtPoint;
  int iMarker = -1;
  int jMarker = -1;
  SourceLocation where;
};

// COUPLER: scales[0] q1 + scales[1] q2 [+ scales[2] q3] = 0 on the displacements q of two or
// three joints (rotation about zJ or translation along zJ of I relative to J, measured from
// the data set's configuration; docs/theory.md §5b).
struct Coupler {
  long id = 0;
  std::vector<int> joints;    // indices into Model::joints (2 or 3)
  std::vector<bool> rotation; // per joint: its rotational (true) or translational displacement
  std::vector<double> scales; // one per joint
  // FUNCTION=USER(...): COUSUB/COUXX/COUXX2 give the constraint instead of the scales.
  std::shared_ptr<const user::CouplerRoutine> user;
  SourceLocation where;
};

// GEAR: the contact point (CV marker origin) moves with the same velocity along zCV whether
// carried by the first or the second joint's gear (docs/theory.md §5b).
struct Gear {
  long id = 0;
  int joints[2] = {-1, -1};  // indices into Model::joints
  int cvMarker = -1;         // on the carrier: the part both joints share
  SourceLocation where;
};

struct Motion {
  enum class Form { Displacement, Velocity, Acceleration };
  long id = 0;
  int joint = -1;        // JOINT= motion, or -1 for a marker-pair (I=, J=) motion
  bool rotation = true;  // rotational (revolute, cylindrical ROTATION, B1-B3) or translational
  // Markers the motion acts between (the joint's for a JOINT= motion).
  int iMarker = -1;
  int jMarker = -1;
  // Marker-pair motions: 0-2 = X, Y, Z (DX/DY/DZ of I rel J in J axes), 3-5 = B1, B2, B3
  // (body 1-2-3 angles of I rel J). Joint motions: 2 (translation) or 5 (rotation about zJ).
  int axis = 2;
  Form form = Form::Displacement;
  double icDisp = 0.0;  // VELOCITY and ACCELERATION: displacement at TIME = 0
  double icVel = 0.0;   // ACCELERATION: velocity at TIME = 0
  expr::Expression function;  // displacement, velocity or acceleration as a function of TIME
  SourceLocation where;
};

// An expression together with the model quantities its host calls read.
struct BoundExpression {
  expr::Expression expression;
  std::vector<Measure> measures;  // measures[k] is the value of expression.hostCalls()[k]
};

// GCON/id [, I=id], FUNCTION=e: the expression is held at zero (docs/theory.md §5c). Only
// position measures of fixed markers may appear (holonomic, scleronomic); I names the marker
// whose part's reaction is reported (-1: none, ADAMS's default of ground).
struct GeneralConstraint {
  // The most markers one GCON may read and the most distinct measures in its FUNCTION; they
  // bound the fixed work arrays of the constraint evaluation.
  static constexpr int kMaxMarkers = 6;
  static constexpr int kMaxMeasures = 16;
  long id = 0;
  int iMarker = -1;
  BoundExpression function;
  SourceLocation where;
};

// UCON/id, FUNCTION=USER(r1, ..., r30) [, ROUTINE=lib::name]: UCOSUB's F(q) = 0 over the part
// variables UCOVAR declared (docs/user-subroutines.md "UCON", docs/theory.md §5f). Variable k is
// code codes[k] of the body frame of the part whose marker markers[k] sits at that frame
// (origin at the CM, CM-marker axes): 11..13 the origin's x, y, z in ground, 100 a + 10 + c
// (a, c = 1..3) component c in ground of the part's axis a.
struct UserConstraint {
  static constexpr int kMaxParts = 6;  // distinct parts: the equation's frame slots
  long id = 0;
  std::vector<int> markers;  // per variable, a marker at its part's body frame
  std::vector<int> codes;    // per variable
  std::shared_ptr<const user::UserConstraintRoutine> user;
  SourceLocation where;
};

struct SForce {
  long id = 0;
  int iMarker = -1;
  int jMarker = -1;
  bool rotation = false;
  bool actionOnly = false;
  BoundExpression function;
  SourceLocation where;
};

// ---- Force elements beyond SFORCE (docs/theory.md §6; mechanics/force_elements.hpp) ----

// SPRINGDAMPER: translational (K, C, LENGTH, FORCE) or rotational (KT, CT, ANGLE, TORQUE).
// Both read as stiffness, damping, free length or angle, and preload at that length or angle.
struct SpringDamper {
  long id = 0;
  int iMarker = -1;
  int jMarker = -1;
  bool rotational = false;
  double stiffness = 0.0;
  double damping = 0.0;
  double freeValue = 0.0;  // LENGTH or ANGLE (radians)
  double preload = 0.0;    // FORCE or TORQUE
  SourceLocation where;
};

// BUSHING, FIELD and BEAM share one law: {F; T} = -K (q - reference) - C q' + preload on the I
// marker, components in J axes, q = (x, y, z, a, b, c) of I relative to J (theory.md §6).
struct LinearField {
  enum class Kind { Bushing, Field, Beam };
  long id = 0;
  Kind kind = Kind::Field;
  int iMarker = -1;
  int jMarker = -1;
  Eigen::Matrix<double, 6, 6> stiffness = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 6> damping = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> reference = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> preload = Eigen::Matrix<double, 6, 1>::Zero();
  // FIELD with FUNCTION=USER(...): FIESUB gives the load instead of the matrices above.
  std::shared_ptr<const user::FieldRoutine> user;
  SourceLocation where;
};

// VFORCE (force), VTORQUE (torque), GFORCE (both): components in RM axes acting at I; the
// reaction acts on the part of the floating marker JFLOAT at I's location.
struct VectorForce {
  enum class Kind { VForce, VTorque, GForce };
  long id = 0;
  Kind kind = Kind::VForce;
  int iMarker = -1;
  int jFloat = -1;
  int rmMarker = -1;
  std::array<std::optional<BoundExpression>, 6> components;  // FX FY FZ TX TY TZ; unset = 0
  SourceLocation where;
};

// PTCV: marker I's origin stays on CURVE `curve` (index into Model::curves), fixed in the frame
// of marker RM (docs/theory.md §5d). JFLOAT is the contact marker on RM's part; its pose is not
// computed (nothing reads it), so requests and functions may not name it.
struct PointCurve {
  long id = 0;
  int iMarker = -1;
  int jFloat = -1;
  int rmMarker = -1;
  int curve = -1;
  SourceLocation where;
};

// CVCV: CURVE `iCurve` (in the x-y plane of marker IRM) and CURVE `jCurve` (in the x-y plane of
// marker JRM, on another part) stay in contact and tangent (docs/theory.md §5e). IFLOAT and
// JFLOAT are contact markers on IRM's and JRM's parts; their poses are not computed.
struct CurveCurve {
  long id = 0;
  int iRm = -1, jRm = -1;
  int iFloat = -1, jFloat = -1;
  int iCurve = -1, jCurve = -1;  // indices into Model::curves
  SourceLocation where;
};

// FRICTION on a joint (docs/theory.md, "Joint friction"; mechanics/friction/): a force and/or
// torque that opposes the slip of the joint, proportional to an equivalent normal force made of
// the joint's reaction (multipliers), its preload and arms.
struct Friction {
  enum class Effect { All, Stiction, Sliding };
  long id = 0;
  int joint = -1;  // index into Model::joints
  double muStatic = 0.0, muDynamic = 0.0;
  double stictionVelocity = 0.1;        // STICTION_TRANSITION_VELOCITY (length/time)
  double maxStictionDeformation = 0.01; // MAX_STICTION_DEFORMATION (length)
  double preload = 0.0;                 // FRICTION_FORCE_PRELOAD (force)
  double frictionArm = 1.0;             // FRICTION_ARM (Rn)
  double bendingArm = 1.0;              // BENDING_REACTION_ARM (Rb)
  double ballRadius = 1.0;              // BALL_RADIUS
  double pinRadius = 1.0;               // PIN_RADIUS (Rp)
  double initialOverlap = 1.0;          // INITIAL_OVERLAP (Xs0)
  Effect effect = Effect::All;
  // INPUTS switches: PRELOAD, REACTION_FORCE, BENDING_MOMENT, TORSIONAL_MOMENT.
  bool usePreload = true, useReactionForce = true, useBendingMoment = true,
       useTorsionalMoment = true;
  bool inactiveStatic = false;  // INACTIVE=STATIC
  SourceLocation where;
};

// NFORCE (docs/theory.md §6b): a linear force among n I markers and J. Per I marker k the
// displacement q_k = (x, y, z, a, b, c) of I_k relative to J in J axes (as FIELD) and its rate
// give {F; T}_k = -K (q - LENGTH) - C q' + FORCE (6n rows, K and C 6n x 6n) on I_k in J axes;
// J takes the reaction that keeps the element in equilibrium.
struct MultiPointForce {
  long id = 0;
  std::vector<int> iMarkers;
  int jMarker = -1;
  Eigen::MatrixXd stiffness, damping;  // 6n x 6n
  Eigen::VectorXd length, preload;     // 6n
  SourceLocation where;
};

// ---- User equations (docs/theory.md §4a; model/user_equation_builder.cpp) ----

// VARIABLE: an algebraic unknown v with v = FUNCTION(...), read with VARVAL(id).
struct Variable {
  long id = 0;
  std::optional<double> ic;  // starting guess of the initial-condition solve
  BoundExpression function;
  SourceLocation where;
};

// DIFF: a state y with y' = FUNCTION (explicit) or 0 = FUNCTION(y, y', t) (IMPLICIT); DIF(id)
// reads y and DIF1(id) reads y'.
struct Diff {
  long id = 0;
  bool implicit = false;
  bool staticHold = false;
  double ic = 0.0;
  std::optional<double> icDerivative;  // IMPLICIT: starting guess for y'
  BoundExpression function;
  SourceLocation where;
};

// ARRAY: X (the states of one LSE or TFSISO), U (VARIABLEs read as inputs), Y (outputs of one
// LSE or TFSISO), IC or plain constants (NUMBERS).
struct DataArray {
  enum class Kind { X, U, Y, IC, Constants };
  long id = 0;
  Kind kind = Kind::Constants;
  std::vector<int> variables;  // U: indices into Model::variables
  std::vector<double> numbers; // IC and constants
  int size = 0;
  int owner = -1;              // X and Y: index into Model::linearStates
  // X and Y of a GSE instead (owner stays -1): index into Model::generalStates; `discrete`
  // for its XD array (the discrete states).
  int gse = -1;
  bool discrete = false;
  SourceLocation where;
};

// LSE and TFSISO (as its controllable canonical state-space form): x' = A x + B u,
// y = C x + D u, with u the VARIABLEs of the U array.
struct LinearStateElement {
  enum class Kind { Lse, Tfsiso };
  long id = 0;
  Kind kind = Kind::Lse;
  int xArray = -1, uArray = -1, yArray = -1;  // indices into Model::arrays (-1 = none)
  Eigen::MatrixXd a, b, c, d;  // b: states x inputs, c: outputs x states, d: outputs x inputs
  Eigen::VectorXd ic;          // initial states (zero unless LSE IC=)
  bool staticHold = false;
  int firstState = -1;  // index of x(1) among the user differential states (after the DIFFs)
  SourceLocation where;
};

// GSE (docs/theory.md, "GSE"): x' = f(x, xd, u, t), y = g(x, xd, u, t) from user-written
// routines (user/gse_routines.hpp); xd = h(x, xd, u, t) at sample times, constant between.
// The x are user differential states, the y user algebraic unknowns; xd lives here.
struct GeneralStateElement {
  long id = 0;
  int ns = 0, nd = 0, ni = 0, no = 0;
  int xArray = -1, xdArray = -1, uArray = -1, yArray = -1;  // indices into Model::arrays
  Eigen::VectorXd ic, icd;  // initial continuous and discrete states (zero unless IC=, ICD=)
  bool staticHold = false;
  std::optional<expr::Expression> samplePeriod;  // SAMPLE_PERIOD (a function of TIME)
  std::shared_ptr<const user::GseRoutines> routines;
  int firstState = -1;   // index of x(1) among the user differential states (after LSEs)
  int firstOutput = -1;  // index of y(1) among the user algebraic unknowns (after DIFFs)
  // The discrete states and the time of the last sample are run-time values: the run state's
  // (mechanics/expression_run_state.hpp), starting at ICD and time 0.
  SourceLocation where;
};

// PINPUT / POUTPUT: ordered lists of VARIABLEs (indices into Model::variables).
struct PlantVariables {
  long id = 0;
  std::vector<int> variables;
  SourceLocation where;
};

// ---- SENSOR (model/sensor_builder.cpp; analysis/sensor_monitor.hpp; docs/theory.md,
// "Sensors") ----
// An event on FUNCTION compared with VALUE: EQ holds while |f - VALUE| <= ERROR, GE while
// f >= VALUE, LE while f <= VALUE. The sensor acts when its test starts to hold.
struct Sensor {
  enum class Test { Eq, Ge, Le };
  long id = 0;
  BoundExpression function;
  double value = 0.0;
  Test test = Test::Eq;
  double error = 1e-3;     // ERROR: absolute tolerance on the function (ADAMS default 0.001)
  bool bisection = false;  // BISECTION: locate the event by bisection (else Illinois secant)
  bool halt = false;       // HALT: the run ends at the event
  bool print = false;      // PRINT: an output step at the event
  bool restart = false;    // RESTART: the integrator restarts at the event (order 1)
  bool returnToCommands = false;           // RETURN: the SIMULATE command ends at the event
  std::optional<double> outputInterval;    // DT: the output interval from the event on
  std::optional<double> stepSize;          // STEPSIZE: the first step after the event
  // EVALUATE: stored at the event in the run state (ExpressionRunState::sensorValue), read by
  // SENVAL (0 before any event).
  std::optional<BoundExpression> evaluate;
  SourceLocation where;
};

struct Request {
  enum class Kind { Displacement, Velocity, Acceleration, Force, Expressions };
  long id = 0;
  Kind kind = Kind::Expressions;
  int iMarker = -1;
  int jMarker = -1;  // -1: ground origin
  int rmMarker = -1; // -1: ground axes
  std::array<std::optional<BoundExpression>, 8> columns;  // F1..F8 for Kind::Expressions
  std::string comment;
  SourceLocation where;
};

// ---- Data elements: SPLINE, CURVE, MATRIX, STRING (model/data_element_builder.cpp) ----
// The interpolants are shared with the expressions that call them (AKISPL, CUBSPL, CURVE).
struct SplineData {
  long id = 0;
  std::shared_ptr<const Spline> spline;
  SourceLocation where;
};
struct CurveData {
  long id = 0;
  long matrixId = 0;
  std::shared_ptr<const BSplineCurve> curve;
  SourceLocation where;
};
struct MatrixData {
  long id = 0;
  Eigen::MatrixXd values;  // ROWS x COLUMNS
  SourceLocation where;
};
struct StringData {
  long id = 0;
  std::string text;
  SourceLocation where;
};

struct OutputSettings {
  bool reqsave = false;
  bool grsave = false;
  bool noseparator = false;
};

// DEBUG statement and command: EPRINT writes the integrator's per-step and per-iteration
// diagnostics to the .msg (analysis/eprint_log.hpp).
struct DebugSettings {
  bool eprint = false;
};

struct Model {
  std::string title;
  std::string file;
  // The line of every statement of the data set that has an id, built or refused: a function
  // naming an element whose statement was refused says so instead of "does not exist"
  // (model_builder.cpp, bindParsedExpression).
  std::map<std::pair<std::string, long>, int> statementLines;
  Units units;
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  std::vector<Part> parts;
  std::vector<Marker> markers;
  std::vector<Joint> joints;
  std::vector<Motion> motions;
  std::vector<JPrim> jprims;
  std::vector<Coupler> couplers;  // COUPLER
  std::vector<Gear> gears;        // GEAR
  std::vector<GeneralConstraint> gcons;  // GCON
  std::vector<UserConstraint> ucons;     // UCON
  std::vector<PointCurve> ptcvs;         // PTCV (point_curve_builder.cpp)
  std::vector<CurveCurve> cvcvs;         // CVCV (curve_curve_builder.cpp)
  std::vector<SForce> sforces;
  std::vector<SpringDamper> springDampers;
  std::vector<LinearField> linearFields;  // BUSHING, FIELD, BEAM
  std::vector<VectorForce> vectorForces;  // VFORCE, VTORQUE, GFORCE
  std::vector<Friction> frictions;        // FRICTION (joint friction)
  std::vector<MultiPointForce> nforces;   // NFORCE
  std::vector<Contact> contacts;          // CONTACT (contact_builder.cpp)
  // User equations: VARIABLE, DIFF, ARRAY, LSE/TFSISO, PINPUT, POUTPUT.
  std::vector<Variable> variables;
  std::vector<Diff> diffs;
  std::vector<DataArray> arrays;
  std::vector<LinearStateElement> linearStates;
  std::vector<GeneralStateElement> generalStates;  // GSE
  std::vector<PlantVariables> pinputs, poutputs;
  std::vector<Request> requests;
  std::vector<Sensor> sensors;  // SENVAL(id) measures index this list
  // Data elements (data_element_builder.cpp); the maps give the index of each id.
  std::vector<SplineData> splines;
  std::vector<CurveData> curves;
  std::vector<MatrixData> matrices;
  std::vector<StringData> strings;
  std::map<long, int> splineIndex, curveIndex, matrixIndex, stringIndex;
  OutputSettings output;
  DebugSettings debug;  // DEBUG statement (EPRINT)
  EquilibriumSettings equilibrium;            // EQUILIBRIUM statement (and command)
  InitialConditionSettings initialConditions;  // IC statement (and command)
  IntegratorSettings integrator;               // INTEGRATOR statement (and command)
  KinematicSettings kinematics;                // KINEMATICS statement (and command)
  std::vector<int> movingParts;  // part index of each moving body, in state order
  int groundPart = -1;

  std::map<long, int> partIndex, markerIndex, jointIndex;
  std::map<long, int> jprimIndex;

  // MODE, HSIZE, ORDER, NJAC, NRHS are run-time values: the run state's
  // (ExpressionRunState::status, mechanics/expression_run_state.hpp).

  int bodyCount() const { return static_cast<int>(movingParts.size()); }
  // User states (mechanics/state_layout.hpp): differential ones are the DIFF states, then the
  // states of each LSE/TFSISO, then of each GSE; algebraic ones the VARIABLEs, then each
  // DIFF's derivative, then each GSE's outputs.
  int userDifferentialCount() const {
    int n = static_cast<int>(diffs.size());
    for (const auto& e : linearStates) n += static_cast<int>(e.a.rows());
    for (const auto& e : generalStates) n += e.ns;  // GSE states after them
    return n;
  }
  int userAlgebraicCount() const {
    int n = static_cast<int>(variables.size() + diffs.size());
    for (const auto& e : generalStates) n += e.no;  // GSE outputs after the DIFF derivatives
    return n;
  }
};

}  // namespace openmss::model
