// OpenMSS embedding API, C++ interface: a thin header-only layer over the C functions of
// openmss.h (the library's only ABI), with exceptions instead of status codes and RAII for the
// solver. docs/embedding.md.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "openmss/openmss.h"

namespace openmss {

// A failed call: what() is openmss_last_error(); file() and line() its location.
class Error : public std::runtime_error {
 public:
  Error(openmss_status status, std::string file, int line)
      : std::runtime_error(openmss_last_error()),
        status_(status),
        file_(std::move(file)),
        line_(line) {}
  openmss_status status() const noexcept { return status_; }
  const std::string& file() const noexcept { return file_; }
  int line() const noexcept { return line_; }

 private:
  openmss_status status_;
  std::string file_;
  int line_;
};

inline void check(openmss_status status) {
  if (status != OPENMSS_OK)
    throw Error(status, openmss_last_error_file(), openmss_last_error_line());
}

class Solver {
 public:
  explicit Solver(const std::string& dataset, const std::string& outputDirectory = ".") {
    check(openmss_open(dataset.c_str(), outputDirectory.c_str(), &solver_));
  }
  ~Solver() { openmss_close(solver_); }
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;
  Solver(Solver&& other) noexcept : solver_(std::exchange(other.solver_, nullptr)) {}
  Solver& operator=(Solver&& other) noexcept {
    std::swap(solver_, other.solver_);
    return *this;
  }

  void command(const std::string& text) { check(openmss_command(solver_, text.c_str())); }
  void initialize() { check(openmss_initialize(solver_)); }
  double time() const {
    double t = 0.0;
    check(openmss_time(solver_, &t));
    return t;
  }
  void advance(double end, int outputSteps = 1) {
    check(openmss_advance(solver_, end, outputSteps));
  }
  void setInputs(long pinputId, const std::vector<double>& values) {
    check(openmss_set_pinput(solver_, pinputId, values.data(), static_cast<int>(values.size())));
  }
  std::vector<double> outputs(long poutputId) const {
    int n = 0;
    check(openmss_poutput_count(solver_, poutputId, &n));
    std::vector<double> v(static_cast<std::size_t>(n));
    check(openmss_get_poutput(solver_, poutputId, v.data(), n));
    return v;
  }
  double variable(long id) const {
    double v = 0.0;
    check(openmss_variable(solver_, id, &v));
    return v;
  }
  std::array<double, 8> request(long id) const {
    std::array<double, 8> v{};
    check(openmss_request(solver_, id, v.data()));
    return v;
  }
  void save(const std::string& path) { check(openmss_save(solver_, path.c_str())); }
  void reload(const std::string& path) { check(openmss_reload(solver_, path.c_str())); }
  openmss_solver* handle() const noexcept { return solver_; }

 private:
  openmss_solver* solver_ = nullptr;
};

}  // namespace openmss
