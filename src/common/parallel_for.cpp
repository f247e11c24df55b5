#include "common/parallel_for.hpp"

#include <unistd.h>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace openmss {
namespace {

// The value of OPENMSS_THREADS, or 0 when it is not a whole number 1..kMaxThreads.
int parseThreads(const char* text) {
  if (text == nullptr || *text == '\0') return 0;
  int value = 0;
  for (const char* c = text; *c != '\0'; ++c) {
    if (*c < '0' || *c > '9') return 0;
    value = 10 * value + (*c - '0');
    if (value > kMaxThreads) return 0;
  }
  return value;
}

int hardwareThreads() {
  const unsigned cores = std::thread::hardware_concurrency();
  return cores == 0 ? 1 : static_cast<int>(cores < kMaxThreads ? cores : kMaxThreads);
}

std::atomic<int> testOverride{0};
// True on the pool's workers and on a thread running a parallelFor: nested calls run inline.
thread_local bool insideParallel = false;

// Persistent workers 1..size-1 (the caller is block 0). Jobs are handed over under one mutex
// and a generation number; workers sleep on a condition variable between jobs (no spinning:
// the machines this runs on are often shared).
class Pool {
 public:
  explicit Pool(int workers) {
    for (int w = 1; w <= workers; ++w) threads_.emplace_back([this, w] { run(w); });
  }
  int workers() const { return static_cast<int>(threads_.size()); }
  void grow(int workers) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (int w = static_cast<int>(threads_.size()) + 1; w <= workers; ++w)
      threads_.emplace_back([this, w, g = generation_] { run(w, g); });
  }
  // Runs blocks 1..blocks-1 on the workers and block 0 here.
  void dispatch(int count, int blocks, const std::function<void(int, int, int)>& body) {
    std::vector<std::exception_ptr> errors(static_cast<size_t>(blocks));
    {
      std::lock_guard<std::mutex> lock(mutex_);
      body_ = &body;
      count_ = count;
      blocks_ = blocks;
      errors_ = &errors;
      pending_ = blocks - 1;
      ++generation_;
    }
    start_.notify_all();
    runBlock(0);
    {
      std::unique_lock<std::mutex> lock(mutex_);
      done_.wait(lock, [this] { return pending_ == 0; });
      body_ = nullptr;
    }
    for (const std::exception_ptr& e : errors)
      if (e) std::rethrow_exception(e);
  }

 private:
  void runBlock(int block) {
    const auto n = static_cast<std::int64_t>(count_);
    const int begin = static_cast<int>(n * block / blocks_);
    const int end = static_cast<int>(n * (block + 1) / blocks_);
    try {
      (*body_)(block, begin, end);
    } catch (...) {
      (*errors_)[static_cast<size_t>(block)] = std::current_exception();
    }
  }
  void run(int w, std::uint64_t seen = 0) {
    insideParallel = true;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      start_.wait(lock, [&] { return generation_ != seen; });
      seen = generation_;
      if (w >= blocks_) continue;  // not needed for this job
      lock.unlock();
      runBlock(w);
      lock.lock();
      if (--pending_ == 0) done_.notify_one();
    }
  }

  std::mutex mutex_;
  std::condition_variable start_, done_;
  std::vector<std::thread> threads_;
  std::uint64_t generation_ = 0;
  const std::function<void(int, int, int)>* body_ = nullptr;
  int count_ = 0, blocks_ = 0, pending_ = 0;
  std::vector<std::exception_ptr>* errors_ = nullptr;
};

// One pool per process, never destroyed (its workers sleep until the process ends; joining
// them from a static destructor would race with other exit-time destructors). A child made by
// fork() has none of the parent's threads, so it makes its own.
std::mutex poolMutex;
Pool* pool = nullptr;
pid_t poolOwner = 0;

}  // namespace

std::string threadCountProblem() {
  const char* text = std::getenv("OPENMSS_THREADS");
  if (text == nullptr || *text == '\0' || parseThreads(text) > 0) return {};
  return "OPENMSS_THREADS=" + std::string(text) +
         ": expected a whole number of threads from 1 to " + std::to_string(kMaxThreads) +
         " (unset: one per core)";
}

int threadCount() {
  if (const int forced = testOverride.load(); forced > 0) return forced;
  static const int fromEnvironment = [] {
    const std::string problem = threadCountProblem();
    if (!problem.empty()) throw std::invalid_argument(problem);
    const int value = parseThreads(std::getenv("OPENMSS_THREADS"));
    return value > 0 ? value : hardwareThreads();
  }();
  return fromEnvironment;
}

void setThreadCountForTesting(int threads) { testOverride.store(threads > 0 ? threads : 0); }

void parallelFor(int count, const std::function<void(int, int, int)>& body) {
  const int threads = threadCount();
  const int blocks = count < threads ? count : threads;
  if (blocks <= 1 || insideParallel) {
    // Inline, but in the same blocks: a body that keeps per-block slots sees the same split.
    for (int b = 0; b < blocks; ++b)
      body(b, static_cast<int>(static_cast<std::int64_t>(count) * b / blocks),
           static_cast<int>(static_cast<std::int64_t>(count) * (b + 1) / blocks));
    return;
  }
  // One job at a time; a second caller (another thread with its own model) runs inline.
  std::unique_lock<std::mutex> lock(poolMutex, std::try_to_lock);
  if (!lock.owns_lock()) {
    for (int b = 0; b < blocks; ++b)
      body(b, static_cast<int>(static_cast<std::int64_t>(count) * b / blocks),
           static_cast<int>(static_cast<std::int64_t>(count) * (b + 1) / blocks));
    return;
  }
  if (pool == nullptr || poolOwner != getpid()) {
    pool = new Pool(blocks - 1);  // a forked child's stale pool is left alone
    poolOwner = getpid();
  } else if (pool->workers() < blocks - 1) {
    pool->grow(blocks - 1);
  }
  insideParallel = true;
  try {
    pool->dispatch(count, blocks, body);
  } catch (...) {
    insideParallel = false;
    throw;
  }
  insideParallel = false;
}

}  // namespace openmss
