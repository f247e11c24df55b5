#pragma once
// Writers of the state matrices of LINEAR/STATEMAT (docs/theory.md "Linear
// analysis"): MATLAB format, one ASCII flat file per matrix and per identifier list; MATRIXx
// format, one file in a MATSAVE-like layout.

#include <string>
#include <vector>

#include "analysis/linearization.hpp"
#include "model/model.hpp"

namespace openmss::analysis {

// Numeric identifiers of each state, for the .st file and the STATES matrix: element id, code,
// index within the element. Codes: 1-6 part displacement X Y Z RX RY RZ (ground axes),
// 7-12 part velocity VX VY VZ WX WY WZ, 20 DIFF state, 21 LSE state, 22 TFSISO state
// (index = the state's number within the element), 0 a coordinate without a name.
Eigen::MatrixXd stateIdentifiers(const LinearSystem& linear, const model::Model& model);

// MATLAB: <base>.a, .b, .c, .d (rows of whitespace-separated numbers with 17 significant
// digits; a matrix with no entries is not written), <base>.st (the state identifiers), <base>.pi
// and <base>.po (VARIABLE ids of the plant inputs and outputs, one per line; written only when
// there are inputs or outputs). Returns the files written, or false with *error set.
bool writeMatlabStateMatrices(const std::string& base, const LinearSystem& linear,
                              const model::Model& model, std::vector<std::string>& written,
                              std::string* error);

// MATRIXx: one file <base>.mat holding A, B, C, D, STATES, PINPUT, POUTPUT in the MATSAVE-like
// layout documented in docs/theory.md.
bool writeMatrixxStateMatrices(const std::string& base, const LinearSystem& linear,
                               const model::Model& model, std::vector<std::string>& written,
                               std::string* error);

}  // namespace openmss::analysis
