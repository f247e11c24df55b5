// common/parallel_for: the split of [0, count) into blocks depends on count and the thread
// count alone, every index runs exactly once, nested calls run inline, and an exception of a
// block reaches the caller (the lowest block's when several throw).

#include "common/parallel_for.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace openmss {
namespace {

struct ThreadsFor {
  explicit ThreadsFor(int n) { setThreadCountForTesting(n); }
  ~ThreadsFor() { setThreadCountForTesting(0); }
};

TEST(ParallelFor, EveryIndexOnceInContiguousBlocksFixedByCountAndThreads) {
  for (int threads : {1, 2, 3, 5}) {
    ThreadsFor guard(threads);
    for (int count : {0, 1, 2, 7, 1000}) {
      std::vector<int> block(static_cast<size_t>(count), -1), hits(static_cast<size_t>(count), 0);
      parallelFor(count, [&](int b, int begin, int end) {
        for (int i = begin; i < end; ++i) {
          block[static_cast<size_t>(i)] = b;
          ++hits[static_cast<size_t>(i)];
        }
      });
      const int blocks = count < threads ? count : threads;
      for (int i = 0; i < count; ++i) {
        EXPECT_EQ(hits[static_cast<size_t>(i)], 1) << threads << " " << count << " " << i;
        // Block b holds [count b / blocks, count (b + 1) / blocks).
        const int b = block[static_cast<size_t>(i)];
        EXPECT_GE(i, count * b / blocks);
        EXPECT_LT(i, count * (b + 1) / blocks);
      }
    }
  }
}

TEST(ParallelFor, NestedCallsRunInlineAndCoverTheirRange) {
  ThreadsFor guard(2);
  std::vector<int> sums(2, 0);
  parallelFor(2, [&](int b, int, int) {
    int inner = 0;
    parallelFor(10, [&](int, int begin, int end) {
      for (int i = begin; i < end; ++i) inner += i;  // inline: no race on `inner`
    });
    sums[static_cast<size_t>(b)] = inner;
  });
  EXPECT_EQ(sums[0], 45);
  EXPECT_EQ(sums[1], 45);
}

TEST(ParallelFor, TheLowestThrowingBlocksExceptionReachesTheCaller) {
  ThreadsFor guard(3);
  try {
    parallelFor(3, [](int b, int, int) {
      if (b >= 1) throw std::runtime_error("block " + std::to_string(b));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "block 1");
  }
  // The pool is usable afterwards.
  int ran = 0;
  std::vector<int> each(3, 0);
  parallelFor(3, [&](int b, int, int) { each[static_cast<size_t>(b)] = 1; });
  for (int e : each) ran += e;
  EXPECT_EQ(ran, 3);
}

}  // namespace
}  // namespace openmss
