// Our stereo engine beside cv::StereoBM and cv::StereoSGBM in the same run, on the same images,
// at three sizes: 320x240 with 32 disparities (the paper's Triclops, section 2.2), 640x480 with 64
// and 1280x720 with 128 (today's stereo cameras). The images are the tsukuba views resized (the
// time does not depend on the content); one thread unless the name says Threads (all cores).
//   - OurPaper:     binocular SAD, 7x7, texture + quality-of-match tests (the paper's path)
//   - OurImproved:  ini/stereo_real_images.ini as shipped (the accuracy configuration of
//                   docs/stereo.md: 5x5 one-sided Birchfield-Tomasi, scanline aggregation,
//                   distinctiveness test, left-right check from the same scores), with the range
//                   set per size
//   - OurBirchfieldTomasi: the same with its most accurate pixel cost (pixel_cost =
//                   birchfield_tomasi, intensity_term = true)
//   - OurAbsoluteDifference: the same with the paper's pixel cost (pixel_cost =
//                   absolute_difference, second_best_ratio = 0.7)
//   - OurSemiGlobal: the same with aggregation = semiglobal (five paths, as SGBM's default mode)
//   - OurTrinocular: the paper's path with the L-shaped Triclops head (left and top cameras)
//   - ...Sse2:      the same with the 128-bit loop forced (the others take AVX2 where the CPU has it)
//   - OpenCvStereoBm: its defaults at 9x9 (x-Sobel, texture 10, uniqueness 15), no speckle filter
//   - OpenCvStereoSgbm: 3x3 blocks, MODE_SGBM
// Compare medians; the argument is the width (320, 640 or 1280):
//   bench_disparity --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>
#include <string>

#include "disparity/disparity_engine.h"
#include "shipped_config.h"

namespace stereonav {
namespace {

cv::Size imageSize(int width) { return width == 1280 ? cv::Size(1280, 720) : cv::Size(width, width * 3 / 4); }
int disparities(int width) { return width / 10; }  // 32, 64, 128

cv::Mat1b tsukubaView(int column, int width) {
  const std::string path =
      std::string(STEREONAV_TEST_DATA_DIR) + "/tsukuba/scene1.row3.col" + std::to_string(column) + ".ppm";
  const cv::Mat1b image = cv::imread(path, cv::IMREAD_GRAYSCALE);
  if (image.empty()) throw std::runtime_error(path + ": cannot read image");
  cv::Mat1b resized;
  cv::resize(image, resized, imageSize(width), 0, 0, cv::INTER_LINEAR);
  return resized;
}

// Tsukuba has no vertical views; the top camera of the L-shaped rig sees a point at (x, y + d),
// here the reference moved down by 8 rows.
cv::Mat1b shiftedDown(const cv::Mat1b& image, int rows) {
  cv::Mat1b shifted;
  cv::copyMakeBorder(image.rowRange(0, image.rows - rows), shifted, rows, 0, 0, 0, cv::BORDER_REPLICATE);
  return shifted;
}

StereoOptions paperOptions(int width) {
  StereoOptions options;  // 7x7, x-Sobel, texture + quality of match
  options.max_disparity = disparities(width) - 1;
  options.uniqueness_threshold = 0.64 / disparities(width);
  options.left_right_check = false;  // the Triclops had none, nor has cv::StereoBM's default
  return options;
}

StereoOptions improvedOptions(int width) {
  StereoOptions options = testing::shippedStereoOptions("stereo_real_images.ini");
  options.min_disparity = 0;
  options.max_disparity = disparities(width) - 1;
  return options;
}

// Like cv::StereoBM below, one matcher object is reused for every frame.
void runOurs(benchmark::State& state, const StereoFrame& frame, StereoOptions options, int threads) {
  cv::setNumThreads(threads);
  options.threads = threads;
  StereoMatcher matcher(options);
  cv::Mat1f disparity;
  for (auto _ : state) {
    matcher.compute(frame, disparity);
    benchmark::DoNotOptimize(disparity.data);
  }
}

StereoFrame binocular(int width) { return {tsukubaView(3, width), {{tsukubaView(4, width), {1, 0}}}}; }

void BM_OurPaper(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  runOurs(state, binocular(width), paperOptions(width), 1);
}

void BM_OurImproved(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  runOurs(state, binocular(width), improvedOptions(width), 1);
}

void BM_OurBirchfieldTomasi(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  StereoOptions options = improvedOptions(width);
  options.pixel_cost = PixelCost::kBirchfieldTomasi;
  options.intensity_term = true;
  runOurs(state, binocular(width), options, 1);
}

void BM_OurAbsoluteDifference(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  StereoOptions options = improvedOptions(width);
  options.pixel_cost = PixelCost::kAbsoluteDifference;
  options.second_best_ratio = 0.7;
  runOurs(state, binocular(width), options, 1);
}

void BM_OurSemiGlobal(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  StereoOptions options = improvedOptions(width);
  options.aggregation = CostAggregation::kSemiGlobal;
  runOurs(state, binocular(width), options, 1);
}

void BM_OurPaperSse2(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  StereoOptions options = paperOptions(width);
  options.simd = SimdLevel::kSse2;
  runOurs(state, binocular(width), options, 1);
}

void BM_OurImprovedSse2(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  StereoOptions options = improvedOptions(width);
  options.simd = SimdLevel::kSse2;
  runOurs(state, binocular(width), options, 1);
}

void BM_OurImprovedThreads(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  runOurs(state, binocular(width), improvedOptions(width), cv::getNumberOfCPUs());
}

void BM_OurTrinocular(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  const cv::Mat1b reference = tsukubaView(3, width);
  runOurs(state, {reference, {{tsukubaView(2, width), {-1, 0}}, {shiftedDown(reference, 8), {0, -1}}}},
          paperOptions(width), 1);
}

void runOpenCv(benchmark::State& state, const cv::Ptr<cv::StereoMatcher>& matcher, int threads) {
  cv::setNumThreads(threads);
  const int width = static_cast<int>(state.range(0));
  const cv::Mat1b left = tsukubaView(3, width), right = tsukubaView(4, width);
  cv::Mat disparity;
  for (auto _ : state) {
    matcher->compute(left, right, disparity);
    benchmark::DoNotOptimize(disparity.data);
  }
}

void BM_OpenCvStereoBm(benchmark::State& state) {
  runOpenCv(state, cv::StereoBM::create(disparities(static_cast<int>(state.range(0))), 9), 1);
}

void BM_OpenCvStereoBmThreads(benchmark::State& state) {
  runOpenCv(state, cv::StereoBM::create(disparities(static_cast<int>(state.range(0))), 9), cv::getNumberOfCPUs());
}

void BM_OpenCvStereoSgbm(benchmark::State& state) {
  runOpenCv(state, cv::StereoSGBM::create(0, disparities(static_cast<int>(state.range(0))), 3, 72, 288), 1);
}

#define STEREO_SIZES ->Arg(320)->Arg(640)->Arg(1280)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_OpenCvStereoBm) STEREO_SIZES;
BENCHMARK(BM_OurPaper) STEREO_SIZES;
BENCHMARK(BM_OurImproved) STEREO_SIZES;
BENCHMARK(BM_OurPaperSse2) STEREO_SIZES;
BENCHMARK(BM_OurImprovedSse2) STEREO_SIZES;
BENCHMARK(BM_OurTrinocular) STEREO_SIZES;
BENCHMARK(BM_OpenCvStereoSgbm) STEREO_SIZES;
BENCHMARK(BM_OurBirchfieldTomasi) STEREO_SIZES;
BENCHMARK(BM_OurAbsoluteDifference) STEREO_SIZES;
BENCHMARK(BM_OurSemiGlobal) STEREO_SIZES;
BENCHMARK(BM_OpenCvStereoBmThreads) STEREO_SIZES->UseRealTime();
BENCHMARK(BM_OurImprovedThreads) STEREO_SIZES->UseRealTime();

}  // namespace
}  // namespace stereonav

BENCHMARK_MAIN();
