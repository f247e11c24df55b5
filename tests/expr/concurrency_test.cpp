// One Expression evaluated from several threads at once gives the same results as alone, both
// for ordinary programs (stack work arrays) and for very long ones (shared owned scratch, with
// a private fallback when it is busy).

#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "expr_test_support.hpp"

namespace openmss::expr {
namespace {

void evaluateConcurrently(const Expression& e) {
  const double host = 0.7;
  std::vector<double> expected;
  std::vector<double> expectedRate;
  for (int k = 0; k < 50; ++k) {
    double rate = 0.0;
    expected.push_back(e.evaluate(&host, 0.01 * k, nullptr, &rate));
    expectedRate.push_back(rate);
  }
  std::atomic<int> mismatches{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&] {
      for (int round = 0; round < 50; ++round) {
        for (int k = 0; k < 50; ++k) {
          double rate = 0.0;
          const double value = e.evaluate(&host, 0.01 * k, nullptr, &rate);
          if (value != expected[k] || rate != expectedRate[k]) ++mismatches;
        }
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(mismatches.load(), 0);
}

TEST(Concurrency, ShortExpression) {
  evaluateConcurrently(testing::parseOk("STEP(TIME, 0, 0, 0.5, 1) * DM(1,2) + SIN(TIME)"));
}

TEST(Concurrency, ExpressionLongerThanTheStackArrays) {
  std::string text = "DM(1,2)";
  for (int k = 1; k <= 150; ++k) text += " + SIN(" + std::to_string(k) + "*TIME)*DM(1,2)";
  evaluateConcurrently(testing::parseOk(text));
}

}  // namespace
}  // namespace openmss::expr
