// Free helpers of the expression parser: name suggestions, usage texts and syntax-tree builders
// (declared in expr/parser_detail.hpp).
#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "expr/parser_detail.hpp"

namespace openmss::expr::parsing {
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({above + 1, row[j - 1] + 1, substitution});
      diagonal = above;
    }
  }
  return row[b.size()];
}

bool isCallable(NameKind kind) {
  return kind == NameKind::Builtin || kind == NameKind::Conditional ||
         kind == NameKind::HostFunction || kind == NameKind::Unsupported ||
         kind == NameKind::DataFunction || kind == NameKind::VectorHost ||
         kind == NameKind::VectorFunction || kind == NameKind::User || kind == NameKind::Delay;
}

// The closest known name of the wanted sort, when it is close enough to be a likely typo.
std::string suggestion(const std::string& upper, bool wantCallable) {
  const std::size_t limit = upper.size() <= 3 ? 1 : 2;
  std::string best;
  std::size_t bestDistance = limit + 1;
  for (const NameInfo& info : allNames()) {
    if (isCallable(info.kind) != wantCallable) continue;
    const std::size_t distance = editDistance(upper, info.name);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = std::string(info.name);
    }
  }
  return best;
}

std::string usageOf(const NameInfo& info) {
  if (!info.usage.empty() && info.usage.front() == '(') {
    return std::string(info.name) + std::string(info.usage);
  }
  return std::string(info.usage);
}

std::string countPhrase(int count) {
  return std::to_string(count) + (count == 1 ? " argument" : " arguments");
}

std::string allowedCounts(const NameInfo& info) {
  if (info.minArguments == info.maxArguments) return std::to_string(info.minArguments);
  return std::to_string(info.minArguments) + " to " + std::to_string(info.maxArguments);
}

SyntaxNode numberNode(double value, int column) {
  SyntaxNode node;
  node.kind = NodeKind::Number;
  node.column = column;
  node.number = value;
  return node;
}

SyntaxNode makeNode(NodeKind kind, int column, std::vector<SyntaxNode> children) {
  SyntaxNode node;
  node.kind = kind;
  node.column = column;
  node.children = std::move(children);
  return node;
}

// True when a subtree reads neither TIME nor the host nor model data.
bool constantTree(const SyntaxNode& node) {
  if (node.kind == NodeKind::Time || node.kind == NodeKind::Host ||
      node.kind == NodeKind::DataCall || node.kind == NodeKind::Delay) {
    return false;
  }
  for (const SyntaxNode& child : node.children) {
    if (!constantTree(child)) return false;
  }
  return true;
}

Value scalarValue(SyntaxNode node) {
  Value v;
  v.node = std::move(node);
  return v;
}

SyntaxNode dotProduct(const std::array<SyntaxNode, 3>& a, const std::array<SyntaxNode, 3>& b,
                      int column) {
  SyntaxNode sum = makeNode(NodeKind::Multiply, column, {a[0], b[0]});
  for (int k = 1; k < 3; ++k) {
    sum = makeNode(NodeKind::Add, column,
                   {std::move(sum), makeNode(NodeKind::Multiply, column, {a[k], b[k]})});
  }
  return sum;
}

SyntaxNode magnitude(const std::array<SyntaxNode, 3>& a, int column) {
  SyntaxNode root = makeNode(NodeKind::Call, column, {dotProduct(a, a, column)});
  root.builtin = Builtin::Sqrt;
  return root;
}

}  // namespace openmss::expr::parsing
