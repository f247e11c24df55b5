#pragma once
// A resolved host call of a function expression: which model quantity it reads. The model
// builder turns expr::HostCall (names and ids) into Measures (kinds and indices); the mechanics
// evaluates them.

namespace openmss::model {

enum class MeasureKind {
  Time,
  // Marker displacement measures (i relative to j, components in k axes).
  DX, DY, DZ, DM,
  // Velocity (time derivative in ground), components in k axes; VR the separation rate.
  VX, VY, VZ, VM, VR,
  // Angular velocity of i relative to j, components in k axes.
  WX, WY, WZ, WM,
  // Accelerations.
  ACCX, ACCY, ACCZ, ACCM, WDTX, WDTY, WDTZ, WDTM,
  // Angles of i relative to j.
  AX, AY, AZ, PSI, THETA, PHI, YAW, PITCH, ROLL,
  Orient,      // ORIENT(system, component, i, j): code in `code`, component in `component`
  IncludedAngle,  // INCANG(i, j, k): angle between the lines i->j and j->k (k in `k`)
  NetForce,    // FX FY FZ FM TX TY TZ TM (i[, j][, k]): `component` 1..8 as for JOINT
  JointForce,  // JOINT(id, jflag, comp, rm)
  MotionForce, // MOTION(id, jflag, comp, rm)
  SForceForce, // SFORCE(id, jflag, comp, rm)
  JPrimForce,  // JPRIM(id, jflag, comp, rm)
  // Read-back of the other force elements, same signature as SFORCE; `element` indexes
  // Model::springDampers, linearFields (BUSH, FIELD, BEAM), vectorForces (VFORCE...) or
  // contacts (CONTACT).
  SpringDamperForce, BushingForce, FieldForce, BeamForce, VForceForce, VTorqueForce,
  GForceForce,
  // FRICTION(id, comp): `element` indexes Model::frictions, `component` 1..22 (ADAMS's
  // FFX..FTZ, coefficients, slip velocities, creep; mechanics/friction/friction_output.hpp).
  FrictionOutput,
  // NFORCE(id, marker, comp, rm): `element` indexes Model::nforces, `i` the marker (one of
  // its I markers or its J) whose force is read.
  NForceForce,
  // CONTACT(id, jflag, comp, rm): `element` indexes Model::contacts.
  ContactForce,
  // User equations (`element` indexes Model::variables, diffs, arrays, pinputs or poutputs;
  // `component` is the 1-based position for ARYVAL, PINVAL, POUVAL).
  VarVal, Dif, Dif1, AryVal, PinVal, PouVal,
  // SENVAL(id): the value SENSOR `element` (index into Model::sensors) stored at its last
  // event; constant between events (analysis/sensor_monitor.hpp).
  SenVal,
  // Analysis variables (model/analysis_status.hpp): MODE, HSIZE, ORDER, NJAC, NRHS. Constants
  // of the state, so their derivatives are zero.
  AnalysisMode, StepSize, IntegratorOrder, JacobianCount, ResidualCount,
};

// Accelerations and the reactions of joints, joint primitives and motions: force, VARIABLE and
// DIFF functions may read them (they are y' and multipliers of the DAE state;
// mechanics/dynamic_measures.hpp). Read-backs of force elements and FX..TM may not yet.
inline bool readsAccelerationOrReaction(MeasureKind kind) {
  switch (kind) {
    case MeasureKind::ACCX: case MeasureKind::ACCY: case MeasureKind::ACCZ:
    case MeasureKind::ACCM: case MeasureKind::WDTX: case MeasureKind::WDTY:
    case MeasureKind::WDTZ: case MeasureKind::WDTM: case MeasureKind::JointForce:
    case MeasureKind::MotionForce: case MeasureKind::JPrimForce:
      return true;
    default:
      return false;
  }
}

struct Measure {
  MeasureKind kind = MeasureKind::Time;
  int i = -1;  // marker index
  int j = -1;  // marker index, -1 = ground origin/axes
  int k = -1;  // resolution marker, -1 = ground axes
  // Derivative frame of VX..VZ, VM, VR, ACCX..ACCM, WDTX..WDTM (their l argument):
  // time derivatives are taken in this marker's frame, -1 = ground (docs/theory.md §11b).
  int l = -1;
  int element = -1;   // joint/motion/sforce index for force measures
  int atJ = 0;        // force measures: 0 = at I marker, 1 = at J marker
  int component = 0;  // force measures: 1..8; ORIENT: 1..4
  int code = 0;       // ORIENT system code
  // True when the value depends on accelerations or constraint forces: such measures may be
  // read by requests but not (yet) by force or motion functions.
  bool needsDynamics() const {
    switch (kind) {
      case MeasureKind::ACCX: case MeasureKind::ACCY: case MeasureKind::ACCZ:
      case MeasureKind::ACCM: case MeasureKind::WDTX: case MeasureKind::WDTY:
      case MeasureKind::WDTZ: case MeasureKind::WDTM: case MeasureKind::JointForce:
      case MeasureKind::MotionForce: case MeasureKind::SForceForce:
      case MeasureKind::JPrimForce:
      case MeasureKind::SpringDamperForce: case MeasureKind::BushingForce:
      case MeasureKind::FieldForce: case MeasureKind::BeamForce:
      case MeasureKind::VForceForce: case MeasureKind::VTorqueForce:
      case MeasureKind::GForceForce: case MeasureKind::NForceForce:
      case MeasureKind::FrictionOutput:
      case MeasureKind::ContactForce:
      case MeasureKind::NetForce:
        return true;
      default:
        return false;
    }
  }
};

}  // namespace openmss::model
