#pragma once
// A string of 16 bytes for the parsed statement tree (language/dataset.hpp), where a data set
// of 500,000 statements holds some four million short names and tokens: std::string takes 32
// bytes for each, CompactString 16, and like std::string it allocates nothing up to 15
// characters (docs/performance.md, "Memory of a parsed data set").
//
// Layout: 16 bytes. Up to 15 characters are stored in place; the last byte then holds
// 15 - size, which is 0 (a terminating NUL) for a string of 15. Longer strings live on the
// heap (size + 1 bytes, NUL-terminated); the last byte is then kHeapTag and the first 12 bytes
// hold the pointer and the size. c_str() is always NUL-terminated.
//
// It reads like a std::string where the tree is used: it compares with strings and literals,
// concatenates with '+', converts implicitly to std::string_view and to std::string (for
// functions taking const std::string&) and prints with <<.

#include <compare>
#include <cstdint>
#include <cstring>
#include <iosfwd>
#include <string>
#include <string_view>

namespace openmss {

class CompactString {
 public:
  using size_type = std::size_t;
  static constexpr size_type npos = std::string_view::npos;

  CompactString() noexcept { setInline(0); }
  CompactString(std::string_view s) { assign(s); }  // NOLINT: implicit, reads like a string
  CompactString(const std::string& s) { assign(s); }
  CompactString(const char* s) { assign(std::string_view(s)); }
  CompactString(const CompactString& o) { assign(o.view()); }
  CompactString(CompactString&& o) noexcept {
    std::memcpy(bytes_, o.bytes_, sizeof bytes_);
    o.setInline(0);
  }
  ~CompactString() { release(); }

  CompactString& operator=(const CompactString& o) {
    if (this != &o) {
      CompactString copy(o);
      swap(copy);
    }
    return *this;
  }
  CompactString& operator=(CompactString&& o) noexcept {
    if (this != &o) {
      release();
      std::memcpy(bytes_, o.bytes_, sizeof bytes_);
      o.setInline(0);
    }
    return *this;
  }
  CompactString& operator=(std::string_view s) {
    CompactString copy(s);
    swap(copy);
    return *this;
  }
  CompactString& operator=(const std::string& s) { return *this = std::string_view(s); }
  CompactString& operator=(const char* s) { return *this = std::string_view(s); }

  void swap(CompactString& o) noexcept {
    unsigned char t[sizeof bytes_];
    std::memcpy(t, bytes_, sizeof bytes_);
    std::memcpy(bytes_, o.bytes_, sizeof bytes_);
    std::memcpy(o.bytes_, t, sizeof bytes_);
  }

  size_type size() const noexcept {
    if (!onHeap()) return kInline - bytes_[kInline];
    std::uint32_t n;
    std::memcpy(&n, bytes_ + sizeof(char*), sizeof n);
    return n;
  }
  size_type length() const noexcept { return size(); }
  bool empty() const noexcept { return size() == 0; }
  const char* data() const noexcept {
    if (!onHeap()) return reinterpret_cast<const char*>(bytes_);
    const char* p;
    std::memcpy(&p, bytes_, sizeof p);
    return p;
  }
  const char* c_str() const noexcept { return data(); }
  const char* begin() const noexcept { return data(); }
  const char* end() const noexcept { return data() + size(); }
  char operator[](size_type k) const noexcept { return data()[k]; }
  char front() const noexcept { return data()[0]; }
  char back() const noexcept { return data()[size() - 1]; }

  std::string_view view() const noexcept { return {data(), size()}; }
  std::string str() const { return std::string(view()); }
  operator std::string_view() const noexcept { return view(); }
  operator std::string() const { return str(); }

  std::string substr(size_type pos = 0, size_type n = npos) const {
    return std::string(view().substr(pos, n));
  }
  size_type find(std::string_view s, size_type pos = 0) const noexcept {
    return view().find(s, pos);
  }
  size_type find(char c, size_type pos = 0) const noexcept { return view().find(c, pos); }
  size_type rfind(char c, size_type pos = npos) const noexcept { return view().rfind(c, pos); }
  size_type rfind(std::string_view s, size_type pos = npos) const noexcept {
    return view().rfind(s, pos);
  }
  size_type find_first_of(std::string_view s, size_type pos = 0) const noexcept {
    return view().find_first_of(s, pos);
  }
  size_type find_first_not_of(std::string_view s, size_type pos = 0) const noexcept {
    return view().find_first_not_of(s, pos);
  }
  size_type find_last_of(std::string_view s, size_type pos = npos) const noexcept {
    return view().find_last_of(s, pos);
  }
  int compare(std::string_view s) const noexcept { return view().compare(s); }
  bool starts_with(std::string_view s) const noexcept { return view().starts_with(s); }
  bool ends_with(std::string_view s) const noexcept { return view().ends_with(s); }

  friend bool operator==(const CompactString& a, const CompactString& b) noexcept {
    return a.view() == b.view();
  }
  friend bool operator==(const CompactString& a, std::string_view b) noexcept {
    return a.view() == b;
  }
  friend bool operator==(const CompactString& a, const std::string& b) noexcept {
    return a.view() == std::string_view(b);
  }
  friend bool operator==(const CompactString& a, const char* b) noexcept {
    return a.view() == std::string_view(b);
  }
  friend std::strong_ordering operator<=>(const CompactString& a, const CompactString& b) noexcept {
    return a.view() <=> b.view();
  }
  friend std::strong_ordering operator<=>(const CompactString& a, std::string_view b) noexcept {
    return a.view() <=> b;
  }

 private:
  static constexpr size_type kInline = 15;  // characters stored in place
  static constexpr unsigned char kHeapTag = 0xFF;

  bool onHeap() const noexcept { return bytes_[kInline] == kHeapTag; }
  void setInline(size_type n) noexcept {
    bytes_[n] = 0;
    bytes_[kInline] = static_cast<unsigned char>(kInline - n);
  }
  void assign(std::string_view s);  // compact_string.cpp
  void release() noexcept {
    if (!onHeap()) return;
    char* p;
    std::memcpy(&p, bytes_, sizeof p);
    delete[] p;
    setInline(0);
  }

  unsigned char bytes_[16];
};

static_assert(sizeof(CompactString) == 16);

// Concatenation gives a std::string, as it does for std::string operands.
std::string operator+(const CompactString& a, std::string_view b);
std::string operator+(std::string_view a, const CompactString& b);
std::string operator+(const CompactString& a, const CompactString& b);
std::string operator+(const CompactString& a, const std::string& b);
std::string operator+(const std::string& a, const CompactString& b);
std::string operator+(const CompactString& a, const char* b);
std::string operator+(const char* a, const CompactString& b);
std::string operator+(const CompactString& a, char b);
std::string operator+(char a, const CompactString& b);
std::string operator+(std::string&& a, const CompactString& b);
std::ostream& operator<<(std::ostream& out, const CompactString& s);

}  // namespace openmss
