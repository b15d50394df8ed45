#pragma once

#include <string>

#include "common/ini_section.h"

namespace stereonav {

// Which matcher computes the disparity image. kSad is this library's multi-baseline SAD engine
// (paper section 2.2); the OpenCV backends are binocular-only references for comparison.
enum class StereoBackend { kSad, kOpenCvBm, kOpenCvSgbm };

// Image transform applied to every view before matching. kXSobel is the horizontal Sobel
// derivative clipped to +-prefilter_cap, as cv::StereoBM's PREFILTER_XSOBEL; kLog is the
// Laplacian of Gaussian clipped the same way. Both remove the brightness offsets between cameras
// that raw SAD is sensitive to.
enum class Prefilter { kNone, kXSobel, kLog };

// How one reference pixel and one candidate pixel are compared before the window adds them up.
// kAbsoluteDifference is the paper's SAD term. kBirchfieldTomasi (Birchfield and Tomasi 1998, as
// cv::StereoSGBM's cost) compares each pixel with the range of values the other image takes within
// half a pixel of the candidate along the baseline, and keeps the smaller of the two: a surface
// sampled at a fractional offset, or an edge that falls between pixels, no longer looks like a
// mismatch, which is where SAD errs at depth edges and on slanted textured surfaces.
// kBirchfieldTomasiOneSided keeps only the first of the two: the reference pixel's distance to the
// candidate's range (their d-bar). It forgives the secondary image's sampling, not the
// reference's, and needs neither the reference's ranges nor the candidates' own values, so it
// reads two bytes per candidate where the symmetric cost reads three and SAD one.
enum class PixelCost { kAbsoluteDifference, kBirchfieldTomasi, kBirchfieldTomasiOneSided };

// How the window scores of several secondary cameras make one score per candidate disparity.
// kSum is the paper's (section 2.2, after Okutomi and Kanade). kBestHalf keeps only the
// ceil(N/2) lowest camera scores, so a point hidden from some cameras by an occluding edge is
// still matched by the cameras that see it.
enum class CameraCombination { kSum, kBestHalf };

// How the scores of a candidate disparity are gathered before the winner is taken. kWindow is the
// paper's: the SAD over the square window alone. kScanline adds, along each image row, the cost of
// changing disparity from pixel to pixel (scanline optimisation: the two horizontal paths of
// Hirschmuller's semi-global matching, from the left and from the right): a jump of one disparity
// costs scanline_p1, a larger jump scanline_p2. A surface then keeps its disparity across pixels
// whose own windows are ambiguous, and a window straddling a depth edge no longer drags the
// background to the foreground's disparity. kSemiGlobal adds the three paths that come down from
// the row above (from the upper left, above and the upper right): five of Hirschmuller's paths,
// as OpenCV's StereoSGBM in its default mode, so a surface also keeps its disparity from row to
// row. Its paths run down the whole image, so the rows are matched on one thread.
enum class CostAggregation { kWindow, kScanline, kSemiGlobal };

// The instruction set of the SAD engine's vector loop. kAuto takes the widest this CPU runs
// (AVX2's 256-bit vectors compare twice the candidates per instruction of SSE2's 128-bit ones);
// the others force one, for comparison. Every level gives the same disparities and scores.
enum class SimdLevel { kAuto, kSse2, kAvx2 };

// Whether this CPU (and OpenCV's view of it, which OPENCV_CPU_DISABLE can restrict) runs `level`.
bool simdSupported(SimdLevel level);

// Everything that controls the stereo engine; loaded from the [stereo] ini section.
struct StereoOptions {
  StereoBackend backend = StereoBackend::kSad;
  int min_disparity = 0;   // smallest candidate disparity, pixels for the unit baseline
  int max_disparity = 31;  // largest candidate disparity (inclusive)
  int window = 7;          // side of the square SAD window, odd >= 3

  Prefilter prefilter = Prefilter::kXSobel;
  int prefilter_cap = 31;  // clip of the prefiltered image, 1..127

  PixelCost pixel_cost = PixelCost::kAbsoluteDifference;
  // Adds the cost of the grey levels at a quarter scale to the prefiltered images' cost, as
  // cv::StereoSGBM does: the prefilter keeps only edges, and the grey levels tell apart the
  // candidates that a flat or repeated gradient leaves alike. Needs a prefilter (xsobel or log)
  // with prefilter_cap <= 63, so that both costs of a pixel fit a byte.
  bool intensity_term = false;

  CameraCombination combination = CameraCombination::kSum;

  CostAggregation aggregation = CostAggregation::kWindow;
  // Jump costs of kScanline and kSemiGlobal per pixel of the window and per camera, in prefiltered grey levels
  // (a score is a sum over window pixels and cameras, so the costs scale with both and one value
  // suits any window, rig and number of disparities). scanline_p2 >= scanline_p1.
  double scanline_p1 = 4;
  double scanline_p2 = 32;

  // Validation (paper section 2.2). Texture: the mean of |LoG| of the reference image over the
  // window (grey levels per pixel) must exceed texture_threshold; 0 keeps every pixel.
  double texture_threshold = 0.25;
  double texture_sigma = 1.0;  // Gaussian sigma of the LoG, pixels
  // Uniqueness: best window score / sum of the scores of all candidates must be below this. A
  // flat score curve has ratio 1/(number of candidates), so the useful range scales with the
  // disparity range: 0.02 suits the default 32 candidates, 0.04 suits 16; 1 = off.
  double uniqueness_threshold = 0.02;
  // Distinctiveness, a uniqueness test whose meaning does not depend on the number of candidates
  // (as cv::StereoBM's uniquenessRatio): best score / lowest score of the candidates more than one
  // disparity away from the best must be below this. 0.9 = the runner-up scores 11% worse; 1 = off.
  double second_best_ratio = 1.0;
  // Left-right consistency: match again with the first secondary camera as reference and keep a
  // pixel only if the disparity found there differs by at most left_right_max_diff.
  bool left_right_check = true;
  double left_right_max_diff = 1.0;
  // Depth-edge test (rejectFattenedEdges): near-surface pixels beyond the strongest brightness step
  // at a disparity fall of at least fattening_min_jump pixels are rejected, where that step is at
  // least fattening_min_step grey levels; 0 = off.
  double fattening_min_step = 0;
  double fattening_min_jump = 2;
  // Pixels within max_disparity of the image edge a baseline points away from (the left band of a
  // binocular rig) have some candidates off the secondary image. false: those that no camera sees
  // at every candidate stay invalid, as cv::StereoBM leaves them. true: they are matched against
  // the replicated border at every candidate, as cv::StereoSGBM matches the whole width, and a
  // match is kept only where its candidate is inside the image.
  bool partial_candidates = false;
  bool subpixel = false;  // parabola through the best score and its neighbours (section 3.2: off)

  int threads = 1;  // horizontal stripes matched in parallel (cv::parallel_for_)
  SimdLevel simd = SimdLevel::kAuto;

  // Only for the OpenCV backends (their own validation, in their own units).
  int opencv_texture_threshold = 10;  // cv::StereoBM::setTextureThreshold
  int opencv_uniqueness_ratio = 15;   // percent, cv::StereoMatcher uniqueness
  int opencv_speckle_window = 0;      // cv::StereoMatcher::setSpeckleWindowSize (0 = off)
  int opencv_speckle_range = 0;       // cv::StereoMatcher::setSpeckleRange

  int disparityCount() const { return max_disparity - min_disparity + 1; }
};

// Loads and validates the [stereo] section; throws ConfigError "[stereo] key: why". Keys are the
// member names above; enums as text: backend = sad | bm | sgbm, prefilter = none | xsobel | log,
// pixel_cost = absolute_difference | birchfield_tomasi | birchfield_tomasi_one_sided, combination = sum | best_half, aggregation = window | scanline | semiglobal, simd = auto | sse2 | avx2.
StereoOptions loadStereoOptions(IniSection& section);

// Bounds on the disparity range and the SAD window, pixels.
constexpr int kMaxDisparity = 4096;
constexpr int kMaxWindow = 255;

// Checks the values (also after command-line overrides); throws ConfigError naming the key.
void validateStereoOptions(const StereoOptions& options, const std::string& section = "stereo");

// The text form of the enums, as written in ini files.
StereoBackend parseStereoBackend(const std::string& text, const std::string& what);
const char* toString(StereoBackend backend);
const char* toString(SimdLevel level);

}  // namespace stereonav
