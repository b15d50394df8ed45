#include "disparity/stereo_options.h"

#include <opencv2/core/utility.hpp>

#include <map>

namespace stereonav {
namespace {

template <typename Enum>
Enum parseEnum(const std::string& text, const std::map<std::string, Enum>& names,
               const std::string& what) {
  const auto found = names.find(text);
  if (found != names.end()) return found->second;
  std::string expected;
  for (const auto& [name, value] : names) expected += (expected.empty() ? "" : " | ") + name;
  throw ConfigError(what + ": expected " + expected + ", got '" + text + "'");
}

const std::map<std::string, StereoBackend> kBackendNames{
    {"sad", StereoBackend::kSad}, {"bm", StereoBackend::kOpenCvBm}, {"sgbm", StereoBackend::kOpenCvSgbm}};
const std::map<std::string, Prefilter> kPrefilterNames{
    {"none", Prefilter::kNone}, {"xsobel", Prefilter::kXSobel}, {"log", Prefilter::kLog}};
const std::map<std::string, PixelCost> kPixelCostNames{
    {"absolute_difference", PixelCost::kAbsoluteDifference},
    {"birchfield_tomasi", PixelCost::kBirchfieldTomasi},
    {"birchfield_tomasi_one_sided", PixelCost::kBirchfieldTomasiOneSided}};
const std::map<std::string, CameraCombination> kCombinationNames{
    {"sum", CameraCombination::kSum}, {"best_half", CameraCombination::kBestHalf}};
const std::map<std::string, CostAggregation> kAggregationNames{
    {"window", CostAggregation::kWindow}, {"scanline", CostAggregation::kScanline},
    {"semiglobal", CostAggregation::kSemiGlobal}};
const std::map<std::string, SimdLevel> kSimdNames{
    {"auto", SimdLevel::kAuto}, {"sse2", SimdLevel::kSse2}, {"avx2", SimdLevel::kAvx2}};

template <typename Enum>
std::string nameOf(Enum value, const std::map<std::string, Enum>& names) {
  for (const auto& [name, candidate] : names) {
    if (candidate == value) return name;
  }
  return "";
}

}  // namespace

StereoBackend parseStereoBackend(const std::string& text, const std::string& what) {
  return parseEnum(text, kBackendNames, what);
}

const char* toString(StereoBackend backend) {
  switch (backend) {
    case StereoBackend::kSad: return "sad";
    case StereoBackend::kOpenCvBm: return "bm";
    case StereoBackend::kOpenCvSgbm: return "sgbm";
  }
  return "";
}

const char* toString(SimdLevel level) {
  switch (level) {
    case SimdLevel::kAuto: return "auto";
    case SimdLevel::kSse2: return "sse2";
    case SimdLevel::kAvx2: return "avx2";
  }
  return "";
}

bool simdSupported(SimdLevel level) {
  // SSE2 is part of x86-64, which is all the engine is built for.
  return level != SimdLevel::kAvx2 || cv::checkHardwareSupport(CV_CPU_AVX2);
}

StereoOptions loadStereoOptions(IniSection& section) {
  StereoOptions options;
  const std::string prefix = "[" + section.name() + "] ";
  options.backend = parseStereoBackend(section.getString("backend", toString(options.backend)),
                                       prefix + "backend");
  options.min_disparity = section.getInt("min_disparity", options.min_disparity);
  options.max_disparity = section.getInt("max_disparity", options.max_disparity);
  options.window = section.getInt("window", options.window);
  options.prefilter = parseEnum(section.getString("prefilter", nameOf(options.prefilter, kPrefilterNames)),
                                kPrefilterNames, prefix + "prefilter");
  options.prefilter_cap = section.getInt("prefilter_cap", options.prefilter_cap);
  options.pixel_cost = parseEnum(section.getString("pixel_cost", nameOf(options.pixel_cost, kPixelCostNames)),
                                 kPixelCostNames, prefix + "pixel_cost");
  options.intensity_term = section.getBool("intensity_term", options.intensity_term);
  options.combination =
      parseEnum(section.getString("combination", nameOf(options.combination, kCombinationNames)),
                kCombinationNames, prefix + "combination");
  options.aggregation =
      parseEnum(section.getString("aggregation", nameOf(options.aggregation, kAggregationNames)),
                kAggregationNames, prefix + "aggregation");
  options.scanline_p1 = section.getDouble("scanline_p1", options.scanline_p1);
  options.scanline_p2 = section.getDouble("scanline_p2", options.scanline_p2);
  options.texture_threshold = section.getDouble("texture_threshold", options.texture_threshold);
  options.texture_sigma = section.getDouble("texture_sigma", options.texture_sigma);
  options.uniqueness_threshold = section.getDouble("uniqueness_threshold", options.uniqueness_threshold);
  options.second_best_ratio = section.getDouble("second_best_ratio", options.second_best_ratio);
  options.left_right_check = section.getBool("left_right_check", options.left_right_check);
  options.left_right_max_diff = section.getDouble("left_right_max_diff", options.left_right_max_diff);
  options.fattening_min_step = section.getDouble("fattening_min_step", options.fattening_min_step);
  options.fattening_min_jump = section.getDouble("fattening_min_jump", options.fattening_min_jump);
  options.partial_candidates = section.getBool("partial_candidates", options.partial_candidates);
  options.subpixel = section.getBool("subpixel", options.subpixel);
  options.threads = section.getInt("threads", options.threads);
  options.simd = parseEnum(section.getString("simd", toString(options.simd)), kSimdNames, prefix + "simd");
  options.opencv_texture_threshold =
      section.getInt("opencv_texture_threshold", options.opencv_texture_threshold);
  options.opencv_uniqueness_ratio = section.getInt("opencv_uniqueness_ratio", options.opencv_uniqueness_ratio);
  options.opencv_speckle_window = section.getInt("opencv_speckle_window", options.opencv_speckle_window);
  options.opencv_speckle_range = section.getInt("opencv_speckle_range", options.opencv_speckle_range);
  validateStereoOptions(options, section.name());
  return options;
}

void validateStereoOptions(const StereoOptions& options, const std::string& section) {
  const auto fail = [&](const std::string& key, const std::string& why) {
    throw ConfigError("[" + section + "] " + key + ": " + why);
  };
  // Upper bounds keep the work and the buffers a matcher allocates proportional to the image
  // (a 999999-pixel window or a 1e6-disparity range would ask OpenCV for gigabytes).
  if (options.min_disparity < 0 || options.min_disparity > kMaxDisparity) {
    fail("min_disparity", "must be in 0.." + std::to_string(kMaxDisparity));
  }
  if (options.max_disparity <= options.min_disparity || options.max_disparity > kMaxDisparity) {
    fail("max_disparity", "must exceed min_disparity and be at most " + std::to_string(kMaxDisparity));
  }
  if (options.window < 3 || options.window % 2 == 0 || options.window > kMaxWindow) {
    fail("window", "must be odd and in 3.." + std::to_string(kMaxWindow));
  }
  if (options.prefilter_cap < 1 || options.prefilter_cap > 127) fail("prefilter_cap", "must be in 1..127");
  if (options.intensity_term && (options.prefilter == Prefilter::kNone || options.prefilter_cap > 63)) {
    fail("intensity_term", "needs prefilter = xsobel or log with prefilter_cap <= 63");
  }
  // A jump costs at most the largest difference of one pixel: that bound keeps the aggregated
  // scores (two paths, each at most the largest window score plus the large-jump cost) inside 32
  // bits for any window and rig.
  if (!(options.scanline_p1 >= 0 && options.scanline_p1 <= 255)) fail("scanline_p1", "must be in 0..255");
  if (!(options.scanline_p2 >= options.scanline_p1 && options.scanline_p2 <= 255)) {
    fail("scanline_p2", "must be in scanline_p1..255");
  }
  // Five paths of at most 2 * 255 per window pixel and camera, for 16 cameras, fit 32 bits up to
  // this window.
  constexpr int kMaxSemiGlobalWindow = 229;
  if (options.aggregation == CostAggregation::kSemiGlobal && options.window > kMaxSemiGlobalWindow) {
    fail("window", "must be at most " + std::to_string(kMaxSemiGlobalWindow) + " with aggregation = semiglobal");
  }
  if (!(options.texture_threshold >= 0)) fail("texture_threshold", "must be >= 0");
  if (!(options.texture_sigma > 0 && options.texture_sigma <= 100)) fail("texture_sigma", "must be in (0, 100]");
  if (!(options.uniqueness_threshold > 0)) fail("uniqueness_threshold", "must be positive");
  if (!(options.second_best_ratio > 0 && options.second_best_ratio <= 1)) {
    fail("second_best_ratio", "must be in (0, 1]");
  }
  if (!(options.left_right_max_diff >= 0)) fail("left_right_max_diff", "must be >= 0");
  if (!(options.fattening_min_step >= 0 && options.fattening_min_step <= 255)) {
    fail("fattening_min_step", "must be in 0..255");
  }
  if (!(options.fattening_min_jump > 0)) fail("fattening_min_jump", "must be positive");
  if (options.threads < 1 || options.threads > 256) fail("threads", "must be in 1..256");
  if (!simdSupported(options.simd)) fail("simd", std::string(toString(options.simd)) + " is not supported by this CPU");
  if (options.opencv_texture_threshold < 0) fail("opencv_texture_threshold", "must be >= 0");
  if (options.opencv_uniqueness_ratio < 0) fail("opencv_uniqueness_ratio", "must be >= 0");
  if (options.opencv_speckle_window < 0) fail("opencv_speckle_window", "must be >= 0");
  if (options.opencv_speckle_range < 0) fail("opencv_speckle_range", "must be >= 0");
}

}  // namespace stereonav
