// The CPU filters at 1920x1080 (Google Benchmark). Run with the threads the measurement is for, e.g.
//   taskset -c 0,1 build/bench/denoise_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// TBB uses the processors the process may run on.
#include <benchmark/benchmark.h>

#include "filter_inputs.h"
#include "image/filters/atrous.h"
#include "image/filters/bilateral.h"
#include "image/filters/temporal.h"

namespace candela {
namespace {

void atrousFivePasses(benchmark::State& state) {
  const bench::FilterInput in = bench::noisyFrame();
  AtrousParams params;
  params.passes = 5;
  for (auto _ : state) benchmark::DoNotOptimize(atrousDenoise(in.color, in.aovs, params));
}
BENCHMARK(atrousFivePasses)->Unit(benchmark::kMillisecond)->UseRealTime();

// Reprojection, accumulation and the a-trous passes (reflected light and emission) of a frame whose camera moved
// a little since the last, with emitters seen in the given percentage of rows: the emission's passes skip the rows
// and columns far from any, so 100 is the worst case. (The random frame's depths do not match a camera, so much of
// the history is rejected: the same taps are read and weighed either way.)
void temporalAndAtrous(benchmark::State& state) {
  const bench::FilterInput in = bench::withEmission(bench::noisyFrame(), int(state.range(0)));
  TemporalFilter filter;
  Camera camera = Camera::lookAt({0, 5, 0}, {0, 0, 0}, {0, 0, 1}, 40.0f, 1920.0f / 1080.0f);
  filter.filter({in.color, in.aovs, camera, 1, false});
  for (auto _ : state) {
    camera.position.x += 1e-4f;
    benchmark::DoNotOptimize(filter.filter({in.color, in.aovs, camera, 1, false}));
  }
}
BENCHMARK(temporalAndAtrous)->Arg(0)->Arg(25)->Arg(100)->Unit(benchmark::kMillisecond)->UseRealTime();

void bilateralRadius3(benchmark::State& state) {
  const bench::FilterInput in = bench::noisyFrame();
  for (auto _ : state) benchmark::DoNotOptimize(bilateralFilter(in.color, BilateralParams{}));
}
BENCHMARK(bilateralRadius3)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace candela

BENCHMARK_MAIN();
