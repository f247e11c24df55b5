#pragma once
// Reads the tab-separated reference tables of a validation case
// (reference/<Case>_ADAMS_{Pos,Vel,...}.txt) back into the requests they were taken from, so
// that they can be compared like a request file. Header-only for the reason given in
// request_comparison.hpp.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "request_comparison.hpp"

namespace openmss::validation {

// Which request and which record columns a reference table holds. The column headers are
// checked so that a table in another order is refused rather than misread.
struct ReferenceTable {
  const char* kind;  // file name part, e.g. "Pos"
  long requestId;    // REQUEST/n of the .adm
  RecordKind recordKind;
  std::vector<int> columns;          // record columns (0..5 = F2 F3 F4 F6 F7 F8)
  std::vector<const char*> headers;  // expected header of each table column after "Time"
};

inline const std::vector<ReferenceTable>& adamsReferenceTables() {
  static const std::vector<ReferenceTable> tables = {
      {"Pos", 1, RecordKind::Displacement, {0, 1, 2}, {"X_Pos", "Y_Pos", "Z_Pos"}},
      {"Vel", 2, RecordKind::Plain, {0, 1, 2}, {"X_Vel", "Y_Vel", "Z_Vel"}},
      {"Avel", 2, RecordKind::Plain, {3, 4, 5}, {"X_AngVel", "Y_AngVel", "Z_AngVel"}},
      {"Acc", 3, RecordKind::Plain, {0, 1, 2}, {"X_Acc", "Y_Acc", "Z_Acc"}},
      {"Aacc", 3, RecordKind::Plain, {3, 4, 5}, {"X_AngAcc", "Y_AngAcc", "Z_AngAcc"}},
      {"Quat", 4, RecordKind::EulerParameters, {0, 1, 2, 3}, {"e0", "e1", "e2", "e3"}},
      {"Rforce", 5, RecordKind::Plain, {0, 1, 2}, {"X_Force", "Y_Force", "Z_Force"}},
      {"Rtorque", 5, RecordKind::Plain, {3, 4, 5}, {"X_Torque", "Y_Torque", "Z_Torque"}},
  };
  return tables;
}

namespace reference_detail {

inline std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  std::string field;
  while (in >> field) fields.push_back(field);
  return fields;
}

inline bool parseField(const std::string& field, double& value) {
  char* end = nullptr;
  value = std::strtod(field.c_str(), &end);
  return !field.empty() && end == field.c_str() + field.size();
}

// Adds one table to its request's series (creating the series on first use).
inline bool addTable(const std::filesystem::path& path, const ReferenceTable& table,
                     RequestRun& run, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    *error = path.string() + ": cannot open reference table";
    return false;
  }
  auto series = std::find_if(run.begin(), run.end(),
                             [&](const RequestSeries& s) { return s.id == table.requestId; });
  const bool firstTableOfRequest = series == run.end();
  if (firstTableOfRequest) {
    RequestSeries fresh;
    fresh.id = table.requestId;
    fresh.kind = table.recordKind;
    fresh.hasColumn.fill(false);
    run.push_back(std::move(fresh));
    series = run.end() - 1;
  }
  for (int column : table.columns) series->hasColumn[static_cast<std::size_t>(column)] = true;

  std::string line;
  int lineNumber = 0;
  bool sawHeader = false;
  std::size_t record = 0;
  auto fail = [&](const std::string& message) {
    *error = path.string() + ":" + std::to_string(lineNumber) + ": " + message;
    return false;
  };
  while (std::getline(in, line)) {
    ++lineNumber;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> fields = splitFields(line);
    if (!sawHeader) {
      if (fields.size() != table.headers.size() + 1 || fields[0] != "Time") {
        return fail("expected a header \"Time\" and " + std::to_string(table.headers.size()) +
                    " columns");
      }
      for (std::size_t k = 0; k < table.headers.size(); ++k) {
        if (fields[k + 1] != table.headers[k]) {
          return fail("column " + std::to_string(k + 2) + " is \"" + fields[k + 1] +
                      "\", expected \"" + table.headers[k] + "\"");
        }
      }
      sawHeader = true;
      continue;
    }
    if (fields.size() != table.headers.size() + 1) return fail("wrong number of columns");
    std::vector<double> values(fields.size());
    for (std::size_t k = 0; k < fields.size(); ++k) {
      if (!parseField(fields[k], values[k])) return fail("not a number: " + fields[k]);
    }
    if (firstTableOfRequest) {
      series->times.push_back(values[0]);
      series->rows.push_back({});
    } else if (record >= series->times.size() || series->times[record] != values[0]) {
      return fail("times differ from the other table of REQUEST/" +
                  std::to_string(table.requestId));
    }
    for (std::size_t k = 0; k < table.columns.size(); ++k) {
      series->rows[record][static_cast<std::size_t>(table.columns[k])] = values[k + 1];
    }
    ++record;
  }
  if (record != series->times.size() || record == 0) {
    return fail("has " + std::to_string(record) + " records, expected " +
                std::to_string(series->times.size()));
  }
  return true;
}

}  // namespace reference_detail

// The reference run of a case from its tables: REQUEST/1 (x, y, z only; the tables carry no
// angles), REQUEST/2, /3 and /5 complete, REQUEST/4 the four Euler parameters.
inline std::optional<RequestRun> runFromReferenceTables(const std::filesystem::path& caseFolder,
                                                        const std::string& caseName,
                                                        std::string* error) {
  RequestRun run;
  for (const ReferenceTable& table : adamsReferenceTables()) {
    const std::filesystem::path path =
        caseFolder / "reference" / (caseName + "_ADAMS_" + table.kind + ".txt");
    if (!reference_detail::addTable(path, table, run, error)) return std::nullopt;
  }
  return run;
}

}  // namespace openmss::validation
