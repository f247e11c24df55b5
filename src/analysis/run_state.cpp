#include "analysis/run_state.hpp"

namespace openmss::analysis {

RunState::RunState(mechanics::MultibodySystem& system)
    : y(system.initialState()),
      expressions(std::make_unique<mechanics::ExpressionRunState>(system.model())) {
  yp = Eigen::VectorXd::Zero(y.size());
  system.setRunState(expressions.get());
}

}  // namespace openmss::analysis
