#include "common/compact_string.hpp"

#include <limits>
#include <ostream>
#include <stdexcept>

namespace openmss {

void CompactString::assign(std::string_view s) {
  if (s.size() <= kInline) {
    if (!s.empty()) std::memcpy(bytes_, s.data(), s.size());
    setInline(s.size());
    return;
  }
  if (s.size() >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("CompactString: text longer than 4 GB");
  char* p = new char[s.size() + 1];
  std::memcpy(p, s.data(), s.size());
  p[s.size()] = '\0';
  const auto n = static_cast<std::uint32_t>(s.size());
  std::memcpy(bytes_, &p, sizeof p);
  std::memcpy(bytes_ + sizeof p, &n, sizeof n);
  bytes_[kInline] = kHeapTag;
}

namespace {
std::string joined(std::string_view a, std::string_view b) {
  std::string out;
  out.reserve(a.size() + b.size());
  out.append(a);
  out.append(b);
  return out;
}
}  // namespace

std::string operator+(const CompactString& a, std::string_view b) { return joined(a, b); }
std::string operator+(std::string_view a, const CompactString& b) { return joined(a, b); }
std::string operator+(const CompactString& a, const CompactString& b) { return joined(a, b); }
std::string operator+(const CompactString& a, const std::string& b) { return joined(a, b); }
std::string operator+(const std::string& a, const CompactString& b) { return joined(a, b); }
std::string operator+(const CompactString& a, const char* b) { return joined(a, b); }
std::string operator+(const char* a, const CompactString& b) { return joined(a, b); }
std::string operator+(const CompactString& a, char b) { return joined(a, std::string_view(&b, 1)); }
std::string operator+(char a, const CompactString& b) { return joined(std::string_view(&a, 1), b); }
std::string operator+(std::string&& a, const CompactString& b) {
  a.append(b.view());
  return std::move(a);
}

std::ostream& operator<<(std::ostream& out, const CompactString& s) { return out << s.view(); }

}  // namespace openmss
