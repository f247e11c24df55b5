// The data-set statement table. Argument lists follow the statement pages of the ADAMS/Solver
// Reference Manual and the spellings found in real exported data sets; where the manual is
// silent the list is a reasonable, documented choice (docs/language.md, "Schema").
// Minimum abbreviations are left at 0 (automatic: the shortest unique prefix among the
// statement's arguments) unless a real spelling needs a shorter one.

#include "language/statement_table.hpp"

#include "language/schema_builder.hpp"

namespace openmss::language {

using namespace schema_builder;

namespace {

const std::vector<std::string> kYesNo = {"ON", "OFF"};
const std::vector<std::string> kTrueFalse = {"T", "F", "TRUE", "FALSE"};

// The user-subroutine escape shared by many elements: FUNCTION=USER(...) is an expression,
// ROUTINE names the library and subroutine.
ArgumentSpec routine() { return word("ROUTINE"); }

// Body orientation and initial velocity shared by PART, POINT_MASS and FLEX_BODY.
std::vector<ArgumentSpec> bodyPlacement() {
  return {triple("QG"),  triple("REULER").alias("EU"),
          triple("XG"),  triple("ZG"),
          real("VX"),    real("VY"),
          real("VZ"),    real("WX"),
          real("WY"),    real("WZ"),
          integer("VM"), integer("WM")};
}

std::vector<ArgumentSpec> solverPattern() { return {word("PATTERN", kTrueFalse, 1, 10)}; }

}  // namespace

std::vector<ArgumentSpec> integratorArguments() {
  std::vector<ArgumentSpec> a = {flag("GSTIFF"),
                                 flag("WSTIFF"),
                                 flag("CONSTANT_BDF"),
                                 flag("ABAM"),
                                 // OpenMSS extension: explicit Kutta-Merson on the index-1
                                 // equations (docs/integrators.md, "MERSON").
                                 flag("MERSON"),
                                 flag("HASTIFF"),
                                 flag("HHT"),
                                 flag("NEWMARK"),
                                 flag("DSTIFF"),
                                 flag("CPBDF"),
                                 flag("SI2_GSTIFF"),
                                 flag("I3"),
                                 flag("SI2"),
                                 flag("SI1"),
                                 real("ERROR"),
                                 real("HINIT"),
                                 real("HMAX"),
                                 real("HMIN"),
                                 integer("KMAX"),
                                 integer("MAXIT"),
                                 word("INTERPOLATE", kYesNo),
                                 real("ADAPTIVITY"),
                                 word("CORRECTOR", {"ORIGINAL", "MODIFIED", "ORIG_CONSTANT"}),
                                 real("ALPHA"),
                                 real("BETA"),
                                 real("GAMMA"),
                                 real("SCALE"),
                                 real("REPARTITION_THRESHOLD"),
                                 integer("FIXED_ITERATIONS"),
                                 integer("HRATIO"),
                                 real("MAX_ERROR"),
                                 flag("DEFAULT")};
  append(a, solverPattern());
  return a;
}

std::vector<ArgumentSpec> equilibriumArguments() {
  std::vector<ArgumentSpec> a = {real("ALIMIT"),
                                 real("ERROR"),
                                 real("IMBALANCE"),
                                 integer("MAXIT"),
                                 real("STABILITY"),
                                 real("TLIMIT"),
                                 flag("DEFAULT"),
                                 flag("DYNAMIC"),
                                 flag("STATIC"),
                                 real("ACCELERATION_ERROR"),
                                 real("KINETIC_ENERGY_ERROR"),
                                 real("GLOBAL_DAMPING"),
                                 real("SETTLING_TIME"),
                                 word("METHOD")};
  append(a, solverPattern());
  return a;
}

std::vector<ArgumentSpec> icArguments() {
  return {real("AERROR"),
          real("ALIMIT"),
          integer("AMAXIT"),
          word("APATTERN", kTrueFalse, 1, 10),
          real("ERROR"),
          integer("MAXIT"),
          word("PATTERN", kTrueFalse, 1, 10),
          real("TLIMIT"),
          real("VERROR"),
          flag("DEFAULT")};
}

std::vector<ArgumentSpec> kinematicsArguments() {
  return {real("ERROR"),
          real("TLIMIT"),
          real("ALIMIT"),
          integer("MAXIT"),
          real("AERROR"),
          integer("AMAXIT"),
          word("PATTERN", kTrueFalse, 1, 10),
          word("APATTERN", kTrueFalse, 1, 10),
          real("HMAX"),
          flag("DEFAULT")};
}

// Over ~150 lines by intent: a table, one entry per data-set statement, read top to bottom.
std::vector<StatementSpec> buildStatementTable() {
  std::vector<StatementSpec> t;
  const auto R = IdRule::Required;
  const auto N = IdRule::NotAllowed;

  // --- Title and end ---------------------------------------------------------------------
  t.push_back(statement("TITLE", N, {}));
  t.push_back(statement("END", N, {}));

  // --- Inertia and reference frames ----------------------------------------------------------
  {
    std::vector<ArgumentSpec> a = {
        flag("GROUND"),   real("MASS"),
        integer("CM"),    integer("IM"),
        real("IP", 3, 6), word("EXACT", {"X", "Y", "Z", "PSI", "THETA", "PHI"}, 1, 6),
        word("MATERIAL"), flag("PLANAR")};
    append(a, bodyPlacement());
    t.push_back(statement("PART", R, a));
  }
  t.push_back(statement(
      "MARKER", R,
      {integer("PART"), integer("POINT_MASS"), integer("FLEX_BODY"), integer("NODE"),
       integer("FE_PART"), integer("NODE_LABEL"), triple("QP"), triple("REULER").alias("EU"),
       triple("XP"), triple("ZP"), flag("USEXP"), integer("RM"), flag("FLOATING")}));
  {
    std::vector<ArgumentSpec> a = {real("MASS"), integer("CM"),
                                   word("EXACT", {"X", "Y", "Z"}, 1, 3)};
    append(a, bodyPlacement());
    t.push_back(statement("POINT_MASS", R, a));
  }
  {
    // Not in the Reference Manual: modal flexible bodies as exported by ADAMS/View.
    std::vector<ArgumentSpec> a = {integers("MATRICES"),    word("INVARIANTS", kTrueFalse, 1, 9),
                                   expression("CRATIO"),    word("MNF_FILE"),
                                   word("DB_FILE"),         integer("INDEX"),
                                   word("EXACT", {}, 1, 6), word("DYNAMIC_LIMIT"),
                                   word("STABILITY_FACTOR")};
    append(a, bodyPlacement());
    t.push_back(statement("FLEX_BODY", R, a));
  }
  t.push_back(
      statement("MATERIAL", R,
                {word("NAME"), real("DENSITY"), real("YOUNGS_MODULUS"), real("POISSONS_RATIO")}));
  t.push_back(
      statement("FE_PART", R,
                {word("TYPE"), integers("NODE_LABELS"), reals("COORDINATES"), reals("SECTION"),
                 wordOrNumber("MATERIAL"), real("CRATIOK"), real("CRATIOM"), flag("GROUND")}));
  t.push_back(statement("FE_NODE", R,
                        {integer("FE_PART"), integer("LABEL"), real("S"), real("ANGLE"),
                         integer("SECTION_NODE"), triple("QG"), triple("REULER").alias("EU")}));
  t.push_back(statement(
      "SECTION", R,
      {text("TYPE"), real("RECT_BASE"), real("RECT_HEIGHT"), real("IYY"), real("IZZ"), real("IYZ"),
       real("JXX"), real("AREA"), real("RADIUS"), real("INNER_RADIUS"), real("OUTER_RADIUS")}));

  // --- Geometry ----------------------------------------------------------------------------
  t.push_back(statement("GRAPHICS", R,
                        {flag("ARC"),
                         flag("BOX"),
                         flag("CIRCLE"),
                         flag("CYLINDER"),
                         flag("FRUSTUM"),
                         integers("OUTLINE"),
                         flag("SPDP"),
                         flag("TORUS"),
                         flag("FORCE"),
                         flag("POINT"),
                         flag("PLANE"),
                         flag("ELLIPSOID"),
                         flag("EXTERNAL"),
                         flag("CURVE"),
                         integer("CM"),
                         integer("CID"),
                         integer("CRM"),
                         real("RADIUS"),
                         real("RANGLE"),
                         integer("SEG"),
                         integer("SIDES"),
                         real("LENGTH"),
                         real("TOP"),
                         real("BOTTOM"),
                         integer("CORNER"),
                         real("X"),
                         real("Y"),
                         real("Z"),
                         real("XSCALE"),
                         real("YSCALE"),
                         real("ZSCALE"),
                         integer("I"),
                         integer("J"),
                         real("DA"),
                         real("DB"),
                         real("DC"),
                         real("DD"),
                         integer("COILS"),
                         word("FILE"),
                         word("ELEMENT"),
                         integer("RM"),
                         word("ETYPE"),
                         integer("EID"),
                         integer("EMARKER"),
                         real("FACETING_TOLERANCE"),
                         real("MAJOR_RADIUS"),
                         real("MINOR_RADIUS"),
                         real("XMIN"),
                         real("XMAX"),
                         real("YMIN"),
                         real("YMAX")}));

  // --- Constraints -----------------------------------------------------------------------
  t.push_back(statement(
      "JOINT", R,
      {integer("I").mandatory(), integer("J").mandatory(), flag("CONVEL"), flag("CYLINDRICAL"),
       flag("FIXED"), flag("HOOKE"), flag("PLANAR"), flag("RACKPIN"), flag("REVOLUTE"),
       flag("SCREW"), flag("SPHERICAL"), flag("TRANSLATIONAL"), flag("UNIVERSAL"), real("PD"),
       real("PITCH"), real("IC", 1, 2), real("ICTRAN", 1, 2), real("ICROT", 1, 2),
       // Joint friction written inline by ADAMS/View exports.
       real("DELTA_V"), real("MAXIMUM_DEFORMATION"), real("MU_DYN_ROT"), real("MU_STAT_ROT"),
       real("MAX_FRIC_ROT"), real("MU_DYN_TRANS"), real("MU_STAT_TRANS"), real("MAX_FRIC_TRANS"),
       real("PRELOAD_RADIAL"), real("PRELOAD_AXIAL"), real("INNER_RADIUS"), real("OUTER_RADIUS"),
       real("PIN_RADIUS"), real("BALL_RADIUS"), real("FRICTION_ARM"), real("REACTION_ARM"),
       word("FRICTION", {"ON", "OFF", "PRELOAD_ONLY"}),
       word("OVERLAP_DELTA", {"INCREASE", "DECREASE", "CONSTANT"})}));
  t.push_back(statement(
      "JPRIM", R,
      {integer("I").mandatory(), integer("J").mandatory(), flag("ATPOINT"), flag("INLINE"),
       flag("INPLANE"), flag("ORIENTATION"), flag("PARALLEL_AXES"), flag("PERPENDICULAR")}));
  t.push_back(statement("MOTION", R,
                        {integer("JOINT"), flag("TRANSLATION").alias("TRANSLATIONAL"),
                         flag("ROTATION").alias("ROTATIONAL"), integer("I"), integer("J"),
                         flag("X"), flag("Y"), flag("Z"), flag("B1"), flag("B2"), flag("B3"),
                         expression("FUNCTION"), routine(), flag("DISPLACEMENT"), flag("VELOCITY"),
                         flag("ACCELERATION"), real("ICDISP"), real("ICVEL")}));
  t.push_back(statement("GEAR", R, {integer("JOINTS", 2, 2), integer("CV")}));
  t.push_back(statement("COUPLER", R,
                        {integer("JOINTS", 2, 3), word("TYPE", {"T", "R"}, 2, 3),
                         real("SCALES", 1, 3), expression("FUNCTION"), words("ROUTINE", 3)}));
  t.push_back(statement("PTCV", R,
                        {integer("I"), integer("JFLOAT"), integer("CURVE"), integer("RM"),
                         triple("DISP"), integer("ICM"), real("VEL")}));
  t.push_back(statement("CVCV", R,
                        {integer("ICURVE"), integer("IRM"), integer("IFLOAT"), integer("JCURVE"),
                         integer("JRM"), integer("JFLOAT"), triple("IDISP"), triple("JDISP"),
                         integer("IICM"), integer("JICM"), real("IVEL"), real("JVEL")}));
  t.push_back(statement("UCON", R, {integers("VARIABLES"), expression("FUNCTION"), routine()}));
  t.push_back(
      statement("GCON", R, {expression("FUNCTION"), integer("I"), integer("J"), routine()}));

  // --- Forces ------------------------------------------------------------------------------
  t.push_back(statement("ACCGRAV", N, {real("IGRAV"), real("JGRAV"), real("KGRAV")}));
  t.push_back(statement(
      "SFORCE", R,
      {integer("I").mandatory(), integer("J").mandatory(),
       flag("TRANSLATION").alias("TRANSLATIONAL"), flag("ROTATION").alias("ROTATIONAL"),
       flag("ACTIONONLY"), flag("REACTION"), expression("FUNCTION").mandatory(), routine()}));
  t.push_back(
      statement("SPRINGDAMPER", R,
                {integer("I").mandatory(), integer("J").mandatory(),
                 flag("TRANSLATIONAL").alias("TRANSLATION"), flag("ROTATIONAL").alias("ROTATION"),
                 real("K"), real("C"), real("KT"), real("CT"), real("LENGTH"), real("FORCE"),
                 real("ANGLE"), real("TORQUE")}));
  t.push_back(
      statement("BUSHING", R,
                {integer("I").mandatory(), integer("J").mandatory(), triple("K"), triple("C"),
                 triple("KT"), triple("CT"), triple("FORCE"), triple("TORQUE")}));
  t.push_back(
      statement("FIELD", R,
                {integer("I").mandatory(), integer("J").mandatory(), real("KMATRIX", 36, 36),
                 real("CMATRIX", 36, 36), real("CRATIO"), real("LENGTH", 6, 6), real("FORCE", 6, 6),
                 expression("FUNCTION"), routine()}));
  t.push_back(statement("BEAM", R,
                        {integer("I").mandatory(), integer("J").mandatory(), real("LENGTH"),
                         real("AREA"), real("IXX"), real("IYY"), real("IZZ"), real("EMODULUS"),
                         real("GMODULUS"), real("ASY"), real("ASZ"), real("CMATRIX", 21, 21),
                         real("CRATIO"), word("FORMULATION", {"LINEAR", "STRING", "NONLINEAR"})}));
  t.push_back(statement(
      "VFORCE", R,
      {integer("I").mandatory(), integer("JFLOAT").mandatory(), integer("RM"), expression("FX"),
       expression("FY"), expression("FZ"), expression("FUNCTION"), routine()}));
  t.push_back(statement(
      "VTORQUE", R,
      {integer("I").mandatory(), integer("JFLOAT").mandatory(), integer("RM"), expression("TX"),
       expression("TY"), expression("TZ"), expression("FUNCTION"), routine()}));
  t.push_back(statement("GFORCE", R,
                        {integer("I").mandatory(), integer("JFLOAT").mandatory(), integer("RM"),
                         expression("FX"), expression("FY"), expression("FZ"), expression("TX"),
                         expression("TY"), expression("TZ"), expression("FUNCTION"), routine()}));
  t.push_back(statement("NFORCE", R,
                        {integer("IMARKERS", 1, 350), integer("J"), integer("KMATRIX"),
                         integer("CMATRIX"), real("CRATIO"), integer("LENGTH"), integer("FORCE")}));
  t.push_back(
      statement("MFORCE", R,
                {integer("FLEX_BODY"), integer("JFLOAT"), expression("CASE_INDEX"),
                 expression("SCALE"), integer("FORCE"), expression("FUNCTION"), routine()}));
  t.push_back(statement("CONTACT", R,
                        {integers("IGEOM"),
                         integers("JGEOM"),
                         integer("ICURVE"),
                         integer("JCURVE"),
                         integers("IFLIP_GEOMETRY"),
                         integers("JFLIP_GEOMETRY"),
                         flag("IMPACT"),
                         flag("POISSON"),
                         real("STIFFNESS"),
                         real("DAMPING"),
                         real("DMAX"),
                         real("EXPONENT"),
                         real("PENALTY"),
                         real("RESTITUTION_COEFFICIENT"),
                         flag("AUGMENTED_LAGRANGIAN_FORMULATION"),
                         word("COULOMB_FRICTION", {"ON", "OFF", "DYNAMICS_ONLY"}),
                         real("MU_STATIC"),
                         real("MU_DYNAMIC"),
                         real("STICTION_TRANSITION_VELOCITY"),
                         real("FRICTION_TRANSITION_VELOCITY"),
                         word("TYPE"),
                         real("FACETING_TOLERANCE"),
                         expression("NORMAL_FUNCTION"),
                         expression("FRICTION_FUNCTION"),
                         word("NORMAL_ROUTINE"),
                         word("FRICTION_ROUTINE")}));
  t.push_back(statement(
      "FRICTION", R,
      {integer("JOINT"), real("MU_STATIC"), real("MU_DYNAMIC"),
       real("STICTION_TRANSITION_VELOCITY"), real("MAX_STICTION_DEFORMATION"),
       real("FRICTION_FORCE_PRELOAD"), real("FRICTION_ARM"), real("BENDING_REACTION_ARM"),
       real("BALL_RADIUS"), real("PIN_RADIUS"), real("INITIAL_OVERLAP"),
       word("EFFECT", {"ALL", "STICTION", "SLIDING"}),
       word("INPUTS",
            {"ALL", "NONE", "PRELOAD", "REACTION_FORCE", "BENDING_MOMENT", "TORSIONAL_MOMENT"}, 1,
            4),
       word("INACTIVE", {"STATIC"})}));
  t.push_back(statement("FE_LOAD", R,
                        {integer("FE_PART"), integer("NODE_LABEL"), integer("RM"), expression("FX"),
                         expression("FY"), expression("FZ"), expression("TX"), expression("TY"),
                         expression("TZ"), expression("FUNCTION"), routine()}));
  t.push_back(statement("CLEARANCE", R, {integers("IGEOM"), integers("JGEOM"), real("THRESHOLD")}));

  // --- System elements ---------------------------------------------------------------------
  t.push_back(
      statement("VARIABLE", R, {expression("FUNCTION").mandatory(), real("IC"), routine()}));
  t.push_back(statement("DIFF", R,
                        {expression("FUNCTION").mandatory(), real("IC", 1, 2), flag("IMPLICIT"),
                         flag("STATIC_HOLD"), routine()}));
  t.push_back(statement("LSE", R,
                        {integer("X"), integer("A"), integer("B"), integer("U"), integer("C"),
                         integer("Y"), integer("D"), integer("IC"), flag("STATIC_HOLD")}));
  t.push_back(statement("GSE", R,
                        {integer("X"), integer("XD"), integer("U"), integer("Y"), integer("IC"),
                         integer("ICD"), integer("NS"), integer("ND"), integer("NO"),
                         expression("SAMPLE_PERIOD"), expression("FUNCTION"), routine(),
                         words("INTERFACE", 6), flag("STATIC_HOLD"), flag("IMPLICIT")}));
  t.push_back(statement("TFSISO", R,
                        {integer("X"), integer("U"), integer("Y"), real("NUMERATOR", 1, 30),
                         real("DENOMINATOR", 1, 30), flag("STATIC_HOLD")}));

  // --- Data elements -----------------------------------------------------------------------
  t.push_back(statement("ARRAY", R,
                        {flag("X"), flag("U"), flag("Y"), flag("IC"), integer("SIZE"),
                         integers("VARIABLES"), reals("NUMBERS")}));
  t.push_back(
      statement("CURVE", R,
                {integer("MATRIX"), flag("CURVE_POINTS"), integer("ORDER"), expression("FUNCTION"),
                 real("MINPAR"), real("MAXPAR"), flag("CLOSED"), flag("OPEN"), routine()}));
  t.push_back(statement(
      "MATRIX", R,
      {word("FULL", {"RORDER", "CORDER"}), flag("SPARSE"), integer("ROWS"), integer("COLUMNS"),
       integers("I"), integers("J"), reals("VALUES"), word("FILE"), word("NAME")}));
  t.push_back(statement("PINPUT", R, {integers("VARIABLES")}));
  t.push_back(statement("POUTPUT", R, {integers("VARIABLES")}));
  t.push_back(statement("SPLINE", R,
                        {reals("X"), reals("Y"), flag("LINEAR_EXTRAPOLATE"), word("FILE"),
                         word("BLOCK"), integer("CHANNEL"), routine()}));
  t.push_back(statement("STRING", R, {text("STRING")}));
  t.push_back(statement("SURFACE", R,
                        {expression("FUNCTION"), routine(), real("MINPAR", 2, 2),
                         real("MAXPAR", 2, 2), flag("UCLOSED"), flag("VCLOSED")}));

  // --- Analysis parameters -----------------------------------------------------------------
  t.push_back(statement("DEBUG", N,
                        {flag("EPRINT"), flag("DUMP"), flag("JMDUMP"), flag("RHSDUMP"),
                         flag("REQDUMP"), flag("VERBOSE"), flag("DOF"), flag("TOPOLOGY")}));
  t.push_back(statement("ENVIRONMENT", N, {word("NAME"), wordOrNumber("VALUE")}));
  t.push_back(statement("EQUILIBRIUM", N, equilibriumArguments()));
  t.push_back(statement("IC", N, icArguments()));
  t.push_back(statement("INTEGRATOR", N, integratorArguments()));
  t.push_back(statement("KINEMATICS", N, kinematicsArguments()));
  t.push_back(
      statement("LSOLVER", N, {flag("CALAHAN"), flag("HARWELL"), flag("UMF"), real("STABILITY")}));
  t.push_back(statement("PREFERENCES", N,
                        {real("CONTACT_FACETING_TOLERANCE"), integer("NTHREADS"),
                         word("CONTACT_GEOMETRY_LIBRARY"), word("FLEX_LIMIT_CHECK"),
                         word("SIMFAIL"), word("STATUS_MESSAGE", kYesNo), word("SOLVERBIAS")}));
  t.push_back(
      statement("SENSOR", R,
                {expression("FUNCTION").mandatory(), real("VALUE"), flag("EQ"), flag("GE"),
                 flag("LE"), real("ERROR"), flag("BISECTION"), flag("CODGEN"), real("DT"),
                 flag("HALT"), flag("PRINT"), flag("RESTART"), flag("RETURN"), real("STEPSIZE"),
                 flag("YYDUMP"), expression("EVALUATE"), routine(), word("EVALUATE_ROUTINE")}));
  t.push_back(statement(
      "UNITS", N,
      {word("FORCE", {"CENTINEWTON", "DYNE", "KILOGRAM_FORCE", "KNEWTON", "KPOUND_FORCE",
                      "MEGANEWTON", "MICRONEWTON", "MILLINEWTON", "NANONEWTON", "NEWTON",
                      "OUNCE_FORCE", "POUND_FORCE", "POUNDAL"}),
       word("MASS", {"GRAM", "KILOGRAM", "KPOUND_MASS", "MILLIGRAM", "MICROGRAM", "NANOGRAM",
                     "OUNCE_MASS", "POUND_MASS", "SLINCH", "SLUG", "TONNE", "US_TON"}),
       word("LENGTH", {"ANGSTROM", "CENTIMETER", "FOOT", "KILOMETER", "INCH", "METER", "MICROINCH",
                       "MICROMETER", "MILE", "MILLIMETER", "MILS", "NANOMETER", "YARD"}),
       word("TIME", {"DAY", "HOUR", "MICROSECOND", "MILLISECOND", "MILLISECONDS", "MINUTE",
                     "NANOSECOND", "SECOND"}),
       word("SYSTEM", {"CGS", "FPS", "IPS", "MKS", "NONE"}), real("UCF")}));

  // --- Output ------------------------------------------------------------------------------
  t.push_back(
      statement("FEMDATA", R,
                {flag("LOADS"), flag("MODAL_ENERGY"), flag("NODAL_DEFORMATION"), flag("STRAIN"),
                 flag("STRESS"), integer("RM"), integer("FLEX_BODY"), real("START"), real("END"),
                 word("FILE"), word("FORMAT"), integer("SKIP")}));
  t.push_back(statement("LIST", N, {}));
  t.push_back(statement("NOLIST", N, {}));
  t.push_back(
      statement("MREQUEST", R,
                {flag("DISPLACEMENT"), flag("VELOCITY"), flag("ACCELERATION"), flag("FORCE"),
                 wordOrNumber("PART", 1, kUnlimited), wordOrNumber("JOINT", 1, kUnlimited),
                 wordOrNumber("JPRIM", 1, kUnlimited), wordOrNumber("MOTION", 1, kUnlimited),
                 wordOrNumber("APPFOR", 1, kUnlimited), wordOrNumber("SFORCE", 1, kUnlimited),
                 integer("RM"), text("COMMENT"), text("TITLE")}));
  t.push_back(
      statement("OUTPUT", N,
                {flag("REQSAVE"), flag("GRSAVE"), flag("NOSEPARATOR"), flag("SEPARATOR"),
                 flag("YPR"), flag("NOPRINT"), flag("TELETYPE"), flag("OSFORMAT"), real("DSCALE"),
                 real("ASCALE"), real("DZERO"), real("VZERO"), real("AZERO"), real("FZERO")}));
  {
    std::vector<ArgumentSpec> a = {
        // Single letters D, V, A, F are the spellings ADAMS/View exports write.
        flag("DISPLACEMENT").abbreviation(1), flag("VELOCITY").abbreviation(1),
        flag("ACCELERATION").abbreviation(1), flag("FORCE").abbreviation(1), integer("I"),
        integer("J"), integer("RM"), text("COMMENT").abbreviation(1), text("TITLE"),
        expression("FUNCTION").abbreviation(2), routine(),
        // ADAMS/View writes more than eight names (empty "" for unused columns).
        words("CNAMES"), words("CUNITS"), words("CLABELS"), word("RESULTS_NAME")};
    for (int k = 1; k <= 8; ++k) a.push_back(expression("F" + std::to_string(k)));
    t.push_back(statement("REQUEST", R, a));
  }
  t.push_back(
      statement("RESULTS", N,
                {flag("XRF"), flag("FORMATTED"), text("COMMENT"), integer("DECIMALPLACES"),
                 integer("SIGNIFICANTFIGURES"), real("ZEROTHRESHOLD"), flag("NOACCELERATIONS"),
                 flag("NOAPPLIEDFORCES"), flag("NOCONTACTS"), flag("NODATASTRUCTURES"),
                 flag("NODISPLACEMENTS"), flag("NOFLOATINGMARKERS"), flag("NOLINEAR"),
                 flag("NOREACTIONFORCES"), flag("NOREQUESTS"), flag("NOSYSTEMELEMENTS"),
                 flag("NOTIRES"), flag("NOVELOCITIES")}));
  return t;
}

}  // namespace openmss::language
