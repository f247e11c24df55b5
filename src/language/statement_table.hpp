#pragma once
// Builders of the raw statement table and of the argument lists that statements share with
// commands (INTEGRATOR, EQUILIBRIUM, IC, KINEMATICS). Internal to the language module: other
// code uses the finalised tables from schema.hpp.

#include <vector>

#include "language/schema.hpp"

namespace openmss::language {

std::vector<StatementSpec> buildStatementTable();
std::vector<StatementSpec> buildCommandTable(const std::vector<StatementSpec>& statements);

std::vector<ArgumentSpec> integratorArguments();
std::vector<ArgumentSpec> equilibriumArguments();
std::vector<ArgumentSpec> icArguments();
std::vector<ArgumentSpec> kinematicsArguments();

}  // namespace openmss::language
