#pragma once
// The one place OpenMSS runs work on several threads (docs/architecture.md, "Threads"): a small
// pool of persistent workers, sized by the environment variable OPENMSS_THREADS (a whole number
// from 1 to kMaxThreads; unset: the hardware's core count), and parallelFor over an index range.
//
// Determinism rule: parallelFor splits [0, count) into contiguous blocks fixed by count and the
// thread count alone; block w always runs the same indices, in increasing order. Callers write
// each index's result into its own preallocated slot and reduce the slots in index order
// afterwards, on one thread, so results are bit-identical for any thread count (never atomics,
// never per-thread partial sums combined in completion order). With one thread, or when called
// from inside a worker (nested), the body runs inline on the calling thread.

#include <functional>
#include <string>

namespace openmss {

// Upper bound accepted from OPENMSS_THREADS.
inline constexpr int kMaxThreads = 256;

// The thread count OPENMSS_THREADS asks for (checked once, on first use): the core count when
// the variable is unset or empty. Throws std::invalid_argument naming the variable and the
// accepted values when it holds anything else than a whole number 1..kMaxThreads.
int threadCount();

// The text of OPENMSS_THREADS's problem, or empty when it is acceptable (for the program's
// start-up check, app/main.cpp, which reports it before any analysis starts).
std::string threadCountProblem();

// Runs body(block, begin, end) over `blocks` = min(threadCount(), count) contiguous blocks of
// [0, count), block 0 on the calling thread and the others on the pool's workers, and returns
// when all are done. An exception thrown by a block is rethrown here after every block has
// finished (the one of the lowest block when several throw).
void parallelFor(int count, const std::function<void(int block, int begin, int end)>& body);

// Test hook: overrides threadCount() for this process (0 restores the environment's value).
void setThreadCountForTesting(int threads);

}  // namespace openmss
