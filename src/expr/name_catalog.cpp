#include "expr/name_catalog.hpp"

#include <numbers>

namespace openmss::expr {
namespace {

constexpr double kDegreesToRadians = std::numbers::pi / 180.0;
constexpr double kRadiansToDegrees = 180.0 / std::numbers::pi;

NameInfo constantName(std::string_view name, double value) {
  return {name, NameKind::Constant, 0, 0, Builtin::Abs, value, name};
}

NameInfo builtin(std::string_view name, Builtin id, int minArgs, int maxArgs,
                 std::string_view usage) {
  return {name, NameKind::Builtin, minArgs, maxArgs, id, 0.0, usage};
}

NameInfo host(std::string_view name, int minArgs, int maxArgs, std::string_view usage) {
  return {name, NameKind::HostFunction, minArgs, maxArgs, Builtin::Abs, 0.0, usage};
}

NameInfo dataFunction(std::string_view name, int minArgs, int maxArgs, std::string_view usage) {
  return {name, NameKind::DataFunction, minArgs, maxArgs, Builtin::Abs, 0.0, usage};
}

NameInfo hostVariable(std::string_view name) {
  return {name, NameKind::HostVariable, 0, 0, Builtin::Abs, 0.0, name};
}

NameInfo unsupported(std::string_view name) {
  return {name, NameKind::Unsupported, 0, 0, Builtin::Abs, 0.0, name};
}

NameInfo vectorHost(std::string_view name, int maxArgs, std::string_view usage) {
  return {name, NameKind::VectorHost, 1, maxArgs, Builtin::Abs, 0.0, usage};
}

std::vector<NameInfo> buildCatalog() {
  std::vector<NameInfo> c;
  // Constants and TIME (docs/expressions.md, "Constants and TIME").
  c.push_back(constantName("PI", std::numbers::pi));
  c.push_back(constantName("DTOR", kDegreesToRadians));
  c.push_back(constantName("RTOD", kRadiansToDegrees));
  c.push_back({"TIME", NameKind::Time, 0, 0, Builtin::Abs, 0.0, "TIME"});

  // FORTRAN intrinsics (docs/expressions.md, "Functions evaluated here"). MAX and MIN accept two or
  // more arguments as in FORTRAN.
  c.push_back(builtin("ABS", Builtin::Abs, 1, 1, "ABS(a)"));
  c.push_back(builtin("SQRT", Builtin::Sqrt, 1, 1, "SQRT(a)"));
  c.push_back(builtin("EXP", Builtin::Exp, 1, 1, "EXP(a)"));
  c.push_back(builtin("LOG", Builtin::Log, 1, 1, "LOG(a)"));
  c.push_back(builtin("LOG10", Builtin::Log10, 1, 1, "LOG10(a)"));
  c.push_back(builtin("SIN", Builtin::Sin, 1, 1, "SIN(a)"));
  c.push_back(builtin("COS", Builtin::Cos, 1, 1, "COS(a)"));
  c.push_back(builtin("TAN", Builtin::Tan, 1, 1, "TAN(a)"));
  c.push_back(builtin("ASIN", Builtin::Asin, 1, 1, "ASIN(a)"));
  c.push_back(builtin("ACOS", Builtin::Acos, 1, 1, "ACOS(a)"));
  c.push_back(builtin("ATAN", Builtin::Atan, 1, 1, "ATAN(a)"));
  c.push_back(builtin("ATAN2", Builtin::Atan2, 2, 2, "ATAN2(y, x)"));
  c.push_back(builtin("SINH", Builtin::Sinh, 1, 1, "SINH(a)"));
  c.push_back(builtin("COSH", Builtin::Cosh, 1, 1, "COSH(a)"));
  c.push_back(builtin("TANH", Builtin::Tanh, 1, 1, "TANH(a)"));
  c.push_back(builtin("MAX", Builtin::Max, 2, kMaxBuiltinArguments, "MAX(a, b[, ...])"));
  c.push_back(builtin("MIN", Builtin::Min, 2, kMaxBuiltinArguments, "MIN(a, b[, ...])"));
  c.push_back(builtin("MOD", Builtin::Mod, 2, 2, "MOD(a, b)"));
  c.push_back(builtin("SIGN", Builtin::Sign, 2, 2, "SIGN(a, b)"));
  c.push_back(builtin("DIM", Builtin::Dim, 2, 2, "DIM(a, b)"));
  c.push_back(builtin("AINT", Builtin::Aint, 1, 1, "AINT(a)"));
  c.push_back(builtin("ANINT", Builtin::Anint, 1, 1, "ANINT(a)"));

  // General-purpose functions (docs/expressions.md, "Functions evaluated here"). Series take up to
  // 31 coefficients (order 30).
  c.push_back(builtin("STEP", Builtin::Step, 5, 5, "STEP(x, x0, h0, x1, h1)"));
  c.push_back(builtin("STEP5", Builtin::Step5, 5, 5, "STEP5(x, x0, h0, x1, h1)"));
  c.push_back(builtin("HAVSIN", Builtin::Havsin, 5, 5, "HAVSIN(x, x0, h0, x1, h1)"));
  c.push_back(builtin("SHF", Builtin::Shf, 6, 6, "SHF(x, x0, a, w, phi, b)"));
  c.push_back(builtin("POLY", Builtin::Poly, 3, 33, "POLY(x, x0, a0[, a1, ..., a30])"));
  c.push_back(builtin("CHEBY", Builtin::Cheby, 3, 33, "CHEBY(x, x0, a0[, a1, ..., a30])"));
  c.push_back(builtin("FORCOS", Builtin::Forcos, 4, 34, "FORCOS(x, x0, w, a0[, a1, ..., a30])"));
  c.push_back(builtin("FORSIN", Builtin::Forsin, 4, 34, "FORSIN(x, x0, w, a0[, a1, ..., a30])"));
  c.push_back(builtin("SWEEP", Builtin::Sweep, 7, 7, "SWEEP(x, a, x0, f0, x1, f1, dx)"));
  c.push_back(builtin("IMPACT", Builtin::Impact, 7, 7, "IMPACT(x, xdot, x1, k, e, cmax, d)"));
  c.push_back(builtin("BISTOP", Builtin::Bistop, 8, 8, "BISTOP(x, xdot, x1, x2, k, e, cmax, d)"));
  c.push_back({"IF", NameKind::Conditional, 4, 4, Builtin::Abs, 0.0, "IF(e1 : e2, e3, e4)"});

  // Marker measures (docs/expressions.md, "Host calls"): i [, j] [, k] [, l] with 0 as the
  // placeholder.
  for (std::string_view n : {"DX", "DY", "DZ"}) c.push_back(host(n, 1, 3, "(i[, j][, k])"));
  c.push_back(host("DM", 1, 2, "DM(i[, j])"));
  for (std::string_view n : {"VX", "VY", "VZ"}) c.push_back(host(n, 1, 4, "(i[, j][, k][, l])"));
  c.push_back(host("VM", 1, 3, "VM(i[, j][, l])"));
  c.push_back(host("VR", 1, 3, "VR(i[, j][, l])"));
  for (std::string_view n : {"WX", "WY", "WZ"}) c.push_back(host(n, 1, 3, "(i[, j][, k])"));
  c.push_back(host("WM", 1, 2, "WM(i[, j])"));
  for (std::string_view n : {"ACCX", "ACCY", "ACCZ"}) {
    c.push_back(host(n, 1, 4, "(i[, j][, k][, l])"));
  }
  c.push_back(host("ACCM", 1, 3, "ACCM(i[, j][, l])"));
  for (std::string_view n : {"WDTX", "WDTY", "WDTZ"}) {
    c.push_back(host(n, 1, 4, "(i[, j][, k][, l])"));
  }
  c.push_back(host("WDTM", 1, 3, "WDTM(i[, j][, l])"));
  for (std::string_view n : {"AX", "AY", "AZ", "PSI", "THETA", "PHI", "YAW", "PITCH", "ROLL"}) {
    c.push_back(host(n, 1, 2, "(i[, j])"));
  }
  c.push_back(host("ORIENT", 3, 4, "ORIENT(sys, comp, i[, j])"));
  c.push_back(host("INCANG", 3, 3, "INCANG(i, j, k)"));

  // Force measures (docs/expressions.md, "Host calls").
  for (std::string_view n : {"FX", "FY", "FZ", "FM", "TX", "TY", "TZ", "TM"}) {
    c.push_back(host(n, 1, 3, "(i[, j][, k])"));
  }
  for (std::string_view n : {"JOINT", "JPRIM", "MOTION", "SFORCE", "SPDP", "BUSH", "FIELD", "BEAM",
                             "VFORCE", "VTORQ", "GFORCE", "PTCV", "CVCV",
                             // CONTACT(id, jflag, comp, rm): the force of a CONTACT element, as
                             // real ADAMS/View data sets use it in SENSOR and DIFF functions.
                             "CONTACT"}) {
    c.push_back(host(n, 4, 4, "(id, jflag, comp, rm)"));
  }
  c.push_back(host("NFORCE", 4, 4, "NFORCE(id, marker, comp, rm)"));
  // FRICTION(id, index): the outputs of joint friction (docs/theory.md, "Joint friction").
  c.push_back(host("FRICTION", 2, 2, "FRICTION(id, index)"));

  // System-element access (docs/expressions.md, "Host calls").
  c.push_back(host("VARVAL", 1, 1, "VARVAL(id)"));
  c.push_back(host("DIF", 1, 1, "DIF(id)"));
  c.push_back(host("DIF1", 1, 1, "DIF1(id)"));
  c.push_back(host("ARYVAL", 2, 2, "ARYVAL(id, n)"));
  c.push_back(host("PINVAL", 2, 2, "PINVAL(id, n)"));
  c.push_back(host("POUVAL", 2, 2, "POUVAL(id, n)"));
  c.push_back(host("SENVAL", 1, 1, "SENVAL(id)"));

  // Analysis variables (docs/expressions.md, "Analysis variables").
  for (std::string_view n : {"MODE", "HSIZE", "ORDER", "NJAC", "NRHS", "CPU"}) {
    c.push_back(hostVariable(n));
  }

  // Interpolation of SPLINE and CURVE data (docs/expressions.md, "Interpolation of model data"):
  // real arguments are expressions, the id and the flags integer constants.
  c.push_back(dataFunction("AKISPL", 3, 4, "AKISPL(x, z, id[, iord])"));
  c.push_back(dataFunction("CUBSPL", 3, 4, "CUBSPL(x, z, id[, iord])"));
  c.push_back(dataFunction("CURVE", 4, 4, "CURVE(alpha, iord, comp, id)"));
  // INTERP reads a time-series SPLINE (degree 1 linear, 3 cubic); INVPSD regenerates a signal
  // from a PSD SPLINE (docs/expressions.md records where these definitions come from).
  c.push_back(dataFunction("INTERP", 3, 4, "INTERP(x, degree, id[, iord])"));
  c.push_back(dataFunction("INVPSD", 7, 7, "INVPSD(x, id, f0, f1, nf, linlog, seed)"));
  c.push_back({"USER", NameKind::User, 0, 30, Builtin::Abs, 0.0, "USER(r1[, ..., r30])"});

  // The value of an expression at an earlier time, from the history the run records
  // (docs/expressions.md, "DELAY").
  c.push_back({"DELAY", NameKind::Delay, 3, 4, Builtin::Abs, 0.0,
               "DELAY(e_delayed, e_delay, e_history[, 0])"});
  // Modal data or a definition that was not found (docs/expressions.md, "Recognised but not
  // supported yet").
  for (std::string_view n : {"AO", "FXFREQ", "FXMODE"}) c.push_back(unsupported(n));

  // Vectors (docs/expressions.md, "Vectors"): component triples of the host measures, MAG and UV.
  c.push_back(vectorHost("DXYZ", 3, "DXYZ(i[, j][, k])"));
  c.push_back(vectorHost("VXYZ", 4, "VXYZ(i[, j][, k][, l])"));
  c.push_back(vectorHost("WXYZ", 3, "WXYZ(i[, j][, k])"));
  c.push_back(vectorHost("ACCXYZ", 4, "ACCXYZ(i[, j][, k][, l])"));
  c.push_back(vectorHost("WDTXYZ", 4, "WDTXYZ(i[, j][, k][, l])"));
  c.push_back(vectorHost("FXYZ", 3, "FXYZ(i[, j][, k])"));
  c.push_back(vectorHost("TXYZ", 3, "TXYZ(i[, j][, k])"));
  c.push_back({"MAG", NameKind::VectorFunction, 1, 1, Builtin::Abs, 0.0, "MAG(v)"});
  c.push_back({"UV", NameKind::VectorFunction, 1, 1, Builtin::Abs, 0.0, "UV(v)"});
  // Marker-axis vectors and frame changes (ADAMS Solver C++ help, UVX and TRANS): expanded
  // into ORIENT(29, ...) direction cosines of the markers by the parser.
  c.push_back({"UVX", NameKind::VectorFunction, 1, 2, Builtin::Abs, 0.0, "UVX(i[, k])"});
  c.push_back({"UVY", NameKind::VectorFunction, 1, 2, Builtin::Abs, 0.0, "UVY(i[, k])"});
  c.push_back({"UVZ", NameKind::VectorFunction, 1, 2, Builtin::Abs, 0.0, "UVZ(i[, k])"});
  c.push_back({"TRANS", NameKind::VectorFunction, 2, 3, Builtin::Abs, 0.0, "TRANS(v, i[, j])"});
  return c;
}

}  // namespace

const std::vector<NameInfo>& allNames() {
  static const std::vector<NameInfo> catalog = buildCatalog();
  return catalog;
}

const NameInfo* findName(std::string_view upperName) {
  for (const NameInfo& info : allNames()) {
    if (info.name == upperName) return &info;
  }
  return nullptr;
}

}  // namespace openmss::expr
