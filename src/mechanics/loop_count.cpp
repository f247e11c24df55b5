#include "mechanics/loop_count.hpp"

#include <cstdint>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

namespace openmss::mechanics {
namespace {

// Above this many independent loops the 2^n combinations are not enumerated.
constexpr int kMaxEnumerated = 16;

int find(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

// True when the edge set (a mask over `edges`) is one simple cycle: every vertex it touches
// has degree two and the edges are connected.
bool isSimpleCycle(const std::vector<char>& inSet, const std::vector<std::pair<int, int>>& edges,
                   int vertices) {
  std::vector<int> degree(vertices, 0);
  std::vector<int> parent(vertices);
  std::iota(parent.begin(), parent.end(), 0);
  int first = -1, count = 0;
  for (size_t e = 0; e < edges.size(); ++e) {
    if (!inSet[e]) continue;
    ++count;
    ++degree[edges[e].first];
    ++degree[edges[e].second];
    parent[find(parent, edges[e].first)] = find(parent, edges[e].second);
    first = edges[e].first;
  }
  if (count == 0) return false;
  const int root = find(parent, first);
  for (int v = 0; v < vertices; ++v) {
    if (degree[v] == 0) continue;
    if (degree[v] != 2 || find(parent, v) != root) return false;
  }
  return true;
}

}  // namespace

LoopCount countLoops(const model::Model& model) {
  const int vertices = static_cast<int>(model.parts.size());
  std::vector<std::pair<int, int>> edges;
  auto add = [&](int iMarker, int jMarker) {
    edges.emplace_back(model.markers[iMarker].part, model.markers[jMarker].part);
  };
  for (const auto& j : model.joints) add(j.iMarker, j.jMarker);
  for (const auto& p : model.jprims) add(p.iMarker, p.jMarker);

  // Spanning forest; every edge that closes a cycle gives one fundamental (independent) loop.
  std::vector<int> parent(vertices);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<std::vector<std::pair<int, int>>> tree(vertices);  // (neighbour, edge)
  std::vector<int> closing;
  for (size_t e = 0; e < edges.size(); ++e) {
    const int a = find(parent, edges[e].first), b = find(parent, edges[e].second);
    if (a == b) {
      closing.push_back(static_cast<int>(e));
    } else {
      parent[a] = b;
      tree[edges[e].first].emplace_back(edges[e].second, static_cast<int>(e));
      tree[edges[e].second].emplace_back(edges[e].first, static_cast<int>(e));
    }
  }
  LoopCount out;
  out.independent = static_cast<int>(closing.size());
  if (out.independent > kMaxEnumerated) {
    out.enumerated = false;
    return out;
  }
  // Tree path from every vertex to its tree root: parent edge and depth.
  std::vector<int> up(vertices, -1), upEdge(vertices, -1), depth(vertices, -1);
  for (int r = 0; r < vertices; ++r) {
    if (depth[r] >= 0) continue;
    depth[r] = 0;
    std::queue<int> q;
    q.push(r);
    while (!q.empty()) {
      const int v = q.front();
      q.pop();
      for (const auto& [w, e] : tree[v])
        if (depth[w] < 0) {
          depth[w] = depth[v] + 1;
          up[w] = v;
          upEdge[w] = e;
          q.push(w);
        }
    }
  }
  std::vector<std::vector<char>> fundamental;
  for (int e : closing) {
    std::vector<char> cycle(edges.size(), 0);
    cycle[e] = 1;
    int a = edges[e].first, b = edges[e].second;
    while (a != b) {
      if (depth[a] < depth[b]) std::swap(a, b);
      cycle[upEdge[a]] ^= 1;
      a = up[a];
    }
    fundamental.push_back(std::move(cycle));
  }
  // Every simple cycle is the sum (mod 2) of a unique set of fundamental cycles: enumerate the
  // sums in Gray-code order and keep those that are one simple cycle.
  std::vector<char> sum(edges.size(), 0);
  int cycles = 0;
  const std::uint32_t combinations = 1u << out.independent;
  for (std::uint32_t g = 1; g < combinations; ++g) {
    const int flip = __builtin_ctz(g);
    for (size_t e = 0; e < edges.size(); ++e) sum[e] ^= fundamental[flip][e];
    if (isSimpleCycle(sum, edges, vertices)) ++cycles;
  }
  out.dependent = cycles - out.independent;
  return out;
}

}  // namespace openmss::mechanics
