// The whole per-frame pipeline of StereoMapper (grey conversion, stereo, spike removal, column
// projection, grid update) on the sample run's 320x240 L-shaped trinocular frames, 32
// disparities, one thread; frames are decoded from rawlogs/sample_trinocular.rawlog before
// timing starts. Target: >= 200 frames/s for the paper's grid. Side by side in the same run:
//   - Paper:      the paper's settings: whole-pixel disparities (section 3.2), texture and
//                 uniqueness validation only (section 2.2; the Triclops had no left-right check)
//   - WithLeftRightCheck: the same plus the left-right check, which matches every frame twice
//   - Subpixel:   ini/sample_trinocular.ini as shipped (left-right check and sub-pixel)
//   - MrptBayes:  the paper's settings into MRPT's COccupancyGridMap2D through the virtual scan
//   - PaperScaled/k: the paper's settings on the same frames resized k times (640x480 with 64
//                 disparities, 1280x960 with 128; the rig's focal length and principal point, the
//                 disparity range and the spike-removal surface size scale with them)
// Counters: frames_per_s per CPU second (like the reported CPU time, it excludes time the
// benchmark waited for a shared core), and the wall-clock ms per frame of each stage from
// StereoMapper's own stage timers (inflated when other processes compete for the cores).
//   bench_mapping --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include <string>
#include <vector>

#include "mapping/rawlog_mapping.h"
#include "mapping/stereo_mapper.h"
#include "observations/rawlog_reader.h"

namespace stereonav {
namespace {

const std::string kSourceDir = std::string(STEREONAV_TEST_DATA_DIR) + "/../..";

MappingOptions sampleOptions() {
  MappingOptions options = loadMappingOptionsFile(kSourceDir + "/ini/sample_trinocular.ini");
  options.stereo.max_disparity = 31;  // 32 disparities
  options.stereo.threads = 1;
  return options;
}

const std::vector<RigFrame>& sampleFrames() {
  static const std::vector<RigFrame> frames = [] {
    RawlogReader reader(kSourceDir + "/rawlogs/sample_trinocular.rawlog",
                        rawlogReaderOptions(sampleOptions()));
    std::vector<RigFrame> decoded;
    while (auto frame = reader.next()) decoded.push_back(std::move(*frame));
    if (decoded.empty()) throw std::runtime_error("no frames in the sample rawlog");
    return decoded;
  }();
  return frames;
}

// The sample frames with every image resized `scale` times and the rig to match.
std::vector<RigFrame> scaledFrames(int scale) {
  std::vector<RigFrame> frames = sampleFrames();
  for (RigFrame& frame : frames) {
    cv::resize(frame.reference, frame.reference, cv::Size(), scale, scale, cv::INTER_LINEAR);
    for (cv::Mat& image : frame.secondaries) cv::resize(image, image, cv::Size(), scale, scale, cv::INTER_LINEAR);
    PinholeCamera& camera = frame.rig.reference;
    camera.width *= scale;
    camera.height *= scale;
    camera.focal_px *= scale;
    camera.cx = (camera.cx + 0.5) * scale - 0.5;
    camera.cy = (camera.cy + 0.5) * scale - 0.5;
  }
  return frames;
}

void runPipeline(benchmark::State& state, const MappingOptions& options,
                 const std::vector<RigFrame>& frames = sampleFrames()) {
  cv::setNumThreads(1);
  StereoMapper mapper(options, frames.front().rig);
  size_t i = 0;
  for (auto _ : state) {
    const RigFrame& frame = frames[i++ % frames.size()];
    mapper.process(frame, *frame.odometry);
  }
  const StageTimes& times = mapper.times();
  for (size_t stage = 0; stage < kPipelineStageCount; ++stage) {
    const auto which = static_cast<PipelineStage>(stage);
    state.counters[std::string(stageName(which)) + "_ms"] = times.meanMs(which);
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(static_cast<double>(times.frames()), benchmark::Counter::kIsRate);
}

MappingOptions paperOptions() {
  MappingOptions options = sampleOptions();
  options.stereo.subpixel = false;
  options.stereo.left_right_check = false;
  return options;
}

void BM_PipelinePaper(benchmark::State& state) { runPipeline(state, paperOptions()); }

void BM_PipelineWithLeftRightCheck(benchmark::State& state) {
  MappingOptions options = paperOptions();
  options.stereo.left_right_check = true;
  runPipeline(state, options);
}

void BM_PipelineSubpixel(benchmark::State& state) { runPipeline(state, sampleOptions()); }

void BM_PipelineMrptBayes(benchmark::State& state) {
  MappingOptions options = paperOptions();
  options.grid.model = GridModel::kMrptBayes;
  runPipeline(state, options);
}

void BM_PipelinePaperScaled(benchmark::State& state) {
  const int scale = static_cast<int>(state.range(0));
  MappingOptions options = paperOptions();
  options.rig.reset();  // the frames carry the scaled rig
  options.stereo.max_disparity = 32 * scale - 1;
  options.stereo.uniqueness_threshold /= scale;  // best / sum: a flat curve is 1 / candidates
  options.spike_removal.segmentation.min_region_pixels *= scale * scale;
  runPipeline(state, options, scaledFrames(scale));
}

BENCHMARK(BM_PipelinePaper)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PipelinePaperScaled)->Arg(2)->Arg(4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PipelineWithLeftRightCheck)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PipelineSubpixel)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PipelineMrptBayes)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace stereonav

BENCHMARK_MAIN();
