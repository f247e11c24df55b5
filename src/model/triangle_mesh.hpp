#pragma once
// A closed triangle shell read from an external file (GRAPHICS/..., EXTERNAL with an ADAMS
// .shl or an STL FILE): the contact geometry of docs/theory.md §6c, "Meshes". Vertices are in
// the reference (RM) marker's axes, shared between triangles (an STL's repeated corners are
// merged when read), so that a vertex touches a plane once.

#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

namespace openmss::model {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;  // indices into vertices
  std::string file;                           // where it was read from (messages)
};

}  // namespace openmss::model
