#pragma once
// Internal to the user-equation builders (user_equation_builder.cpp, linear_state_builder.cpp,
// gse_builder.cpp, user_equation_references.cpp): the builder that turns VARIABLE, DIFF,
// ARRAY, PINPUT, POUTPUT, LSE, TFSISO and GSE statements into the Model, with the indices by
// id that the elements' references (VARIABLES=, X=, U=, Y=, IC=, A=, ...) resolve against.
// Not for use outside these files: model/user_equation_builder.hpp is the interface.

#include <map>
#include <set>
#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"
#include "user/loaded_gse_routines.hpp"

namespace openmss::model {

// "X", "U", "Y", "IC" or "constants" for diagnostics.
std::string arrayKindName(DataArray::Kind k);
inline int toInt(size_t n) { return static_cast<int>(n); }
// The numbers of an argument (the reader checked that they are numbers).
inline std::vector<double> numbersOf(const language::Argument& a) {
  std::vector<double> out;
  for (const auto& v : a.values) out.push_back(v.number);
  return out;
}

class UserEquationBuilder {
 public:
  UserEquationBuilder(Model& model, Diagnostics& diags) : model_(model), diags_(diags) {}

  // Referenced elements first (user_equation_builder.cpp).
  void variable(const language::Statement& s);
  void diff(const language::Statement& s);
  void plant(const language::Statement& s, std::vector<PlantVariables>& list);
  void array(const language::Statement& s);
  // The elements that own arrays: LSE and TFSISO (linear_state_builder.cpp), GSE
  // (gse_builder.cpp).
  void lse(const language::Statement& s);
  void tfsiso(const language::Statement& s);
  void gse(const language::Statement& s, const std::string& baseDirectory);
  // After every element: state offsets, and X/Y arrays nobody owns.
  void finish();

 private:
  // References (user_equation_references.cpp). Each reports what is wrong and clears `ok`.
  std::vector<int> variableList(const language::Statement& s, bool& ok);
  int arrayRef(const language::Statement& s, const char* name, DataArray::Kind kind, bool required,
               bool& ok);
  const Eigen::MatrixXd* matrixRef(const language::Statement& s, const char* name, bool required,
                                   bool& ok);
  static std::string elementName(const LinearStateElement& e);
  bool shape(const language::Statement& s, const char* name, const Eigen::MatrixXd& m,
             Eigen::Index rows, Eigen::Index cols, const std::string& why);
  bool claimSize(const language::Statement& s, const char* name, int array, Eigen::Index n);
  // LSE and TFSISO (linear_state_builder.cpp).
  void add(LinearStateElement& e);
  // GSE parts (gse_builder.cpp).
  int gseArray(const language::Statement& s, const char* count, long n, const char* arrayArg,
               DataArray::Kind kind, bool& ok);
  void gseInitial(const language::Statement& s, const char* name, long n, Eigen::VectorXd& out,
                  bool& ok);
  bool gseSamplePeriod(const language::Statement& s, long nd, GeneralStateElement& e);
  bool gseRoutines(const language::Statement& s, const std::string& baseDirectory,
                   const std::vector<double>& par, const user::GseRoutineNames& names,
                   GeneralStateElement& e);

  Model& model_;
  Diagnostics& diags_;
  std::map<long, int> variableIndex_, diffIndex_, arrayIndex_;
  std::map<long, bool> broken_;  // arrays with errors (no second diagnostic for them)
  std::set<int> referenced_;     // arrays an LSE/TFSISO names (even one with errors)
};

}  // namespace openmss::model
