#include "language/dataset.hpp"

namespace openmss::language {

std::string Statement::subject() const {
  std::string s = name.str();
  if (id) s += "/" + std::to_string(*id);
  return s;
}

const Argument* Statement::find(std::string_view canonicalName) const {
  // The last occurrence wins, as ADAMS keeps the last value of a repeated argument.
  const Argument* found = nullptr;
  for (const auto& a : args)
    if (a.name == canonicalName) found = &a;
  return found;
}

}  // namespace openmss::language
