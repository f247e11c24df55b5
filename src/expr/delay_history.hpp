#pragma once
// The recorded past of one DELAY argument: (time, value) pairs appended after accepted
// integrator steps, read back by cubic Lagrange interpolation (docs/expressions.md, "DELAY").

#include <vector>

namespace openmss::expr {

// Value and slope (d/ds) of the interpolant at one time s.
struct DelayLookup {
  double value = 0.0;
  double slope = 0.0;
};

class DelayHistory {
 public:
  // Appends (t, v). Records at times >= t are dropped first, so a restart at an earlier time
  // (a SENSOR event inside the last step) replaces the part of the history after it.
  void record(double t, double v);
  void clear();
  bool empty() const { return times_.empty(); }
  std::size_t size() const { return times_.size(); }
  double startTime() const { return times_.front(); }  // precondition: !empty()
  double lastTime() const { return times_.back(); }    // precondition: !empty()
  // The records, oldest first (a SAVE file holds them; record() them back in order).
  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& values() const { return values_; }

  // The cubic through the four records nearest s (two on each side where there are; fewer
  // when the history has fewer), its value and slope at s. Between records this is order-3
  // interpolation, error f''''(xi)/24 * prod(s - t_i); past the last record (a delay shorter
  // than the step under way) the same cubic extrapolates. Precondition: !empty().
  DelayLookup at(double s) const;

 private:
  std::vector<double> times_, values_;
};

}  // namespace openmss::expr
