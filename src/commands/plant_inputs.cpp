// Session::setPlantInputs: the values an embedding program gives its plant's PINPUT variables
// (docs/embedding.md). A change of input is a jump, as a GSE sample is one
// (analysis/discrete_sampler.cpp): only what reads the input algebraically jumps with it.

#include <cstdio>

#include "commands/session.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/user_state_solve.hpp"

namespace openmss::commands {

bool Session::setPlantInputs(const std::vector<std::pair<int, double>>& values) {
  if (!state_ || !system_ || !model_) return false;
  for (const auto& [k, v] : values) {
    model::Variable& variable = model_->variables[static_cast<std::size_t>(k)];
    // %.17g reads back as the same double; the system evaluates the model's function at every
    // call, so the new constant holds from the next evaluation on.
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v);
    Diagnostics ignored;
    model::BoundExpression constant;
    if (!expr::Expression::parse(text, variable.where, "VARIABLE/" + std::to_string(variable.id),
                                 ignored, constant.expression))
      return false;
    variable.function = std::move(constant);
  }
  if (!state_->initialized) return true;  // the initial conditions will solve with them
  Eigen::VectorXd y = state_->y, yp = state_->yp;
  if (!mechanics::solveUserAlgebraic(*system_, state_->t, y).converged) return false;
  if (!mechanics::solveAccelerations(*system_, state_->t, y, yp)) return false;
  mechanics::userStateRates(*system_, state_->t, y, yp);
  state_->y = std::move(y);
  state_->yp = std::move(yp);
  return true;
}

}  // namespace openmss::commands
