#include "user/user_library.hpp"

#include <dlfcn.h>

#include <filesystem>

namespace openmss::user {
namespace {

std::string& defaultLibraryPath() {
  static std::string path;
  return path;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

RoutineName splitRoutineName(const std::string& text) {
  const auto colons = text.find("::");
  if (colons == std::string::npos) return {"", text};
  return {text.substr(0, colons), text.substr(colons + 2)};
}

void setDefaultLibrary(const std::string& path) { defaultLibraryPath() = path; }
const std::string& defaultLibrary() { return defaultLibraryPath(); }

std::shared_ptr<Library> Library::open(const std::string& name, const std::string& baseDirectory,
                                       std::string& why) {
  namespace fs = std::filesystem;
  std::vector<fs::path> candidates;
  const fs::path given(name);
  const bool isPath = name.find('/') != std::string::npos;
  const std::vector<fs::path> directories =
      given.is_absolute() ? std::vector<fs::path>{fs::path()}
                          : std::vector<fs::path>{fs::path(baseDirectory), fs::current_path()};
  for (const fs::path& dir : directories) {
    candidates.push_back(dir / given);
    if (!endsWith(name, ".so")) {
      candidates.push_back(dir / (name + ".so"));
      if (!isPath) candidates.push_back(dir / ("lib" + name + ".so"));
    }
  }
  std::string target;
  for (const fs::path& c : candidates) {
    std::error_code ec;
    if (fs::is_regular_file(c, ec)) {
      target = fs::absolute(c, ec).lexically_normal().string();
      break;
    }
  }
  // A bare name found nowhere above: the dynamic loader's own search (LD_LIBRARY_PATH, ...).
  if (target.empty() && !isPath) target = endsWith(name, ".so") ? name : "lib" + name + ".so";
  if (target.empty()) {
    why = "no file " + name + " (looked in " + baseDirectory + " and the working directory)";
    return nullptr;
  }
  // RTLD_NOW: a routine that calls a utility OpenMSS does not export fails here, with the
  // symbol's name, rather than in the middle of a simulation.
  void* handle = dlopen(target.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* err = dlerror();
    why = err ? err : ("cannot load " + target);
    return nullptr;
  }
  return std::shared_ptr<Library>(new Library(handle, target));
}

Library::~Library() {
  if (handle_) dlclose(handle_);
}

void* Library::symbol(const std::string& name) const {
  dlerror();
  return dlsym(handle_, name.c_str());
}

}  // namespace openmss::user
