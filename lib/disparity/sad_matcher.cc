#include "disparity/sad_matcher.h"

#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "disparity/disparity_image.h"
#include "disparity/prefilter.h"
#include "disparity/sad_kernel.h"

// The engine follows cv::StereoBM's structure: per image row, column sums over the window rows
// are kept for every (x, d) and updated by adding the entering row's absolute differences and
// subtracting the leaving row's (kept in a ring buffer, so nothing is recomputed); a horizontal
// running sum over x then gives the window score of all candidates of a pixel at once, and the
// winner-takes-all search and the sum of all scores (for the uniqueness test) happen in the
// same pass. Candidates are laid out so that the disparities of one pixel are contiguous bytes,
// which makes every step a vector operation across disparities (OpenCV universal intrinsics).
// Several cameras are combined by summing their absolute differences before the box filter: the
// sum of the cameras' SADs is the SAD of the summed differences (paper section 2.2).
// That loop is sad_kernel_loop.h, built for SSE2 and for AVX2; the matcher picks one at run time
// (options.simd). This file prepares the images it reads and splits the work.

namespace stereonav {
namespace {

int roundUp(int value, int multiple) { return (value + multiple - 1) / multiple * multiple; }

// A sample offset split as the bilinear taps use it: whole pixels and a fraction in 1/256.
void splitOffset(double offset, int& whole, int& weight) {
  whole = static_cast<int>(std::floor(offset));
  weight = static_cast<int>(std::lround((offset - whole) * 256.0));
  if (weight == 256) {
    ++whole;
    weight = 0;
  }
}

// The whole-pixel step per disparity (-1, 0 or 1) that a baseline component `b` samples at every
// candidate, if interpolation would land exactly on pixels there. Calibrations read from rawlogs
// carry rounding (by = -0.99999999999999978): such a camera reads exactly the pixels of the unit
// one, so it takes the direct layout, not the (several times slower) interpolated one.
bool wholePixelStep(double b, int min_d, int max_d, int& step) {
  step = static_cast<int>(std::lround(b));
  if (std::abs(step) > 1) return false;
  for (int d = min_d; d <= max_d; ++d) {
    int whole = 0, weight = 0;
    splitOffset(-b * d, whole, weight);
    if (weight != 0 || whole != -step * d) return false;
  }
  return true;
}

// The largest cost of one pixel against one camera, all channels: grey levels at a quarter scale
// (rounded, 0..64) add at most 64.
int largestPixelCost(const StereoOptions& options) {
  return maxPrefilteredDifference(options.prefilter, options.prefilter_cap) + (options.intensity_term ? 64 : 0);
}

long long largestWindowScore(const StereoOptions& options, int cameras) {
  return static_cast<long long>(options.window) * options.window * largestPixelCost(options) * cameras;
}

// Grey level v at a quarter scale, rounded half up: (v + 2) / 4, 0..64.
const cv::Mat1b& quarterScale() {
  static const cv::Mat1b table = [] {
    cv::Mat1b values(1, 256);
    for (int v = 0; v < 256; ++v) values(0, v) = static_cast<uchar>((v + 2) >> 2);
    return values;
  }();
  return table;
}

// Rewrites `image` so that its diagonals x - y = const become rows: sheared(x - y + rows - 1, y) =
// image(y, x). Entries off the image are never read.
void shear(const cv::Mat1b& image, cv::Mat1b& sheared) {
  sheared.create(image.cols + image.rows - 1, image.rows);
  const ptrdiff_t step = static_cast<ptrdiff_t>(sheared.step);
  for (int y = 0; y < image.rows; ++y) {
    const uchar* row = image.ptr<uchar>(y);
    uchar* column = sheared.data + (image.rows - 1 - y) * step + y;
    for (int x = 0; x < image.cols; ++x) column[x * step] = row[x];
  }
}

// The image of `size` inside `padded`, `margin` pixels in from each side (allocating `padded`
// once per frame size): images are written there and padded in place (padInPlace), which saves a
// copy of the whole image per padding.
cv::Mat1b interior(cv::Mat1b& padded, cv::Size size, int margin) {
  padded.create(size.height + 2 * margin, size.width + 2 * margin);
  return padded(cv::Rect(margin, margin, size.width, size.height));
}

// Fills the margins of `padded` around its interior `inside` with the nearest interior pixel.
// cv::copyMakeBorder sees its source inside its destination and builds only the border; isolated,
// so that it does not take the margins around the interior for image.
void padInPlace(const cv::Mat1b& inside, int margin, cv::Mat1b& padded) {
  cv::copyMakeBorder(inside, padded, margin, margin, margin, margin, cv::BORDER_REPLICATE | cv::BORDER_ISOLATED);
}

// Arranges `image` as CandidateSource describes for a direct camera of whole-pixel steps (sx, sy)
// (candidate d of pixel (x, y) is (x - sx*d, y - sy*d)), or only pads it for a tabulated one.
// Flipping the axes with a positive step makes the candidate (x' + |sx| d, y' + |sy| d) in the
// flipped image, x' = width-1-x or x.
void arrangeImage(const cv::Mat1b& image, int sx, int sy, int margin, ArrangedImage& arranged) {
  cv::Mat1b inside = interior(arranged.padded, image.size(), margin);
  if (sx > 0 || sy > 0) {
    cv::flip(image, inside, sx > 0 && sy > 0 ? -1 : (sx > 0 ? 1 : 0));
  } else {
    image.copyTo(inside);
  }
  padInPlace(inside, margin, arranged.padded);
  if (sy == 0) {
    arranged.buffer = arranged.padded;
  } else if (sx == 0) {
    cv::transpose(arranged.padded, arranged.buffer);
  } else {
    shear(arranged.padded, arranged.buffer);
  }
}

// The sampling interval of Birchfield and Tomasi along the direction (dx, dy): for each pixel,
// the lowest and highest of its value and the values halfway to its two neighbours along it
// (borders replicated; halves rounded up).
void samplingInterval(const cv::Mat1b& image, int dx, int dy, cv::Mat1b& low, cv::Mat1b& high) {
  thread_local cv::Mat1b padded;
  // Isolated: `image` may lie inside a padded image, whose margins are not this border.
  cv::copyMakeBorder(image, padded, 1, 1, 1, 1, cv::BORDER_REPLICATE | cv::BORDER_ISOLATED);
  low.create(image.size());
  high.create(image.size());
  const int width = image.cols;
  for (int y = 0; y < image.rows; ++y) {
    const uchar* row = padded.ptr<uchar>(y + 1) + 1;
    const uchar* before = padded.ptr<uchar>(y + 1 - dy) + 1 - dx;
    const uchar* after = padded.ptr<uchar>(y + 1 + dy) + 1 + dx;
    uchar* low_row = low.ptr<uchar>(y);
    uchar* high_row = high.ptr<uchar>(y);
    // Plain loops: the compiler turns the rounded halves into byte averages (pavgb).
    for (int x = 0; x < width; ++x) {
      const int value = row[x];
      const int half_before = (value + before[x] + 1) >> 1, half_after = (value + after[x] + 1) >> 1;
      low_row[x] = static_cast<uchar>(std::min({value, half_before, half_after}));
      high_row[x] = static_cast<uchar>(std::max({value, half_before, half_after}));
    }
  }
}

// The direction along which a camera of baseline (bx, by) samples the candidates, in whole
// pixels (one of the eight neighbours).
cv::Point baselineDirection(const SecondaryCamera& camera) {
  const double longest = std::max(std::abs(camera.bx), std::abs(camera.by));
  return {static_cast<int>(std::lround(camera.bx / longest)), static_cast<int>(std::lround(camera.by / longest))};
}

// Fills `source` for one secondary camera from its channels' images (and, for Birchfield-Tomasi,
// their sampling intervals unless the loop takes them row by row), reusing its buffers when the
// frame size is unchanged.
void prepareCandidateSource(const SecondaryCamera& camera, const PreparedFrame& frame, CandidateSource& source) {
  const cv::Mat1b& first_image = source.channels.front().image;
  const int width = first_image.cols, height = first_image.rows, margin = frame.margin;
  const int min_d = frame.min_disparity, max_d = frame.min_disparity + frame.disparities - 1;
  int sx = 0, sy = 0;
  const bool direct = wholePixelStep(camera.bx, min_d, max_d, sx) && wholePixelStep(camera.by, min_d, max_d, sy) &&
                      (sx != 0 || sy != 0);
  source.taps.clear();
  source.step_x = direct ? sx : 0;
  source.step_y = direct ? sy : 0;
  source.row_intervals = direct && sy == 0 && frame.candidateIntervals();
  if (!direct) sx = sy = 0;  // tabulated: padded only
  const bool interval_images = frame.candidateIntervals() && !source.row_intervals;
  const bool values = frame.candidateValues() || source.row_intervals;
  for (CandidateChannel& channel : source.channels) {
    if (values) arrangeImage(channel.image, sx, sy, margin, channel.values);
    if (interval_images) {
      const cv::Point direction = baselineDirection(camera);
      samplingInterval(channel.image, direction.x, direction.y, channel.image_low, channel.image_high);
      arrangeImage(channel.image_low, sx, sy, margin, channel.low);
      arrangeImage(channel.image_high, sx, sy, margin, channel.high);
    }
  }
  // Every arranged image of the source has the same layout.
  const CandidateChannel& first_channel = source.channels.front();
  const ArrangedImage& arranged = values ? first_channel.values : first_channel.low;
  const ptrdiff_t step = static_cast<ptrdiff_t>(arranged.buffer.step);
  if (direct) {
    const ptrdiff_t x_sign = sx > 0 ? -1 : 1, y_sign = sy > 0 ? -1 : 1;
    const ptrdiff_t x_first = sx > 0 ? width - 1 : 0, y_first = sy > 0 ? height - 1 : 0;  // x', y' of pixel (0, 0)
    if (sy == 0) {  // padded row y'+m, column x'+m+d
      source.origin = margin * step + margin + x_first + min_d;
      source.x_step = x_sign;
      source.y_step = step;
    } else if (sx == 0) {  // transposed row x+m, column y'+m+d
      source.origin = margin * step + margin + y_first + min_d;
      source.x_step = step;
      source.y_step = y_sign;
    } else {  // sheared row x'-y'+rows-1, column y'+m+d
      source.origin = (x_first - y_first + arranged.padded.rows - 1) * step + margin + y_first + min_d;
      source.x_step = x_sign * step;
      source.y_step = y_sign * (1 - step);
    }
    return;
  }
  source.origin = margin * step + margin;
  source.x_step = 1;
  source.y_step = step;
  for (int j = 0; j < frame.padded_disparities; ++j) {
    // Padding lanes repeat the last disparity so that their samples stay inside the image.
    const int d = min_d + std::min(j, frame.disparities - 1);
    BilinearTap tap;
    int wx = 0, wy = 0;
    splitOffset(-camera.bx * d, tap.dx, wx);
    splitOffset(-camera.by * d, tap.dy, wy);
    tap.w00 = (256 - wx) * (256 - wy);
    tap.w01 = wx * (256 - wy);
    tap.w10 = (256 - wx) * wy;
    tap.w11 = wx * wy;
    source.taps.push_back(tap);
  }
}

// Reference rows or columns [lo, hi] whose candidates at every disparity lie inside the image
// for a camera offset b along this axis (the sample is at coordinate - b*d).
void visibleRange(double b, int min_d, int max_d, int size, int& lo, int& hi) {
  const double near_shift = b * min_d, far_shift = b * max_d;
  lo = std::max(0, static_cast<int>(std::ceil(std::max(near_shift, far_shift))));
  hi = std::min(size - 1, size - 1 + static_cast<int>(std::floor(std::min(near_shift, far_shift))));
}

// The regions to match, and in `unseen` the rectangles that no camera sees at every candidate
// (with `partial_candidates`: at any candidate). A pixel is matched with the cameras that see it at
// every candidate; with `partial_candidates`, where there are none, with those that see it at some.
std::vector<MatchRegion> matchRegions(const StereoFrame& frame, int min_d, int max_d, bool partial_candidates,
                                      std::vector<cv::Rect>& unseen) {
  const int width = frame.reference.cols, height = frame.reference.rows;
  const size_t cameras = frame.secondaries.size();
  // [0]: seen at every candidate; [1]: at the nearest candidate (the last to leave the image).
  std::vector<int> x_lo[2], x_hi[2], y_lo[2], y_hi[2];
  std::vector<int> x_cuts{0, width}, y_cuts{0, height};
  const int kinds = partial_candidates ? 2 : 1;
  for (int kind = 0; kind < kinds; ++kind) {
    for (auto* bounds : {&x_lo[kind], &x_hi[kind], &y_lo[kind], &y_hi[kind]}) bounds->resize(cameras);
    for (size_t c = 0; c < cameras; ++c) {
      const SecondaryCamera& camera = frame.secondaries[c].camera;
      const int far_d = kind == 0 ? max_d : min_d;
      visibleRange(camera.bx, min_d, far_d, width, x_lo[kind][c], x_hi[kind][c]);
      visibleRange(camera.by, min_d, far_d, height, y_lo[kind][c], y_hi[kind][c]);
      x_cuts.insert(x_cuts.end(), {std::clamp(x_lo[kind][c], 0, width), std::clamp(x_hi[kind][c] + 1, 0, width)});
      y_cuts.insert(y_cuts.end(), {std::clamp(y_lo[kind][c], 0, height), std::clamp(y_hi[kind][c] + 1, 0, height)});
    }
  }
  for (auto* cuts : {&x_cuts, &y_cuts}) {
    std::sort(cuts->begin(), cuts->end());
    cuts->erase(std::unique(cuts->begin(), cuts->end()), cuts->end());
  }
  std::vector<MatchRegion> regions;
  unseen.clear();
  for (size_t i = 0; i + 1 < y_cuts.size(); ++i) {
    for (size_t k = 0; k + 1 < x_cuts.size(); ++k) {
      MatchRegion cell{x_cuts[k], x_cuts[k + 1], y_cuts[i], y_cuts[i + 1], {}};
      for (int kind = 0; kind < kinds && cell.cameras.empty(); ++kind) {
        for (size_t c = 0; c < cameras; ++c) {
          if (x_lo[kind][c] <= cell.x0 && x_hi[kind][c] >= cell.x1 - 1 && y_lo[kind][c] <= cell.y0 &&
              y_hi[kind][c] >= cell.y1 - 1) {
            cell.cameras.push_back(static_cast<int>(c));
          }
        }
      }
      if (cell.cameras.empty()) {
        unseen.emplace_back(cell.x0, cell.y0, cell.x1 - cell.x0, cell.y1 - cell.y0);
        continue;
      }
      MatchRegion* left = regions.empty() ? nullptr : &regions.back();
      if (left && left->y0 == cell.y0 && left->x1 == cell.x0 && left->cameras == cell.cameras) {
        left->x1 = cell.x1;
      } else {
        regions.push_back(cell);
      }
    }
  }
  return regions;
}

}  // namespace

const SadKernel& sadKernel(SimdLevel level) {
  if (level == SimdLevel::kAuto) level = simdSupported(SimdLevel::kAvx2) ? SimdLevel::kAvx2 : SimdLevel::kSse2;
  return level == SimdLevel::kAvx2 ? avx2SadKernel() : sse2SadKernel();
}

struct SadMatcher::Workspace {
  const SadKernel* kernel = nullptr;
  PreparedFrame prepared;
  SadMatch result;
};

namespace {

// The prefiltered, border-padded reference and the candidate sources of every secondary view.
void prepareFrame(const StereoFrame& frame, const StereoOptions& options, const SadKernel& kernel,
                  PreparedFrame& prepared) {
  prepared.radius = options.window / 2;
  prepared.min_disparity = options.min_disparity;
  prepared.disparities = options.disparityCount();
  prepared.padded_disparities = roundUp(prepared.disparities, kernel.byte_lanes);
  const int channels = options.intensity_term ? 2 : 1;
  prepared.max_difference = largestPixelCost(options);
  // Candidates off the image read the replicated border: pixels near the edge with
  // partial_candidates reach up to the last (padding) candidate's offset beyond it.
  double widest_baseline = 0;
  for (const SecondaryView& view : frame.secondaries) {
    widest_baseline = std::max({widest_baseline, std::abs(view.camera.bx), std::abs(view.camera.by)});
  }
  const int beyond_edge =
      options.partial_candidates
          ? static_cast<int>(std::ceil(widest_baseline * (prepared.min_disparity + prepared.padded_disparities)))
          : 0;
  prepared.margin = prepared.radius + std::max(prepared.padded_disparities, beyond_edge) + 2;
  prepared.best_half = options.combination == CameraCombination::kBestHalf;
  prepared.subpixel = options.subpixel;
  prepared.second_best = options.second_best_ratio < 1.0;
  prepared.sum_scores = options.uniqueness_threshold < 1.0;
  prepared.pixel_cost = options.pixel_cost;
  prepared.scanline = options.aggregation != CostAggregation::kWindow;
  prepared.paths_from_above = options.aggregation == CostAggregation::kSemiGlobal;
  prepared.scanline_p1 = options.scanline_p1;
  prepared.scanline_p2 = options.scanline_p2;
  prepared.path_shift = scanlinePathShift(options, static_cast<int>(frame.secondaries.size()));
  const auto channelImage = [&](const cv::Mat1b& image, int channel, cv::Mat1b& out) {
    if (channel == 0) {
      prefilterImage(image, options.prefilter, options.prefilter_cap, options.texture_sigma, out);
    } else {
      cv::LUT(image, quarterScale(), out);
    }
  };
  const size_t cameras = frame.secondaries.size();
  prepared.sources.resize(cameras);
  prepared.reference.resize(channels);
  const int margin = prepared.margin;
  // View 0 is the reference, view c + 1 secondary camera c; each writes only its own images, so
  // with several threads they are prepared in parallel (done on one, this would cap what a
  // second thread gains on small images).
  const auto prepareViews = [&](const cv::Range& views) {
    for (int view = views.start; view < views.end; ++view) {
      if (view == 0) {
        for (int k = 0; k < channels; ++k) {
          ReferenceChannel& channel = prepared.reference[k];
          channel.image = interior(channel.padded, frame.reference.size(), margin);
          channelImage(frame.reference, k, channel.image);
          padInPlace(channel.image, margin, channel.padded);
          channel.low.resize(prepared.referenceIntervals() ? cameras : 0);
          channel.high.resize(prepared.referenceIntervals() ? cameras : 0);
          for (size_t c = 0; c < channel.low.size(); ++c) {
            const cv::Point direction = baselineDirection(frame.secondaries[c].camera);
            cv::Mat1b low = interior(channel.low[c], frame.reference.size(), margin);
            cv::Mat1b high = interior(channel.high[c], frame.reference.size(), margin);
            samplingInterval(channel.image, direction.x, direction.y, low, high);
            padInPlace(low, margin, channel.low[c]);
            padInPlace(high, margin, channel.high[c]);
          }
        }
        continue;
      }
      CandidateSource& source = prepared.sources[view - 1];
      const SecondaryCamera& camera = frame.secondaries[view - 1].camera;
      source.channels.resize(channels);
      for (int k = 0; k < channels; ++k) {
        CandidateChannel& channel = source.channels[k];
        channelImage(frame.secondaries[view - 1].image, k, channel.image);
      }
      prepareCandidateSource(camera, prepared, source);
    }
  };
  const int views = static_cast<int>(frame.secondaries.size()) + 1;
  if (options.threads == 1) {
    prepareViews(cv::Range(0, views));
  } else {
    cv::parallel_for_(cv::Range(0, views), prepareViews, std::min(options.threads, views));
  }
}

// The output images, with the pixels of the `unseen` rectangles at their starting values (the
// loop writes every other pixel); the left-right check's and the runner-up's images only when
// they are asked for (a binocular horizontal rig for the one-pass left-right check).
void resetResult(int height, int width, const StereoOptions& options, const std::vector<cv::Rect>& unseen,
                 PreparedFrame& prepared, SadMatch& match) {
  const auto reset = [&](cv::Mat& image, const cv::Scalar& value) {
    for (const cv::Rect& rect : unseen) image(rect).setTo(value);
  };
  match.disparity.create(height, width);
  reset(match.disparity, kInvalidDisparity);
  match.best_score.create(height, width);
  reset(match.best_score, 0);
  match.score_sum.create(height, width);
  reset(match.score_sum, 0);
  const CandidateSource& first_source = prepared.sources.front();
  prepared.reverse_sign = options.left_right_check && prepared.sources.size() == 1 && first_source.step_y == 0
                              ? first_source.step_x
                              : 0;
  if (prepared.reverse_sign) {
    match.reverse_disparity.create(height, width);
    match.reverse_disparity.setTo(kInvalidDisparity);  // the loop writes only the pixels matched back
  } else {
    match.reverse_disparity.release();
  }
  if (prepared.second_best) {
    match.second_score.create(height, width);
    reset(match.second_score, std::numeric_limits<int>::max());
  } else {
    match.second_score.release();
  }
}

// Near the edges (partial_candidates), a winner whose candidate lies off a camera's image was
// compared with the replicated border: no match. Only pixels outside the rectangle where the
// camera sees every candidate can have one.
void rejectMatchesOffTheImage(const StereoFrame& frame, const std::vector<MatchRegion>& regions, int min_d, int max_d,
                              cv::Mat1f& disparity) {
  const int width = disparity.cols, height = disparity.rows;
  for (const MatchRegion& region : regions) {
    for (const int c : region.cameras) {
      const SecondaryCamera& camera = frame.secondaries[c].camera;
      int x_lo = 0, x_hi = 0, y_lo = 0, y_hi = 0;
      visibleRange(camera.bx, min_d, max_d, width, x_lo, x_hi);
      visibleRange(camera.by, min_d, max_d, height, y_lo, y_hi);
      const auto check = [&](int y, int x_from, int x_to) {
        float* row = disparity.ptr<float>(y);
        for (int x = x_from; x < x_to; ++x) {
          const float d = row[x];
          if (d == kInvalidDisparity) continue;
          const double sx = x - camera.bx * d, sy = y - camera.by * d;
          if (sx < 0 || sx > width - 1 || sy < 0 || sy > height - 1) row[x] = kInvalidDisparity;
        }
      };
      for (int y = region.y0; y < region.y1; ++y) {
        if (y < y_lo || y > y_hi) {
          check(y, region.x0, region.x1);
          continue;
        }
        check(y, region.x0, std::min(region.x1, x_lo));
        check(y, std::max(region.x0, x_hi + 1), region.x1);
      }
    }
  }
}

}  // namespace

SadMatcher::SadMatcher(const StereoOptions& options) : options_(options), workspace_(std::make_unique<Workspace>()) {
  validateStereoOptions(options_);
  workspace_->kernel = &sadKernel(options_.simd);
}

SadMatcher::~SadMatcher() = default;

int scanlinePathShift(const StereoOptions& options, int cameras) {
  const long long largest_score = largestWindowScore(options, cameras);
  if (options.aggregation != CostAggregation::kScanline || options.disparityCount() > 256 ||
      largest_score > std::numeric_limits<int16_t>::max()) {
    return -1;
  }
  int shift = 0;
  while ((largest_score >> shift) >= 512) ++shift;
  const double large_jump = std::ldexp(options.scanline_p2 * options.window * options.window * cameras, -shift);
  return std::lround(large_jump) <= 255 ? shift : -1;
}

const SadMatch& SadMatcher::match(const StereoFrame& frame) {
  checkStereoFrame(frame);
  if (frame.secondaries.size() > kMaxCameras) {
    throw std::invalid_argument("stereo frame: at most " + std::to_string(kMaxCameras) + " secondary views");
  }
  const StereoOptions& options = options_;
  PreparedFrame& prepared = workspace_->prepared;
  const SadKernel& kernel = *workspace_->kernel;
  prepareFrame(frame, options, kernel, prepared);
  SadMatch& match = workspace_->result;
  std::vector<cv::Rect> unseen;
  const std::vector<MatchRegion> regions =
      matchRegions(frame, options.min_disparity, options.max_disparity, options.partial_candidates, unseen);
  resetResult(frame.reference.rows, frame.reference.cols, options, unseen, prepared, match);

  const int height = frame.reference.rows;
  const long long largest_score = largestWindowScore(options, static_cast<int>(frame.secondaries.size()));
  // With paths, a score is the sum of two (scanline) or five (semi-global) paths, each at most the
  // largest window score plus the large-jump cost.
  const int paths = prepared.paths_from_above ? 5 : prepared.scanline ? 2 : 0;
  const long long largest_total =
      paths ? paths * (largest_score + static_cast<long long>(std::ceil(options.scanline_p2 * options.window *
                                                                         options.window * frame.secondaries.size())))
            : largest_score;
  const bool narrow = largest_total <= std::numeric_limits<int16_t>::max();
  // Paths from the row above run down the whole image: stripes would cut them.
  const int stripes = prepared.paths_from_above ? 1 : std::min(options.threads, height);
  const auto matchStripes = [&](const cv::Range& range) {
    for (int stripe = range.start; stripe < range.end; ++stripe) {
      const int top = height * stripe / stripes, bottom = height * (stripe + 1) / stripes;
      for (MatchRegion region : regions) {
        region.y0 = std::max(region.y0, top);
        region.y1 = std::min(region.y1, bottom);
        if (region.y0 >= region.y1) continue;
        const SadKernel::Match match_region = prepared.path_shift >= 0
                                                  ? kernel.match_byte_paths
                                                  : kernel.match[narrow ? 0 : 1][prepared.paths_from_above ? 1 : 0];
        match_region(prepared, region, match);
      }
    }
  };
  if (stripes == 1) {
    matchStripes(cv::Range(0, 1));
  } else {
    cv::parallel_for_(cv::Range(0, stripes), matchStripes, stripes);
  }
  if (options.partial_candidates) {
    rejectMatchesOffTheImage(frame, regions, options.min_disparity, options.max_disparity, match.disparity);
  }
  return match;
}

}  // namespace stereonav
