#include "user/fcl_module.hpp"

#include <dlfcn.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace openmss::user {
namespace {

std::atomic<bool> loaded{false};

// RTLD_DEEPBIND but under a sanitizer, whose run-time refuses it (see open()).

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr int kDeepBind = 0;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
constexpr int kDeepBind = 0;
#else
constexpr int kDeepBind = RTLD_DEEPBIND;
#endif
#else
constexpr int kDeepBind = RTLD_DEEPBIND;
#endif

// Where the module may be: OPENMSS_FCL_MODULE if set (then that path only); else
// openmss/openmss_fcl.so next to the binary holding this code (an installed libopenmss:
// src/capi/CMakeLists.txt installs the module in LIBDIR/openmss; the build tree's libopenmss in
// build/lib finds build/lib/openmss), then the build tree's module (OPENMSS_FCL_MODULE_PATH,
// set by src/CMakeLists.txt) for the program and the tests. An installed library tries its own
// module first: a build tree left behind may hold a module of another version.
std::vector<std::string> candidates() {
  if (const char* env = std::getenv("OPENMSS_FCL_MODULE"); env && *env) return {env};
  std::vector<std::string> paths;
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&fclModuleLoaded), &info) && info.dli_fname) {
    const std::filesystem::path self = std::filesystem::absolute(info.dli_fname);
    paths.push_back((self.parent_path() / "openmss" / "openmss_fcl.so").string());
  }
#ifdef OPENMSS_FCL_MODULE_PATH
  paths.emplace_back(OPENMSS_FCL_MODULE_PATH);
#endif
  return paths;
}

struct Entry {  // the entry point, or null and why
  void* address = nullptr;
  std::string why;
};

Entry open() {
  Entry e;
  for (const std::string& path : candidates()) {
    if (!std::filesystem::exists(path)) {
      e.why += (e.why.empty() ? "" : "; ") + path + ": no such file";
      continue;
    }
    // Never closed: its functions are called until the process ends. RTLD_DEEPBIND: libfcl's own
    // 29,000 symbols are looked up in the module's scope first, not after every library of the
    // program (16 M more instructions without it, docs/performance.md); sanitizer run-times
    // refuse it.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL | kDeepBind);
    if (!handle) {
      const char* message = ::dlerror();
      e.why += (e.why.empty() ? "" : "; ") + path + ": " + (message ? message : "dlopen failed");
      continue;
    }
    e.address = ::dlsym(handle, kFclEntryName);
    if (e.address) {
      loaded = true;
      e.why.clear();
      return e;
    }
    e.why += (e.why.empty() ? "" : "; ") + path + ": no symbol " + kFclEntryName;
  }
  if (e.why.empty()) e.why = "no path to try";
  return e;
}

}  // namespace

void* fclModuleEntry(std::string& why) {
  // Opened once per process; a failure is not kept, so that a later call may find the module
  // (its callers refuse the model: a failure is never on the path of a run).
  static std::mutex lock;
  static void* address = nullptr;
  std::lock_guard<std::mutex> guard(lock);
  if (!address) {
    Entry e = open();
    address = e.address;
    why = std::move(e.why);
  }
  return address;
}

bool fclModuleLoaded() { return loaded; }

}  // namespace openmss::user
