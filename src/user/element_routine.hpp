#pragma once
// An evaluation subroutine of one FUNCTION=USER(...) element (SFOSUB, VFOSUB, VTOSUB, GFOSUB,
// VARSUB, DIFSUB, MOTSUB, REQSUB, SENSUB, SEVSUB) loaded from a user library, FORTRAN-77 or
// C style (docs/user-subroutines.md). Loading runs ADAMS's dependency pass (IFLAG = 1, then
// 3): every SYSFNC/SYSARY call the routine makes is recorded as a host call (DX(i,j), VARVAL(id),
// ...), so that the model binds those measures like the ones of an expression and the chain
// rule through the routine is exact in the measures. The routine's own partials in its inputs
// come from SYSPAR where it gives them, else from central differences over the input values.

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/bspline_curve.hpp"
#include "common/spline.hpp"
#include "expr/expression.hpp"
#include "expr/user_function.hpp"
#include "user/user_library.hpp"

namespace openmss::user {

enum class RoutineKind {
  Sfosub,
  Vfosub,
  Vtosub,
  Gfosub,
  Varsub,
  Difsub,
  Motsub,
  Reqsub,
  Sensub,
  Sevsub
};

// ADAMS's default name (upper case, FORTRAN spelling) and the number of values it returns.
const char* routineName(RoutineKind kind);
int routineOutputs(RoutineKind kind);

// The model data the data-access utilities read (AKISPL, CUBSPL, GTCURV, GTARAY, GTSTRG).
struct ModelData {
  std::map<long, std::shared_ptr<const Spline>> splines;
  std::map<long, std::shared_ptr<const BSplineCurve>> curves;
  std::map<long, std::vector<double>> arrays;  // IC and constant ARRAYs (values fixed)
  std::map<long, std::string> strings;
  // GTUNTS: whether a UNITS statement was read; SI value of the model's time, length, force
  // and mass units; their symbols, 3 characters each, blank-padded, in that order.
  bool unitsGiven = false;
  std::array<double, 4> unitScales{1.0, 1.0, 1.0, 1.0};
  std::string unitNames;
};

// The statement's data the routine's element struct carries (fields a kind does not use stay
// at their defaults).
struct ElementData {
  std::string subject;  // "SFORCE/3": for messages
  long id = 0;
  std::vector<double> par;  // FUNCTION=USER(r1, ..., r30)
  long i = 0, j = 0, jfloat = 0, rm = 0, joint = 0;
  bool actionOnly = false, rotation = false, staticHold = false, implicit = false;
  double ic = 0.0, icDerivative = 0.0;  // VARIABLE IC; DIFF IC and its derivative
  double sensorValue = 0.0, sensorError = 0.0;
  char sensorLogic = 'E';          // 'E', 'G', 'L'
  std::string motionType = "T";    // "T" translation or "R" rotation
  char motionWhich = 'Z';          // X Y Z (translation) or 1 2 3 (B1 B2 B3)
  std::string motionDva = "DISP";  // DISP, VELO or ACCE
  std::string comment;
  std::shared_ptr<const ModelData> data;  // may be null: the data utilities then fail
};

class ElementRoutine;

// Loads the routine for `kind` (library and name from ROUTINE=, or the default library and
// ADAMS's default names) and runs its dependency pass. Null with one line per problem.
std::shared_ptr<ElementRoutine> loadElementRoutine(RoutineKind kind, const ElementData& element,
                                                   const RoutineName& routine,
                                                   const std::string& baseDirectory,
                                                   std::string& error);

class ElementRoutine : public std::enable_shared_from_this<ElementRoutine> {
 public:
  virtual ~ElementRoutine() = default;
  // The measures the routine declared in its dependency pass, in first-call order.
  virtual const std::vector<expr::HostCall>& dependencies() const = 0;
  // Output `component` (0-based) as an expression function (copies share the routine).
  virtual std::shared_ptr<const expr::UserFunction> component(int component) const = 0;
  // The first fatal condition (NaN, ERRMES with STOP, a crash), or empty.
  virtual std::string fatalError() const = 0;
};

// The first fatal message of any user routine in this process (empty: none). The program
// repeats it as its last words when an analysis fails.
std::string firstUserFatal();

}  // namespace openmss::user
