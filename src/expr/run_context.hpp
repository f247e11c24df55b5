#pragma once
// What an expression may read from the run that evaluates it, beyond host values and TIME:
// the recorded history of its DELAY arguments. The analysis owns the history and updates it
// after accepted steps only (mechanics/expression_run_state.hpp); evaluation only reads it, so
// an Expression stays immutable and may be evaluated concurrently.

#include "expr/delay_history.hpp"

namespace openmss::expr {

class RunContext {
 public:
  virtual ~RunContext() = default;
  // The history of the DELAY argument identified by `key` (Expression::delayKey), or nullptr
  // when the run has recorded none (before the first accepted state).
  virtual const DelayHistory* delayHistory(const void* key) const = 0;
};

}  // namespace openmss::expr
