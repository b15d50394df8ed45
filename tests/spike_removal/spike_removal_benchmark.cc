// Surface segmentation (paper section 4.2) against OpenCV's cv::filterSpeckles, which does the same
// job (invalidate small regions of similar disparity, 4-connected) by flood fill, on the same
// 320x240 image in the same run. Both time the copy of the input that each iteration filters
// (ours copies float pixels, twice the bytes of filterSpeckles' CV_16S).
//   bench_spike_removal --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <opencv2/calib3d.hpp>

#include "noisy_tsukuba.h"
#include "spike_removal/surface_segmentation.h"

namespace stereonav {
namespace {

constexpr int kMinRegionPixels = 100;
constexpr int16_t kInvalidFixedPoint = -16;

void BM_SurfaceSegmentation(benchmark::State& state) {
  const cv::Mat1f input = noisyTsukubaDisparity(1);
  SurfaceSegmentationOptions options;
  options.min_region_pixels = kMinRegionPixels;
  options.max_difference = 1.0f;
  options.connectivity = static_cast<int>(state.range(0));
  SurfaceSegmentation segmentation(options);
  cv::Mat1f disparity(input.size());
  cv::Mat1b rejected;
  for (auto _ : state) {
    input.copyTo(disparity);
    segmentation.apply(disparity, rejected);
    benchmark::DoNotOptimize(disparity.data);
  }
}
BENCHMARK(BM_SurfaceSegmentation)->ArgName("connectivity")->Arg(4)->Arg(8)->Unit(benchmark::kMicrosecond);

void BM_OpenCvFilterSpeckles(benchmark::State& state) {
  const cv::Mat1s input = toFixedPointDisparity(noisyTsukubaDisparity(1), kInvalidFixedPoint);
  cv::Mat1s disparity(input.size());
  cv::Mat buffer;  // kept between calls, as our buffers are
  for (auto _ : state) {
    input.copyTo(disparity);
    // Same regions as ours: removes blobs of <= maxSpeckleSize pixels, disparities x16.
    cv::filterSpeckles(disparity, kInvalidFixedPoint, kMinRegionPixels - 1, 16.0, buffer);
    benchmark::DoNotOptimize(disparity.data);
  }
}
BENCHMARK(BM_OpenCvFilterSpeckles)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace stereonav

BENCHMARK_MAIN();
