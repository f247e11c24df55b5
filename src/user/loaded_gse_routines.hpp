#pragma once
// A GSE whose equations come from a user library (ADAMS's GSE_DERIV, GSE_OUTPUT, GSE_UPDATE,
// GSE_SAMP in the C-style interface, user/openmss_usersub.h), behind the plain GseRoutines
// interface. The utility subroutines those routines call back (SYSARY, SYSFNC, SYSPAR,
// ERRMES, ...) are defined next to the adapter, in loaded_gse_routines.cpp, and read the
// element that is being evaluated.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "user/gse_routines.hpp"
#include "user/user_library.hpp"

namespace openmss::user {

// The GSE statement's data the routines may read (sAdamsGSE and the arrays behind it).
struct GseDescription {
  long id = 0;
  std::vector<double> par;  // FUNCTION=USER(r1, ..., r30)
  int ns = 0, nd = 0, ni = 0, no = 0;
  long xArray = 0, xdArray = 0, uArray = 0, yArray = 0, icArray = 0, icdArray = 0;  // ids
  bool staticHold = false;
  // IC and constant ARRAYs of the data set (id, numbers), readable with SYSARY("ARRAY").
  std::vector<std::pair<long, std::vector<double>>> constantArrays;
};

// Where each of the four routines comes from: library and exported name (empty library: the
// default library; empty name: the default name).
struct GseRoutineNames {
  RoutineName deriv, output, update, sample;
};

// Opens the libraries, finds the routines the sizes need (GSE_DERIV when NS > 0, GSE_OUTPUT
// when NO > 0, GSE_UPDATE when ND > 0; GSE_SAMP when present) and runs ADAMS's initialization
// pass (IFLAG = 1, utilities read zeros). Returns null with one line per problem in `errors`.
std::shared_ptr<const GseRoutines> loadGseRoutines(const GseDescription& description,
                                                   const GseRoutineNames& names,
                                                   const std::string& baseDirectory,
                                                   std::vector<std::string>& errors);

}  // namespace openmss::user
