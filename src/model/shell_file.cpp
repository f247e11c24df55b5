#include "model/shell_file.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace openmss::model {
namespace {

std::string lowerExtension(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// Whitespace-separated numbers with the line each came from.
class Tokens {
 public:
  explicit Tokens(std::istream& in) {
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      std::istringstream s(line);
      std::string w;
      while (s >> w) words_.push_back({w, n});
    }
  }
  bool number(double& out, std::string& why, const char* what) {
    if (k_ >= words_.size()) {
      why = std::string("the file ends where ") + what + " is expected";
      return false;
    }
    const auto& [w, line] = words_[k_++];
    char* end = nullptr;
    out = std::strtod(w.c_str(), &end);
    if (end == w.c_str() || *end != '\0') {
      why = "line " + std::to_string(line) + ": '" + w + "' is not a number (" + what + ")";
      return false;
    }
    return true;
  }
  bool integer(int& out, std::string& why, const char* what) {
    double v = 0.0;
    if (!number(v, why, what)) return false;
    if (v != static_cast<int>(v)) {
      why = "line " + std::to_string(words_[k_ - 1].second) + ": " + what + " is not an integer";
      return false;
    }
    out = static_cast<int>(v);
    return true;
  }
  int line() const { return k_ == 0 ? 1 : words_[k_ - 1].second; }

 private:
  std::vector<std::pair<std::string, int>> words_;
  size_t k_ = 0;
};

// ADAMS shell: "np nf", the scale, np points "x y z", then nf faces "n i1 ... in" with 1-based
// point indices; a polygon of n > 3 corners is split into a fan of triangles from its first.
std::optional<TriangleMesh> readShl(std::istream& in, std::string& why) {
  Tokens t(in);
  int np = 0, nf = 0;
  double scale = 1.0;
  if (!t.integer(np, why, "the number of points") || !t.integer(nf, why, "the number of faces") ||
      !t.number(scale, why, "the scale"))
    return std::nullopt;
  if (np < 4 || nf < 4 || !(scale > 0.0)) {
    why = "it declares " + std::to_string(np) + " points, " + std::to_string(nf) +
          " faces and scale " + std::to_string(scale) +
          ": a closed shell needs at least 4 of each and a positive scale";
    return std::nullopt;
  }
  TriangleMesh m;
  for (int k = 0; k < np; ++k) {
    Eigen::Vector3d p;
    for (int c = 0; c < 3; ++c)
      if (!t.number(p[c], why, "a point coordinate")) return std::nullopt;
    m.vertices.push_back(scale * p);
  }
  for (int f = 0; f < nf; ++f) {
    int n = 0;
    if (!t.integer(n, why, "a face's number of corners")) return std::nullopt;
    if (n < 3) {
      why = "line " + std::to_string(t.line()) + ": a face with " + std::to_string(n) +
            " corners (at least 3)";
      return std::nullopt;
    }
    std::vector<int> corner(static_cast<size_t>(n));
    for (int& c : corner) {
      if (!t.integer(c, why, "a face corner")) return std::nullopt;
      if (c < 1 || c > np) {
        why = "line " + std::to_string(t.line()) + ": face corner " + std::to_string(c) +
              " is not a point number 1.." + std::to_string(np);
        return std::nullopt;
      }
      --c;
    }
    for (int k = 1; k + 1 < n; ++k) m.triangles.push_back({corner[0], corner[k], corner[k + 1]});
  }
  return m;
}

// STL corners merged by exact coordinates (std::map: a fixed order, deterministic indices).
class VertexPool {
 public:
  explicit VertexPool(TriangleMesh& m) : m_(m) {}
  int add(const Eigen::Vector3d& p) {
    const auto [it, fresh] = index_.emplace(std::array<double, 3>{p.x(), p.y(), p.z()},
                                            static_cast<int>(m_.vertices.size()));
    if (fresh) m_.vertices.push_back(p);
    return it->second;
  }

 private:
  TriangleMesh& m_;
  std::map<std::array<double, 3>, int> index_;
};

std::optional<TriangleMesh> readStlText(std::istream& in, std::string& why) {
  TriangleMesh m;
  VertexPool pool(m);
  std::string line;
  std::vector<int> corners;
  for (int n = 1; std::getline(in, line); ++n) {
    std::istringstream s(line);
    std::string word;
    if (!(s >> word)) continue;
    std::transform(word.begin(), word.end(), word.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (word == "vertex") {
      Eigen::Vector3d p;
      if (!(s >> p.x() >> p.y() >> p.z())) {
        why = "line " + std::to_string(n) + ": a vertex needs three numbers";
        return std::nullopt;
      }
      corners.push_back(pool.add(p));
    } else if (word == "endfacet") {
      if (corners.size() != 3) {
        why = "line " + std::to_string(n) + ": a facet with " + std::to_string(corners.size()) +
              " vertices (3 expected)";
        return std::nullopt;
      }
      m.triangles.push_back({corners[0], corners[1], corners[2]});
      corners.clear();
    }
  }
  if (m.triangles.size() < 4) {
    why = "it holds " + std::to_string(m.triangles.size()) +
          " facets: a closed shell needs at least 4";
    return std::nullopt;
  }
  return m;
}

std::optional<TriangleMesh> readStlBinary(const std::string& bytes, std::string& why) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  TriangleMesh m;
  VertexPool pool(m);
  for (std::uint32_t f = 0; f < count; ++f) {
    const char* rec = bytes.data() + 84 + 50 * static_cast<size_t>(f) + 12;  // past the normal
    std::array<int, 3> tri{};
    for (int c = 0; c < 3; ++c) {
      float xyz[3];
      std::memcpy(xyz, rec + 12 * c, 12);
      tri[c] = pool.add(Eigen::Vector3d(xyz[0], xyz[1], xyz[2]));
    }
    m.triangles.push_back(tri);
  }
  if (m.triangles.size() < 4) {
    why = "it holds " + std::to_string(count) + " facets: a closed shell needs at least 4";
    return std::nullopt;
  }
  return m;
}

}  // namespace

std::optional<TriangleMesh> readShellFile(const std::string& path, std::string& why) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    why = "it cannot be opened";
    return std::nullopt;
  }
  std::ostringstream all;
  all << in.rdbuf();
  const std::string bytes = all.str();
  const std::string ext = lowerExtension(path);
  std::optional<TriangleMesh> m;
  if (ext == "shl") {
    std::istringstream s(bytes);
    m = readShl(s, why);
  } else if (ext == "stl") {
    // Binary when the size is that of the count in its header (an ASCII file may also start
    // with "solid", so the size decides).
    std::uint32_t count = 0;
    if (bytes.size() >= 84) std::memcpy(&count, bytes.data() + 80, 4);
    if (bytes.size() >= 84 && bytes.size() == 84 + 50 * static_cast<size_t>(count)) {
      m = readStlBinary(bytes, why);
    } else {
      std::istringstream s(bytes);
      m = readStlText(s, why);
    }
  } else {
    why = "its kind ('." + ext + "') is not a shell the solver reads (.shl or .stl)";
    return std::nullopt;
  }
  if (m) m->file = path;
  return m;
}

}  // namespace openmss::model
