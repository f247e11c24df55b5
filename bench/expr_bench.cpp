// Cost of one evaluation of a typical force expression (the SFORCE contact of a real data set),
// with and without exact derivatives, and of a MOTION time jet. Google Benchmark reports the
// time per iteration, i.e. nanoseconds per evaluation.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <iostream>

#include "common/diagnostics.hpp"
#include "expr/expression.hpp"

namespace {

using openmss::Diagnostics;
using openmss::expr::Expression;

Expression compileOrExit(const char* text) {
  Diagnostics diags;
  Expression e;
  if (!Expression::parse(text, {"bench", 1, 1}, "BENCH", diags, e)) {
    for (const auto& d : diags.all()) std::cerr << openmss::format(d) << "\n";
    std::exit(1);
  }
  return e;
}

constexpr const char* kContactForce =
    "-IMPACT(0.1+0.5066-DM(68,64), -VR(78,81), 0.10085, 1.0E+007, 1.0, 1.0E+006, 1.0E-006)";

void contactForceValue(benchmark::State& state) {
  const Expression e = compileOrExit(kContactForce);
  double host[2] = {0.5061, 0.02};  // in contact, approaching
  for (auto _ : state) {
    benchmark::DoNotOptimize(host);
    benchmark::DoNotOptimize(e.evaluate(host, 0.0));
  }
}
BENCHMARK(contactForceValue);

void contactForceWithDerivatives(benchmark::State& state) {
  const Expression e = compileOrExit(kContactForce);
  double host[2] = {0.5061, 0.02};
  double dHost[2];
  double dTime = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(host);
    benchmark::DoNotOptimize(e.evaluate(host, 0.0, dHost, &dTime));
    benchmark::DoNotOptimize(dHost);
  }
}
BENCHMARK(contactForceWithDerivatives);

void gasSpringWithDerivatives(benchmark::State& state) {
  const Expression e = compileOrExit("1422.0 * DM(0409, 0109) ** (-1.4) - 185.4");
  double host[1] = {0.8};
  double dHost[1];
  double dTime = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(host);
    benchmark::DoNotOptimize(e.evaluate(host, 0.0, dHost, &dTime));
  }
}
BENCHMARK(gasSpringWithDerivatives);

void motionTimeJet(benchmark::State& state) {
  const Expression e = compileOrExit("STEP(TIME,0,0,1,1) * POLY(TIME, 0, 0, 360D)");
  double time = 0.3;
  for (auto _ : state) {
    benchmark::DoNotOptimize(time);
    benchmark::DoNotOptimize(e.evaluateTimeJet(time));
  }
}
BENCHMARK(motionTimeJet);

}  // namespace
