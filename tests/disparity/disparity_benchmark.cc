// Our multi-baseline SAD engine against cv::StereoBM in the same run, on the same 320x240 images,
// 32 disparities, 7x7 window, one thread (paper section 2.2: the Triclops head delivers 320x240).
// Compare medians: bench_disparity --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>

#include <string>

#include "disparity/disparity_engine.h"

namespace stereonav {
namespace {

const cv::Rect kCrop(32, 24, 320, 240);

cv::Mat1b tsukubaView(int column) {
  const std::string path =
      std::string(STEREONAV_TEST_DATA_DIR) + "/tsukuba/scene1.row3.col" + std::to_string(column) + ".ppm";
  const cv::Mat1b image = cv::imread(path, cv::IMREAD_GRAYSCALE);
  if (image.empty()) throw std::runtime_error(path + ": cannot read image");
  return image(kCrop).clone();
}

// Tsukuba has no vertical views; the top camera of the L-shaped rig sees a point at (x, y + d),
// here the reference moved down by 8 rows (the speed does not depend on the content).
cv::Mat1b shiftedDown(const cv::Mat1b& image, int rows) {
  cv::Mat1b shifted;
  cv::copyMakeBorder(image.rowRange(0, image.rows - rows), shifted, rows, 0, 0, 0, cv::BORDER_REPLICATE);
  return shifted;
}

StereoOptions benchmarkOptions() {
  StereoOptions options;  // the shipped defaults: 32 disparities, 7x7, x-Sobel, texture + uniqueness
  options.max_disparity = 31;
  options.window = 7;
  options.threads = 1;
  options.left_right_check = false;  // cv::StereoBM's defaults have no left-right check either
  return options;
}

// Like cv::StereoBM below, one matcher object is reused for every frame.
void runOurs(benchmark::State& state, const StereoFrame& frame, const StereoOptions& options) {
  cv::setNumThreads(1);
  StereoMatcher matcher(options);
  cv::Mat1f disparity;
  for (auto _ : state) {
    matcher.compute(frame, disparity);
    benchmark::DoNotOptimize(disparity.data);
  }
}

void BM_OurSadBinocular(benchmark::State& state) {
  runOurs(state, {tsukubaView(3), {{tsukubaView(4), {1, 0}}}}, benchmarkOptions());
}

void BM_OurSadBinocularWithLeftRightCheck(benchmark::State& state) {
  StereoOptions options = benchmarkOptions();
  options.left_right_check = true;
  runOurs(state, {tsukubaView(3), {{tsukubaView(4), {1, 0}}}}, options);
}

void BM_OurSadTriclopsL(benchmark::State& state) {
  const cv::Mat1b reference = tsukubaView(3);
  runOurs(state, {reference, {{tsukubaView(2), {-1, 0}}, {shiftedDown(reference, 8), {0, -1}}}}, benchmarkOptions());
}

void BM_OpenCvStereoBm(benchmark::State& state) {
  cv::setNumThreads(1);
  const cv::Mat1b left = tsukubaView(3), right = tsukubaView(4);
  // Its defaults: x-Sobel prefilter (cap 31), texture threshold 10, uniqueness ratio 15.
  const cv::Ptr<cv::StereoBM> matcher = cv::StereoBM::create(32, 7);
  cv::Mat disparity;
  for (auto _ : state) {
    matcher->compute(left, right, disparity);
    benchmark::DoNotOptimize(disparity.data);
  }
}

BENCHMARK(BM_OpenCvStereoBm)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OurSadBinocular)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OurSadTriclopsL)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OurSadBinocularWithLeftRightCheck)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace stereonav

BENCHMARK_MAIN();
