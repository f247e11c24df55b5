#include "analysis/state_matrices.hpp"

#include <cstdio>
#include <cstring>

namespace openmss::analysis {
namespace {

class File {
 public:
  explicit File(const std::string& path) : f_(std::fopen(path.c_str(), "w")) {}
  ~File() {
    if (f_) std::fclose(f_);
  }
  File(const File&) = delete;
  File& operator=(const File&) = delete;
  std::FILE* get() const { return f_; }
  bool close() {
    const bool ok = f_ && std::fclose(f_) == 0;
    f_ = nullptr;
    return ok;
  }

 private:
  std::FILE* f_;
};

// Whitespace-separated rows, 17 significant digits: every double reads back exactly.
// Identifier files hold whole numbers and are written as such.
bool writeFlat(const std::string& path, const Eigen::MatrixXd& m, std::string* error,
               bool integers = false) {
  File f(path);
  if (!f.get()) {
    if (error) *error = "cannot create " + path;
    return false;
  }
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    for (Eigen::Index c = 0; c < m.cols(); ++c)
      if (integers)
        std::fprintf(f.get(), c ? " %.0f" : "%.0f", m(r, c));
      else
        std::fprintf(f.get(), c ? " %.16e" : "%.16e", m(r, c) == 0.0 ? 0.0 : m(r, c));
    std::fputc('\n', f.get());
  }
  if (!f.close()) {
    if (error) *error = "cannot write " + path;
    return false;
  }
  return true;
}

Eigen::MatrixXd idColumn(const std::vector<int>& variables, const model::Model& model) {
  Eigen::MatrixXd ids(static_cast<Eigen::Index>(variables.size()), 1);
  for (size_t i = 0; i < variables.size(); ++i)
    ids(static_cast<Eigen::Index>(i), 0) = static_cast<double>(model.variables[variables[i]].id);
  return ids;
}

// MATRIXx save layout: a header line "NAME rows cols 0(1P3E25.17)" (name in 10 columns, the
// sizes in 5 each, 0 = real), then the entries by columns, three per line in E25.17.
void matsave(std::FILE* f, const char* name, const Eigen::MatrixXd& m) {
  std::fprintf(f, "%-10s%5ld%5ld%5d(1P3E25.17)\n", name, static_cast<long>(m.rows()),
               static_cast<long>(m.cols()), 0);
  int onLine = 0;
  for (Eigen::Index c = 0; c < m.cols(); ++c)
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
      std::fprintf(f, "%25.17E", m(r, c) == 0.0 ? 0.0 : m(r, c));
      if (++onLine == 3) {
        std::fputc('\n', f);
        onLine = 0;
      }
    }
  if (onLine) std::fputc('\n', f);
}

}  // namespace

Eigen::MatrixXd stateIdentifiers(const LinearSystem& linear, const model::Model& model) {
  const auto states = static_cast<Eigen::Index>(linear.stateNames.size());
  Eigen::MatrixXd ids = Eigen::MatrixXd::Zero(states, 3);
  for (Eigen::Index s = 0; s < states; ++s) {
    const std::string& name = linear.stateNames[static_cast<size_t>(s)];
    char kind[16] = {0}, coordinate[8] = {0};
    long id = 0, index = 1;
    if (std::sscanf(name.c_str(), "PART/%ld %7s", &id, coordinate) == 2) {
      static const char* codes[12] = {"X",  "Y",  "Z",  "RX", "RY", "RZ",
                                      "VX", "VY", "VZ", "WX", "WY", "WZ"};
      for (int k = 0; k < 12; ++k)
        if (std::strcmp(coordinate, codes[k]) == 0) ids(s, 1) = k + 1;
    } else if (std::sscanf(name.c_str(), "%15[A-Z]/%ld X%ld", kind, &id, &index) >= 2) {
      const std::string k = kind;
      ids(s, 1) = k == "DIFF" ? 20 : k == "LSE" ? 21 : k == "TFSISO" ? 22 : 0;
    } else {
      continue;
    }
    ids(s, 0) = static_cast<double>(id);
    ids(s, 2) = static_cast<double>(index);
  }
  (void)model;
  return ids;
}

bool writeMatlabStateMatrices(const std::string& base, const LinearSystem& linear,
                              const model::Model& model, std::vector<std::string>& written,
                              std::string* error) {
  const struct {
    const char* extension;
    const Eigen::MatrixXd& matrix;
  } matrices[] = {{".a", linear.a}, {".b", linear.b}, {".c", linear.c}, {".d", linear.d}};
  for (const auto& m : matrices) {
    if (m.matrix.size() == 0) continue;  // no inputs or no outputs: fewer files (docs/theory.md §8b, "STATEMAT files")
    if (!writeFlat(base + m.extension, m.matrix, error)) return false;
    written.push_back(base + m.extension);
  }
  if (!writeFlat(base + ".st", stateIdentifiers(linear, model), error, true)) return false;
  written.push_back(base + ".st");
  const std::vector<int>& inputs = linear.inputVariables;
  const std::vector<int>& outputs = linear.outputVariables;
  if (!inputs.empty()) {
    if (!writeFlat(base + ".pi", idColumn(inputs, model), error, true)) return false;
    written.push_back(base + ".pi");
  }
  if (!outputs.empty()) {
    if (!writeFlat(base + ".po", idColumn(outputs, model), error, true)) return false;
    written.push_back(base + ".po");
  }
  return true;
}

bool writeMatrixxStateMatrices(const std::string& base, const LinearSystem& linear,
                               const model::Model& model, std::vector<std::string>& written,
                               std::string* error) {
  const std::string path = base + ".mat";
  File f(path);
  if (!f.get()) {
    if (error) *error = "cannot create " + path;
    return false;
  }
  std::fprintf(f.get(), "MATRIXx MATSAVE (OpenMSS LINEAR/STATEMAT) %.40s\n", model.title.c_str());
  matsave(f.get(), "A", linear.a);
  matsave(f.get(), "B", linear.b);
  matsave(f.get(), "C", linear.c);
  matsave(f.get(), "D", linear.d);
  matsave(f.get(), "STATES", stateIdentifiers(linear, model));
  matsave(f.get(), "PINPUT", idColumn(linear.inputVariables, model));
  matsave(f.get(), "POUTPUT", idColumn(linear.outputVariables, model));
  if (!f.close()) {
    if (error) *error = "cannot write " + path;
    return false;
  }
  written.push_back(path);
  return true;
}

}  // namespace openmss::analysis
