#pragma once
// The validation metric: how far the requests of one run are from those of a reference run
// (real ADAMS), column by column. Header-only because tests/CMakeLists.txt builds only the
// *_test.cpp files of this folder. The metric and why it is so are in docs/output-files.md.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "output/request_file_reader.hpp"

namespace openmss::validation {

// What the six columns of a request record mean, as far as comparing them is concerned.
enum class RecordKind {
  Plain,            // six independent values
  Displacement,     // x, y, z, then psi, theta, phi (body 3-1-3) in degrees
  EulerParameters,  // e0..e3 in the first four columns; q and -q are the same orientation
};

// One request of a run: records in time order, one per output time.
struct RequestSeries {
  long id = 0;
  RecordKind kind = RecordKind::Plain;
  std::array<bool, 6> hasColumn = {true, true, true, true, true, true};
  std::vector<double> times;
  std::vector<std::array<double, 6>> rows;
};
using RequestRun = std::vector<RequestSeries>;

struct ColumnResult {
  long requestId = 0;
  int column = 0;           // 0..5 in the record, i.e. F2 F3 F4 F6 F7 F8
  double maxError = 0.0;    // largest |ours - reference| over the records, in file units
  double scale = 0.0;       // what maxError is divided by
  double normalised = 0.0;  // maxError / scale
  double timeOfMax = 0.0;
};

struct RunComparison {
  std::vector<ColumnResult> columns;
  std::vector<std::string> problems;  // what of the reference the candidate lacks
  std::size_t records = 0;            // reference records compared (most of any request)

  // The column with the largest normalised error (a NaN counts as the largest); a default
  // result when nothing was compared.
  ColumnResult worst() const {
    auto rank = [](const ColumnResult& c) {
      return std::isnan(c.normalised) ? std::numeric_limits<double>::infinity() : c.normalised;
    };
    ColumnResult worstColumn;
    for (std::size_t k = 0; k < columns.size(); ++k) {
      if (k == 0 || rank(columns[k]) > rank(worstColumn)) worstColumn = columns[k];
    }
    return worstColumn;
  }
};

// The request's column name as in the REQUEST statement (F2..F4, F6..F8).
inline const char* columnName(int column) {
  static constexpr const char* kNames[] = {"F2", "F3", "F4", "F6", "F7", "F8"};
  return column >= 0 && column < 6 ? kNames[column] : "F?";
}

namespace comparison_detail {

// A column whose size is small next to the other components of the same vector is judged
// against this share of the vector's size (see docs/output-files.md).
constexpr double kGroupFloorShare = 0.1;
// A vector that does not move at all (e.g. the reaction torque of a planar pendulum) is judged
// against this share of the largest size in its request.
constexpr double kRequestFloorShare = 1.0e-2;
// ADAMS prints six significant digits, so a value is known to 1e-5 of its magnitude at best;
// with this share of a column's largest magnitude as its least size, one unit in the last
// printed digit scores at most 1e-3 (it matters for columns that barely move off a value).
constexpr double kPrintedDigitsShare = 1.0e-2;
// Within this many degrees of theta = 0 or 180, psi and phi of a 3-1-3 set are not separately
// defined; only psi + phi (theta = 0) or psi - phi (theta = 180) is. Near the lock an
// orientation difference d moves psi and phi by up to d / sin(theta): two runs that agree in
// orientation to 1e-5 rad (the positions of the 5 s validation runs agree to about 5e-4 m on a
// 2 m arm) may print psi 180 degrees apart when theta is below about 0.01 degree (measured:
// Spherical_Case01, WSTIFF SI2, t = 3.39 s, theta 0.0011 against ADAMS's 0.014 degree, psi and
// phi swapped between +90 and -90 with psi + phi equal). 0.1 degree leaves psi and phi each a
// factor sin(0.1 deg) = 1.7e-3 of conditioning, so only their defined combination is compared
// below it.
constexpr double kGimbalLockDegrees = 1.0e-1;
constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

inline double wrappedDegrees(double difference) {
  return difference - 360.0 * std::round(difference / 360.0);
}

inline double errorMagnitude(double difference) {
  const double e = std::abs(difference);
  return std::isfinite(e) ? e : std::numeric_limits<double>::infinity();
}

inline double timeTolerance(double time) { return 1.0e-9 + 1.0e-6 * std::abs(time); }

// Index of the record of `series` at `time`, or -1. Times are ascending.
inline long recordAt(const RequestSeries& series, double time) {
  const double tolerance = timeTolerance(time);
  const auto it = std::lower_bound(series.times.begin(), series.times.end(), time - tolerance);
  if (it == series.times.end() || std::abs(*it - time) > tolerance) return -1;
  return static_cast<long>(it - series.times.begin());
}

inline bool isColumnGroupedWithAll(RecordKind kind) { return kind == RecordKind::EulerParameters; }

// 0: theta is away from 0 and 180; +1: near 0; -1: near 180.
inline int gimbalLock(const std::array<double, 6>& row) {
  if (std::abs(row[4]) <= kGimbalLockDegrees) return 1;
  if (std::abs(std::abs(row[4]) - 180.0) <= kGimbalLockDegrees) return -1;
  return 0;
}

// Reference values prepared for measuring ranges: Euler parameters made sign-continuous and
// psi/phi unwrapped, so that a sign flip or a wrap through 180 degrees does not count as motion.
inline std::vector<std::array<double, 6>> continuousRows(const RequestSeries& reference,
                                                         const std::vector<long>& records,
                                                         std::vector<bool>& usable) {
  std::vector<std::array<double, 6>> rows;
  usable.assign(6 * records.size(), true);
  for (std::size_t r = 0; r < records.size(); ++r) {
    rows.push_back(reference.rows[static_cast<std::size_t>(records[r])]);
  }
  if (reference.kind == RecordKind::EulerParameters) {
    for (std::size_t r = 1; r < rows.size(); ++r) {
      double dot = 0.0;
      for (std::size_t c = 0; c < 4; ++c) dot += rows[r][c] * rows[r - 1][c];
      if (dot < 0.0) {
        for (std::size_t c = 0; c < 4; ++c) rows[r][c] = -rows[r][c];
      }
    }
  }
  if (reference.kind == RecordKind::Displacement && reference.hasColumn[4]) {
    for (std::size_t c : {std::size_t{3}, std::size_t{5}}) {
      bool havePrevious = false;
      double previousRaw = 0.0;
      double previousUnwrapped = 0.0;
      for (std::size_t r = 0; r < rows.size(); ++r) {
        if (gimbalLock(rows[r]) != 0) {
          usable[6 * r + c] = false;  // psi and phi are arbitrary here; not part of the range
          continue;
        }
        const double raw = rows[r][c];
        rows[r][c] = havePrevious ? previousUnwrapped + wrappedDegrees(raw - previousRaw) : raw;
        previousRaw = raw;
        previousUnwrapped = rows[r][c];
        havePrevious = true;
      }
    }
  }
  return rows;
}

// Per column the largest |difference| and its time, for matched records.
inline void accumulateErrors(const RequestSeries& reference, const RequestSeries& candidate,
                             const std::vector<long>& refRecords,
                             const std::vector<long>& candRecords,
                             std::array<ColumnResult, 6>& results) {
  for (std::size_t r = 0; r < refRecords.size(); ++r) {
    const auto& ref = reference.rows[static_cast<std::size_t>(refRecords[r])];
    const auto& ours = candidate.rows[static_cast<std::size_t>(candRecords[r])];
    const double time = reference.times[static_cast<std::size_t>(refRecords[r])];
    std::array<double, 6> errors{};
    for (std::size_t c = 0; c < 6; ++c) errors[c] = errorMagnitude(ours[c] - ref[c]);

    if (reference.kind == RecordKind::EulerParameters) {
      // The sign of q is a free choice of each program; take the one that fits this record.
      double plusWorst = 0.0;
      double minusWorst = 0.0;
      std::array<double, 4> minusErrors{};
      for (std::size_t c = 0; c < 4; ++c) {
        minusErrors[c] = errorMagnitude(-ours[c] - ref[c]);
        plusWorst = std::max(plusWorst, errors[c]);
        minusWorst = std::max(minusWorst, minusErrors[c]);
      }
      if (minusWorst < plusWorst) std::copy(minusErrors.begin(), minusErrors.end(), errors.begin());
    }
    if (reference.kind == RecordKind::Displacement) {
      for (std::size_t c = 3; c < 6; ++c)
        errors[c] = errorMagnitude(wrappedDegrees(ours[c] - ref[c]));
      // Locked when either run is near the lock: the other may sit just outside the threshold.
      const int refLock = gimbalLock(ref);
      if (const int lock = refLock != 0 ? refLock : gimbalLock(ours);
          lock != 0 && reference.hasColumn[4]) {
        // Only the sum (theta = 0) or difference (theta = 180) of psi and phi is defined.
        const double sign = static_cast<double>(lock);
        const double combined =
            errorMagnitude(wrappedDegrees((ours[3] + sign * ours[5]) - (ref[3] + sign * ref[5])));
        errors[3] = combined;
        errors[5] = combined;
      }
    }
    for (std::size_t c = 0; c < 6; ++c) {
      if (reference.hasColumn[c] && !(errors[c] <= results[c].maxError)) {
        results[c].maxError = errors[c];
        results[c].timeOfMax = time;
      }
    }
  }
}

}  // namespace comparison_detail

// Compares every column of every reference request with the candidate's. For each column:
//   normalised = max over records |ours - reference| / scale,
//   scale = max(size, 0.1 * max(groupSize, 0.01 * requestSize)),
//   size = max(range, 0.01 * magnitude),
// range and magnitude = max - min and max |value| of the reference column, groupSize = largest
// size among the columns of the same vector (F2-F4 or F6-F8; all of an Euler-parameter
// request), requestSize = largest size in the request (angles in radians so that they compare
// with lengths; 1 when the whole request is zero).
inline RunComparison compareRuns(const RequestRun& reference, const RequestRun& candidate) {
  namespace d = comparison_detail;
  RunComparison comparison;
  for (const RequestSeries& ref : reference) {
    const std::string subject = "REQUEST/" + std::to_string(ref.id);
    const auto found = std::find_if(candidate.begin(), candidate.end(),
                                    [&](const RequestSeries& s) { return s.id == ref.id; });
    if (found == candidate.end()) {
      comparison.problems.push_back(subject + " is missing from the run");
      continue;
    }
    std::vector<long> refRecords;
    std::vector<long> candRecords;
    std::size_t missing = 0;
    double firstMissing = 0.0;
    for (std::size_t r = 0; r < ref.times.size(); ++r) {
      const long match = d::recordAt(*found, ref.times[r]);
      if (match < 0) {
        if (missing++ == 0) firstMissing = ref.times[r];
        continue;
      }
      refRecords.push_back(static_cast<long>(r));
      candRecords.push_back(match);
    }
    if (missing > 0) {
      char text[160];
      std::snprintf(text, sizeof text, "%s: %zu of %zu reference times missing (first t=%g)",
                    subject.c_str(), missing, ref.times.size(), firstMissing);
      comparison.problems.push_back(text);
    }
    if (refRecords.empty()) continue;
    comparison.records = std::max(comparison.records, refRecords.size());

    std::vector<bool> usable;
    const auto rows = d::continuousRows(ref, refRecords, usable);
    // A column's size: its range, but never below what its printed digits can resolve.
    std::array<double, 6> size{};
    for (std::size_t c = 0; c < 6; ++c) {
      if (!ref.hasColumn[c]) continue;
      double low = std::numeric_limits<double>::infinity();
      double high = -low;
      double magnitude = 0.0;
      for (std::size_t r = 0; r < rows.size(); ++r) {
        magnitude = std::max(magnitude, std::abs(rows[r][c]));
        if (!usable[6 * r + c]) continue;
        low = std::min(low, rows[r][c]);
        high = std::max(high, rows[r][c]);
      }
      const double range = high >= low ? high - low : 0.0;
      size[c] = std::max(range, d::kPrintedDigitsShare * magnitude);
    }
    const bool angles = ref.kind == RecordKind::Displacement;
    // Per column the factor that takes it to the request's common unit (radians for angles).
    auto toCommon = [&](std::size_t c) { return angles && c >= 3 ? d::kRadiansPerDegree : 1.0; };
    double requestSize = 0.0;
    for (std::size_t c = 0; c < 6; ++c) requestSize = std::max(requestSize, size[c] * toCommon(c));
    // A request that is zero throughout has no size of its own: 1 in model units.
    if (requestSize == 0.0) requestSize = 1.0;

    std::array<ColumnResult, 6> results{};
    d::accumulateErrors(ref, *found, refRecords, candRecords, results);
    for (std::size_t c = 0; c < 6; ++c) {
      if (!ref.hasColumn[c]) continue;
      double groupSize = 0.0;
      for (std::size_t g = 0; g < 6; ++g) {
        const bool sameGroup = d::isColumnGroupedWithAll(ref.kind) || (g / 3 == c / 3);
        if (sameGroup && ref.hasColumn[g]) groupSize = std::max(groupSize, size[g]);
      }
      ColumnResult& result = results[c];
      result.requestId = ref.id;
      result.column = static_cast<int>(c);
      result.scale = std::max(
          size[c], d::kGroupFloorShare *
                       std::max(groupSize, d::kRequestFloorShare * requestSize / toCommon(c)));
      result.normalised = result.maxError / result.scale;
      comparison.columns.push_back(result);
    }
  }
  return comparison;
}

// The requests of a request file, one record per output time (the last of repeated times).
// Displacement requests are recognised by their type; Euler-parameter requests are expression
// requests, so the caller names them.
inline RequestRun runFromRequestFile(const output::RequestFileData& data,
                                     const std::vector<long>& eulerParameterRequests) {
  const std::vector<output::RequestFileStep> steps = output::lastStepPerTime(data.steps);
  RequestRun run;
  for (std::size_t k = 0; k < data.entries.size(); ++k) {
    RequestSeries series;
    series.id = data.entries[k].id;
    if (data.entries[k].type == output::kDisplacementRequest) {
      series.kind = RecordKind::Displacement;
    } else if (std::find(eulerParameterRequests.begin(), eulerParameterRequests.end(), series.id) !=
               eulerParameterRequests.end()) {
      series.kind = RecordKind::EulerParameters;
    }
    for (const output::RequestFileStep& step : steps) {
      series.times.push_back(step.time);
      series.rows.push_back(step.rows[k]);
    }
    run.push_back(std::move(series));
  }
  return run;
}

// "worst 3.2e-05 (REQUEST/5 col F3), 501 records"
inline std::string summary(const RunComparison& comparison) {
  const ColumnResult worst = comparison.worst();
  char text[160];
  std::snprintf(text, sizeof text, "worst %.1e (REQUEST/%ld col %s), %zu records", worst.normalised,
                worst.requestId, columnName(worst.column), comparison.records);
  return text;
}

}  // namespace openmss::validation
