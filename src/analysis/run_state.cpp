#include "analysis/run_state.hpp"

namespace openmss::analysis {

RunState::RunState(mechanics::MultibodySystem& system)
    : y(system.initialState()),
      expressions(std::make_unique<mechanics::ExpressionRunState>(system.model())) {
  yp = Eigen::VectorXd::Zero(y.size());
  // The COUPLER/GEAR turn counts' storage before the equations are bound to it.
  expressions->trackCoupledAngles(system.constraints());
  expressions->trackCurveParameters(system.constraints());  // PTCV/CVCV warm starts
  system.setRunState(expressions.get());
}

}  // namespace openmss::analysis
