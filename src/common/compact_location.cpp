#include "common/compact_location.hpp"

#include <deque>
#include <mutex>
#include <stdexcept>
#include <unordered_map>

namespace openmss {

namespace {

struct FileNameTable {
  std::mutex mutex;
  std::deque<std::string> names{std::string()};  // a deque: entries never move
  std::unordered_map<std::string_view, std::uint32_t> index{{std::string_view(), 0u}};
};

FileNameTable& table() {
  static FileNameTable* t = new FileNameTable;  // never destroyed: used until exit
  return *t;
}

}  // namespace

std::uint32_t internFileName(std::string_view file) {
  FileNameTable& t = table();
  std::lock_guard<std::mutex> lock(t.mutex);
  if (auto it = t.index.find(file); it != t.index.end()) return it->second;
  const auto k = static_cast<std::uint32_t>(t.names.size());
  t.names.emplace_back(file);
  t.index.emplace(std::string_view(t.names.back()), k);
  return k;
}

const std::string& internedFileName(std::uint32_t index) {
  FileNameTable& t = table();
  std::lock_guard<std::mutex> lock(t.mutex);
  if (index >= t.names.size()) throw std::out_of_range("internedFileName: unknown index");
  return t.names[index];
}

}  // namespace openmss
