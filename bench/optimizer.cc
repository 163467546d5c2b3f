// Speed of the optimisers on synthetic problems (Google Benchmark): a frame's pose from 500
// observations (a fifth of them gross mismatches, half with depth), and local bundle adjustment of
// 10 keyframes / 2000 points and 20 keyframes / 3000 points (an arc of keyframes, points seen
// from the keyframes around their own), as local mapping meets them.
//
//   segslam_bench_optimizer [--benchmark_format=json ...]

#include <benchmark/benchmark.h>

#include <random>

#include "segslam/optim/optim_test_problems.h"

namespace {

using namespace segslam::optim;

void optimizePoseFrom500Observations(benchmark::State& state) {
  std::mt19937 rng(5);
  const testing::PoseScene scene = testing::makePoseScene(rng, 500, 0.2, testing::DepthMix::kHalf);
  const auto initial = testing::perturbedPose(rng, scene.T_cw, 0.03, 1.0 * M_PI / 180.0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(optimizePose(scene.intrinsics, initial, scene.observations));
  }
}
BENCHMARK(optimizePoseFrom500Observations)->Unit(benchmark::kMillisecond);

void localBundleAdjustment(benchmark::State& state) {
  std::mt19937 rng(28);
  testing::BaSceneOptions options;
  options.num_keyframes = static_cast<int>(state.range(0));
  options.num_points = static_cast<int>(state.range(1));
  options.mismatched_point_share = 0.05;
  testing::BaScene scene = testing::makeBaScene(rng, options);
  testing::perturb(rng, scene.problem, 0.02, 1.0);
  for (auto _ : state) {
    // bundleAdjust moves the problem's poses and points: each run starts from the perturbed copy.
    state.PauseTiming();
    BundleAdjustmentProblem problem = scene.problem;
    state.ResumeTiming();
    benchmark::DoNotOptimize(bundleAdjust(problem));
  }
  state.counters["observations"] = static_cast<double>(scene.problem.observations.size());
}
BENCHMARK(localBundleAdjustment)->Args({10, 2000})->Args({20, 3000})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
