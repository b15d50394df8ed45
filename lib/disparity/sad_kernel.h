#pragma once

// The matching loop of SadMatcher, built once per instruction set (sad_kernel_sse2.cc,
// sad_kernel_avx2.cc from sad_kernel_loop.h), and the frame data it reads. Internal to the
// disparity stage.

#include <opencv2/core.hpp>

#include <cstddef>
#include <vector>

#include "disparity/sad_matcher.h"
#include "disparity/stereo_options.h"

namespace stereonav {

constexpr size_t kMaxCameras = 16;

// Weights of one bilinear sample of a tabulated camera; they add up to 1 << 16.
struct BilinearTap {
  int dx = 0, dy = 0;  // integer part of the sample's offset from the reference pixel
  int w00 = 0, w01 = 0, w10 = 0, w11 = 0;
};

// Where the candidates of a reference pixel are. Candidate j (disparity min + j) of pixel (x, y)
// is the byte buffer.data + origin + x*x_step + y*y_step + j for cameras that move one whole pixel
// per disparity along an image axis or a diagonal: their image is flipped, transposed or sheared
// once per frame so that increasing disparity runs forward in memory. Other cameras (fractional
// or longer baselines) are interpolated into a per-row table; for them origin/x_step/y_step
// address pixel (x, y) itself.
//
// With the Birchfield-Tomasi costs the lowest and highest values within half a pixel of each
// pixel along the baseline are arranged the same way, so the same address reads all three.
struct ArrangedImage {
  cv::Mat1b padded;  // the image flipped, then padded by the margin
  cv::Mat1b buffer;           // `padded`, or its transpose or shear for vertical and diagonal cameras
};

// The images a pixel is compared on, whose costs add up to the pixel's cost: channel 0 is the
// prefiltered image; with StereoOptions::intensity_term, channel 1 is the grey levels at a quarter
// scale (as cv::StereoSGBM adds them to its x-Sobel cost).
constexpr int kMaxChannels = 2;

// One channel of a secondary camera: its image and sampling interval, and the arrangements of
// those the pixel cost reads (PreparedFrame::candidateValues, candidateIntervals; the values
// only where CandidateSource::row_intervals).
struct CandidateChannel {
  cv::Mat1b image, image_low, image_high;
  ArrangedImage values, low, high;
};

struct CandidateSource {
  std::vector<CandidateChannel> channels;  // arranged alike: the same address reads each channel
  ptrdiff_t origin = 0;
  ptrdiff_t x_step = 0;
  ptrdiff_t y_step = 0;
  std::vector<BilinearTap> taps;  // one per candidate; empty for direct sources
  int step_x = 0, step_y = 0;     // direct sources: the whole-pixel step per disparity
  // A direct camera along the rows (step_y = 0) whose candidates' sampling intervals the loop takes
  // from each arranged row of values as it enters the row: nothing is prepared but the values,
  // and the loop reads the intervals from a row buffer instead of two images.
  bool row_intervals = false;

  bool tabulated() const { return !taps.empty(); }
};

// One channel of the reference, padded by margin. With PixelCost::kBirchfieldTomasi its sampling
// interval along each camera's baseline (one pair per camera, as the cameras' baselines may point
// different ways).
struct ReferenceChannel {
  cv::Mat1b image, padded;  // `image` is the interior of `padded`
  std::vector<cv::Mat1b> low, high;
};

// What a pixel cost reads: the candidates' values, their sampling intervals, the reference's.
constexpr bool readsCandidateValues(PixelCost cost) { return cost != PixelCost::kBirchfieldTomasiOneSided; }
constexpr bool readsCandidateIntervals(PixelCost cost) { return cost != PixelCost::kAbsoluteDifference; }
constexpr bool readsReferenceIntervals(PixelCost cost) { return cost == PixelCost::kBirchfieldTomasi; }

struct PreparedFrame {
  std::vector<ReferenceChannel> reference;  // one per channel
  std::vector<CandidateSource> sources;
  PixelCost pixel_cost = PixelCost::kAbsoluteDifference;
  int margin = 0;
  int radius = 0;
  int min_disparity = 0;
  int disparities = 0;         // D
  int padded_disparities = 0;  // D rounded up to whole byte vectors
  int max_difference = 255;    // the largest cost of one pixel, all channels
  bool best_half = false;
  bool subpixel = false;
  bool second_best = false;  // find the runner-up score (SadMatch::second_score)
  bool sum_scores = true;    // add up all candidates' scores (SadMatch::score_sum)
  bool scanline = false;     // the horizontal paths, with their jump costs per window pixel and camera
  bool paths_from_above = false;  // CostAggregation::kSemiGlobal: also the three paths from the row above
  double scanline_p1 = 0, scanline_p2 = 0;
  // The scanline's paths in bytes, from the window scores divided by 2^path_shift (see
  // scanlinePathShift); -1: paths in the scores' own width.
  int path_shift = -1;
  // Binocular horizontal rig with the left-right check: +1 if candidate d of pixel x is pixel
  // x - d of the secondary image, -1 if x + d; 0 = no reverse match (SadMatch::reverse_disparity).
  int reverse_sign = 0;

  bool candidateValues() const { return readsCandidateValues(pixel_cost); }
  bool candidateIntervals() const { return readsCandidateIntervals(pixel_cost); }
  bool referenceIntervals() const { return readsReferenceIntervals(pixel_cost); }
};

// A rectangle of reference pixels whose candidates, at every disparity, are inside the images of
// exactly `cameras`.
struct MatchRegion {
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  std::vector<int> cameras;
};

// One instruction set's build of the loop: it matches the reference pixels of a region, with
// 16-bit scores (when the largest possible score fits) or 32-bit ones. Candidate disparities are
// padded to a multiple of byte_lanes, the candidates of one 8-bit vector.
// The semi-global paths from above are built separately: the other loops run as tight as
// without them. So is the scanline with byte paths (16-bit window scores, path_shift >= 0).
struct SadKernel {
  using Match = void (*)(const PreparedFrame& frame, const MatchRegion& region, SadMatch& out);
  int byte_lanes;
  Match match[2][2];  // [32-bit scores][paths from above]
  Match match_byte_paths;
};

const SadKernel& sse2SadKernel();
const SadKernel& avx2SadKernel();  // call only where the CPU has AVX2 (simdSupported)

// The kernel of `level`, which the CPU must run (validateStereoOptions checks it); kAuto is the
// widest the CPU runs.
const SadKernel& sadKernel(SimdLevel level);

}  // namespace stereonav
