#include "output/request_file_reader.hpp"

#include <charconv>
#include <fstream>
#include <sstream>
#include <utility>

namespace openmss::output {
namespace {

constexpr std::size_t kValuesPerRecord = 6;
constexpr std::size_t kValueWidth = 13;  // each value is printed in 13 columns after one blank
constexpr std::size_t kFixedRecordWidth = 1 + kValuesPerRecord * kValueWidth;
constexpr std::size_t kStampBegin = 9;  // " A.R3    " precedes the stamp
constexpr std::size_t kStampWidth = 19;

std::string_view trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const std::size_t last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> splitWords(std::string_view text) {
  std::vector<std::string_view> words;
  std::size_t at = 0;
  while (true) {
    at = text.find_first_not_of(" \t", at);
    if (at == std::string_view::npos) break;
    std::size_t end = text.find_first_of(" \t", at);
    if (end == std::string_view::npos) end = text.size();
    words.push_back(text.substr(at, end - at));
    at = end;
  }
  return words;
}

// The whole word must be a number ("1.0E+00", "-7.0E-01", "NAN", "INF").
std::optional<double> parseNumber(std::string_view word) {
  word = trimmed(word);
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);
  if (word.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, status] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (status != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

std::optional<long> parseInteger(std::string_view word) {
  word = trimmed(word);
  if (word.empty()) return std::nullopt;
  long value = 0;
  const auto [end, status] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (status != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

// Walks the text line by line, CR of CRLF removed, counting lines for messages.
class LineCursor {
 public:
  LineCursor(std::string_view text, std::string name) : text_(text), name_(std::move(name)) {}

  bool atEnd() const { return at_ >= text_.size(); }
  int lineNumber() const { return line_; }

  std::string_view next() {
    std::size_t end = text_.find('\n', at_);
    if (end == std::string_view::npos) end = text_.size();
    std::string_view line = text_.substr(at_, end - at_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    at_ = end + 1;
    ++line_;
    return line;
  }

  std::string_view peek() const {
    LineCursor copy = *this;
    return copy.next();
  }

  // "name:line: message" about the line last returned by next().
  std::string where(const std::string& message) const {
    return name_ + ":" + std::to_string(line_) + ": " + message;
  }
  std::string whereEnd(const std::string& message) const {
    return name_ + ": " + message + " (file ends after line " + std::to_string(line_) + ")";
  }

 private:
  std::string_view text_;
  std::string name_;
  std::size_t at_ = 0;
  int line_ = 0;
};

std::string stripTrailingBlanks(std::string_view text) {
  const std::size_t last = text.find_last_not_of(' ');
  return std::string(last == std::string_view::npos ? std::string_view{}
                                                    : text.substr(0, last + 1));
}

// A data record holds six values in fixed 13-column fields after one blank. Fixed columns are
// read first because a value such as -1.00000E-300 fills its whole field and touches its
// neighbour; a record whose trailing blanks were trimmed by some tool falls back to words.
std::optional<std::array<double, 6>> parseRecord(std::string_view line) {
  std::array<double, 6> values{};
  if (line.size() >= kFixedRecordWidth && trimmed(line.substr(kFixedRecordWidth)).empty()) {
    bool allParsed = true;
    for (std::size_t k = 0; k < kValuesPerRecord && allParsed; ++k) {
      const auto value = parseNumber(line.substr(1 + k * kValueWidth, kValueWidth));
      if (value) {
        values[k] = *value;
      } else {
        allParsed = false;
      }
    }
    if (allParsed) return values;
  }
  const std::vector<std::string_view> words = splitWords(line);
  if (words.size() != kValuesPerRecord) return std::nullopt;
  for (std::size_t k = 0; k < kValuesPerRecord; ++k) {
    const auto value = parseNumber(words[k]);
    if (!value) return std::nullopt;
    values[k] = *value;
  }
  return values;
}

bool parseHeader(LineCursor& cursor, RequestFileData& data, std::size_t& requestCount,
                 std::string* error) {
  if (cursor.atEnd()) {
    *error = cursor.whereEnd("empty file, not a request file");
    return false;
  }
  const std::string_view first = cursor.next();
  if (trimmed(first).substr(0, 4) != "A.R3") {
    *error = cursor.where("not a request file: line 1 does not begin with \"A.R3\"");
    return false;
  }
  if (first.size() > kStampBegin) {
    data.header.stamp = std::string(trimmed(first.substr(kStampBegin, kStampWidth)));
  }
  if (cursor.atEnd()) {
    *error = cursor.whereEnd("missing title line");
    return false;
  }
  data.header.title = stripTrailingBlanks(cursor.next());
  if (cursor.atEnd()) {
    *error = cursor.whereEnd("missing line with the number of requests and the units");
    return false;
  }
  const std::vector<std::string_view> words = splitWords(cursor.next());
  const auto count = words.size() == 3 ? parseInteger(words[0]) : std::nullopt;
  const auto scale = words.size() == 3 ? parseNumber(words[2]) : std::nullopt;
  if (!count || *count < 0 || !scale) {
    *error = cursor.where(
        "expected the number of requests, the units token and the length scale "
        "(e.g. \"    5     M_KGS_N_RACA 1.000000000000000E+00\")");
    return false;
  }
  requestCount = static_cast<std::size_t>(*count);
  data.header.unitsToken = std::string(words[1]);
  data.header.lengthScale = *scale;
  return true;
}

bool parseDirectory(LineCursor& cursor, std::size_t requestCount, RequestFileData& data,
                    std::string* error) {
  for (std::size_t k = 0; k < requestCount; ++k) {
    if (cursor.atEnd()) {
      *error = cursor.whereEnd("directory ends after " + std::to_string(k) + " of " +
                               std::to_string(requestCount) + " requests");
      return false;
    }
    const std::vector<std::string_view> words = splitWords(cursor.next());
    std::array<long, 5> numbers{};
    bool valid = words.size() == numbers.size();
    for (std::size_t w = 0; valid && w < numbers.size(); ++w) {
      const auto number = parseInteger(words[w]);
      valid = number.has_value();
      if (valid) numbers[w] = *number;
    }
    if (!valid) {
      *error = cursor.where(
          "expected a directory record of five integers (id, type, I marker, "
          "J marker, comment length in words) for request " +
          std::to_string(k + 1) + " of " + std::to_string(requestCount));
      return false;
    }
    RequestEntry entry;
    entry.id = numbers[0];
    entry.type = static_cast<int>(numbers[1]);
    entry.iMarker = numbers[2];
    entry.jMarker = numbers[3];
    // A comment of zero words may be an empty record or no record at all; accept both.
    const bool hasCommentRecord =
        numbers[4] > 0 || (!cursor.atEnd() && trimmed(cursor.peek()).empty());
    if (hasCommentRecord) {
      if (cursor.atEnd()) {
        *error =
            cursor.whereEnd("missing the comment record of REQUEST/" + std::to_string(entry.id));
        return false;
      }
      entry.comment = stripTrailingBlanks(cursor.next());
    }
    data.entries.push_back(std::move(entry));
  }
  return true;
}

bool parseSteps(LineCursor& cursor, RequestFileData& data, std::string* error) {
  const std::size_t requestCount = data.entries.size();
  while (!cursor.atEnd()) {
    const std::string_view timeLine = cursor.next();
    // A final line end leaves nothing behind; blank lines between blocks are tolerated.
    if (trimmed(timeLine).empty()) continue;
    const std::vector<std::string_view> words = splitWords(timeLine);
    const auto time = words.size() == 1 ? parseNumber(words[0]) : std::nullopt;
    if (!time) {
      *error = cursor.where("expected a time record (one number) after " +
                            std::to_string(data.steps.size()) + " complete output steps");
      return false;
    }
    RequestFileStep step;
    step.time = *time;
    step.rows.reserve(requestCount);
    for (std::size_t k = 0; k < requestCount; ++k) {
      const std::string what =
          "REQUEST/" + std::to_string(data.entries[k].id) + " at time " + std::string(words[0]);
      if (cursor.atEnd()) {
        *error = cursor.whereEnd("output step is cut short: no record for " + what);
        return false;
      }
      const auto values = parseRecord(cursor.next());
      if (!values) {
        *error = cursor.where("expected six numbers for " + what);
        return false;
      }
      step.rows.push_back(*values);
    }
    data.steps.push_back(std::move(step));
  }
  return true;
}

}  // namespace

int RequestFileData::entryIndex(long id) const {
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (entries[k].id == id) return static_cast<int>(k);
  }
  return -1;
}

std::optional<RequestFileData> parseRequestFile(std::string_view text, const std::string& name,
                                                std::string* error) {
  std::string ignored;
  if (error == nullptr) error = &ignored;
  LineCursor cursor(text, name);
  RequestFileData data;
  std::size_t requestCount = 0;
  if (!parseHeader(cursor, data, requestCount, error)) return std::nullopt;
  if (!parseDirectory(cursor, requestCount, data, error)) return std::nullopt;
  if (!parseSteps(cursor, data, error)) return std::nullopt;
  return data;
}

std::optional<RequestFileData> readRequestFile(const std::string& path, std::string* error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (error) *error = path + ": cannot open request file";
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    if (error) *error = path + ": cannot read request file";
    return std::nullopt;
  }
  return parseRequestFile(text.str(), path, error);
}

std::vector<RequestFileStep> lastStepPerTime(const std::vector<RequestFileStep>& steps) {
  std::vector<RequestFileStep> kept;
  kept.reserve(steps.size());
  for (const RequestFileStep& step : steps) {
    // Times are compared as printed: two records of one output time parse to the same double.
    if (!kept.empty() && kept.back().time == step.time) {
      kept.back() = step;
    } else {
      kept.push_back(step);
    }
  }
  return kept;
}

}  // namespace openmss::output
