#include "disparity/sad_matcher.h"

#include <opencv2/core/hal/intrin.hpp>
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

// The engine follows cv::StereoBM's structure: per image row, column sums over the window rows
// are kept for every (x, d) and updated by adding the entering row's absolute differences and
// subtracting the leaving row's (kept in a ring buffer, so nothing is recomputed); a horizontal
// running sum over x then gives the window score of all candidates of a pixel at once, and the
// winner-takes-all search and the sum of all scores (for the uniqueness test) happen in the
// same pass. Candidates are laid out so that the disparities of one pixel are contiguous bytes,
// which makes every step a vector operation across disparities (OpenCV universal intrinsics).
// Several cameras are combined by summing their absolute differences before the box filter: the
// sum of the cameras' SADs is the SAD of the summed differences (paper section 2.2).

namespace stereonav {
namespace {

constexpr int kByteLanes = 16;  // candidates compared per 8-bit vector
constexpr size_t kMaxCameras = 16;

int roundUp(int value, int multiple) { return (value + multiple - 1) / multiple * multiple; }

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
struct CandidateSource {
  cv::Mat1b filtered, flipped, padded;  // the prefiltered image, flipped, padded by the margin
  cv::Mat1b buffer;  // `padded`, or its transpose or shear for vertical and diagonal cameras
  ptrdiff_t origin = 0;
  ptrdiff_t x_step = 0;
  ptrdiff_t y_step = 0;
  std::vector<BilinearTap> taps;  // one per candidate; empty for direct sources
  int step_x = 0, step_y = 0;     // direct sources: the whole-pixel step per disparity

  bool tabulated() const { return !taps.empty(); }
};

struct PreparedFrame {
  cv::Mat1b filtered_reference;
  cv::Mat1b reference;  // prefiltered, padded by margin
  std::vector<CandidateSource> sources;
  int margin = 0;
  int radius = 0;
  int min_disparity = 0;
  int disparities = 0;         // D
  int padded_disparities = 0;  // D rounded up to whole byte vectors
  bool best_half = false;
  bool subpixel = false;
  bool second_best = false;  // find the runner-up score (SadMatch::second_score)
  bool sum_scores = true;    // add up all candidates' scores (SadMatch::score_sum)
  bool scanline = false;     // CostAggregation::kScanline, with its jump costs per window pixel and camera
  double scanline_p1 = 0, scanline_p2 = 0;
  // Binocular horizontal rig with the left-right check: +1 if candidate d of pixel x is pixel
  // x - d of the secondary image, -1 if x + d; 0 = no reverse match (SadMatch::reverse_disparity).
  int reverse_sign = 0;
};

// A rectangle of reference pixels whose candidates, at every disparity, are inside the images of
// exactly `cameras`.
struct MatchRegion {
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  std::vector<int> cameras;
};

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

// Fills `source` for one secondary camera, reusing its buffers when the frame size is unchanged.
void prepareCandidateSource(const cv::Mat1b& image, const SecondaryCamera& camera, const PreparedFrame& frame,
                            CandidateSource& source) {
  const int width = image.cols, height = image.rows, margin = frame.margin;
  const int min_d = frame.min_disparity, max_d = frame.min_disparity + frame.disparities - 1;
  int sx = 0, sy = 0;
  const bool direct = wholePixelStep(camera.bx, min_d, max_d, sx) && wholePixelStep(camera.by, min_d, max_d, sy) &&
                      (sx != 0 || sy != 0);
  source.taps.clear();
  source.step_x = direct ? sx : 0;
  source.step_y = direct ? sy : 0;
  if (direct) {
    // Candidate d of pixel (x, y) is (x - sx*d, y - sy*d). Flipping the axes with a positive
    // step makes it (x' + |sx| d, y' + |sy| d) in the flipped image, x' = width-1-x or x.
    cv::Mat1b arranged = image;
    if (sx > 0 || sy > 0) {
      cv::flip(image, source.flipped, sx > 0 && sy > 0 ? -1 : (sx > 0 ? 1 : 0));
      arranged = source.flipped;
    }
    cv::copyMakeBorder(arranged, source.padded, margin, margin, margin, margin, cv::BORDER_REPLICATE);
    const ptrdiff_t x_sign = sx > 0 ? -1 : 1, y_sign = sy > 0 ? -1 : 1;
    const ptrdiff_t x_first = sx > 0 ? width - 1 : 0, y_first = sy > 0 ? height - 1 : 0;  // x', y' of pixel (0, 0)
    if (sy == 0) {  // padded row y'+m, column x'+m+d
      source.buffer = source.padded;
      const ptrdiff_t step = static_cast<ptrdiff_t>(source.buffer.step);
      source.origin = margin * step + margin + x_first + min_d;
      source.x_step = x_sign;
      source.y_step = step;
    } else if (sx == 0) {  // transposed row x+m, column y'+m+d
      cv::transpose(source.padded, source.buffer);
      const ptrdiff_t step = static_cast<ptrdiff_t>(source.buffer.step);
      source.origin = margin * step + margin + y_first + min_d;
      source.x_step = step;
      source.y_step = y_sign;
    } else {  // sheared row x'-y'+rows-1, column y'+m+d
      shear(source.padded, source.buffer);
      const ptrdiff_t step = static_cast<ptrdiff_t>(source.buffer.step);
      source.origin = (x_first - y_first + source.padded.rows - 1) * step + margin + y_first + min_d;
      source.x_step = x_sign * step;
      source.y_step = y_sign * (1 - step);
    }
    return;
  }
  cv::copyMakeBorder(image, source.padded, margin, margin, margin, margin, cv::BORDER_REPLICATE);
  source.buffer = source.padded;
  const ptrdiff_t step = static_cast<ptrdiff_t>(source.buffer.step);
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

std::vector<MatchRegion> matchRegions(const StereoFrame& frame, int min_d, int max_d) {
  const int width = frame.reference.cols, height = frame.reference.rows;
  const size_t cameras = frame.secondaries.size();
  std::vector<int> x_lo(cameras), x_hi(cameras), y_lo(cameras), y_hi(cameras);
  std::vector<int> x_cuts{0, width}, y_cuts{0, height};
  for (size_t c = 0; c < cameras; ++c) {
    const SecondaryCamera& camera = frame.secondaries[c].camera;
    visibleRange(camera.bx, min_d, max_d, width, x_lo[c], x_hi[c]);
    visibleRange(camera.by, min_d, max_d, height, y_lo[c], y_hi[c]);
    x_cuts.insert(x_cuts.end(), {std::clamp(x_lo[c], 0, width), std::clamp(x_hi[c] + 1, 0, width)});
    y_cuts.insert(y_cuts.end(), {std::clamp(y_lo[c], 0, height), std::clamp(y_hi[c] + 1, 0, height)});
  }
  for (auto* cuts : {&x_cuts, &y_cuts}) {
    std::sort(cuts->begin(), cuts->end());
    cuts->erase(std::unique(cuts->begin(), cuts->end()), cuts->end());
  }
  std::vector<MatchRegion> regions;
  for (size_t i = 0; i + 1 < y_cuts.size(); ++i) {
    for (size_t k = 0; k + 1 < x_cuts.size(); ++k) {
      MatchRegion cell{x_cuts[k], x_cuts[k + 1], y_cuts[i], y_cuts[i + 1], {}};
      for (size_t c = 0; c < cameras; ++c) {
        if (x_lo[c] <= cell.x0 && x_hi[c] >= cell.x1 - 1 && y_lo[c] <= cell.y0 && y_hi[c] >= cell.y1 - 1) {
          cell.cameras.push_back(static_cast<int>(c));
        }
      }
      if (cell.cameras.empty()) continue;
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

// The vector type that accumulates scores: 16-bit when the largest possible window score fits in
// an int16 (SSE2 compares and takes minima of signed 16-bit lanes natively), 32-bit otherwise.
template <typename Acc>
struct AccumulatorLanes;

template <>
struct AccumulatorLanes<int16_t> {
  using Vec = cv::v_int16x8;
  static constexpr int kCount = 8;
  static void widen(const cv::v_uint8x16& bytes, Vec* out) {
    cv::v_uint16x8 low, high;
    cv::v_expand(bytes, low, high);
    out[0] = cv::v_reinterpret_as_s16(low);
    out[1] = cv::v_reinterpret_as_s16(high);
  }
  // OpenCV's 16-bit + and - saturate; running sums need modular arithmetic, which is exact as
  // long as the true result fits.
  static Vec add(const Vec& a, const Vec& b) { return cv::v_add_wrap(a, b); }
  static Vec subtract(const Vec& a, const Vec& b) { return cv::v_sub_wrap(a, b); }
  static Vec slide(const Vec& sum, const Vec& entering, const Vec& leaving) {
    return cv::v_sub_wrap(cv::v_add_wrap(sum, entering), leaving);
  }
  // Pairwise 32-bit sums of the lanes (one multiply-add instruction).
  static cv::v_int32x4 widenSum(const Vec& v) { return cv::v_dotprod(v, cv::v_setall_s16(1)); }
  static Vec all(int value) { return cv::v_setall_s16(static_cast<short>(value)); }
  // Sign bits of a's lanes then b's (lanes of comparison masks are 0 or -1).
  static unsigned packedSignMask(const Vec& a, const Vec& b) {
    return static_cast<unsigned>(cv::v_signmask(cv::v_pack(a, b)));
  }
};

template <>
struct AccumulatorLanes<int32_t> {
  using Vec = cv::v_int32x4;
  static constexpr int kCount = 4;
  static void widen(const cv::v_uint8x16& bytes, Vec* out) {
    cv::v_uint16x8 low, high;
    cv::v_expand(bytes, low, high);
    cv::v_uint32x4 parts[4];
    cv::v_expand(low, parts[0], parts[1]);
    cv::v_expand(high, parts[2], parts[3]);
    for (int i = 0; i < 4; ++i) out[i] = cv::v_reinterpret_as_s32(parts[i]);
  }
  static Vec add(const Vec& a, const Vec& b) { return a + b; }
  static Vec subtract(const Vec& a, const Vec& b) { return a - b; }
  static Vec slide(const Vec& sum, const Vec& entering, const Vec& leaving) { return sum + entering - leaving; }
  static cv::v_int32x4 widenSum(const Vec& v) { return v; }
  static Vec all(int value) { return cv::v_setall_s32(value); }
  static unsigned packedSignMask(const Vec& a, const Vec& b) {
    return static_cast<unsigned>(cv::v_signmask(cv::v_pack(a, b)));
  }
};

// Grows `buffer` if needed (buffers are reused from call to call: frames of one size need no new
// memory) and returns its start.
template <typename T>
T* scratch(std::vector<T>& buffer, size_t size) {
  if (buffer.size() < size) buffer.resize(size);
  return buffer.data();
}

// Index of the first of the `chunks` * kCount scores equal to `wanted` (one must be): the
// comparison masks of 64 lanes at a time are packed into one bit mask, so there is no
// data-dependent branch inside a block.
template <typename Lanes, typename Acc>
CV_ALWAYS_INLINE int firstLaneEqual(const Acc* scores, int chunks, const typename Lanes::Vec& wanted) {
  constexpr int kChunksPerBlock = 64 / Lanes::kCount;
  for (int block = 0; block < chunks; block += kChunksPerBlock) {
    const int block_chunks = std::min(chunks - block, kChunksPerBlock);
    uint64_t hits = 0;
    for (int chunk = 0; chunk < block_chunks; chunk += 2) {
      const Acc* first = scores + (block + chunk) * Lanes::kCount;
      const typename Lanes::Vec a = cv::v_load(first) == wanted;
      const typename Lanes::Vec b = chunk + 1 < block_chunks ? cv::v_load(first + Lanes::kCount) == wanted : Lanes::all(0);
      hits |= static_cast<uint64_t>(Lanes::packedSignMask(a, b)) << (chunk * Lanes::kCount);
    }
    if (hits) return block * Lanes::kCount + __builtin_ctzll(hits);
  }
  return 0;
}

template <typename Acc>
void matchRegion(const PreparedFrame& frame, const MatchRegion& region, SadMatch& out) {
  using Lanes = AccumulatorLanes<Acc>;
  using Vec = typename Lanes::Vec;
  constexpr int kVectorsPerBytes = kByteLanes / Lanes::kCount;
  constexpr Acc kMaxScore = std::numeric_limits<Acc>::max();

  const int r = frame.radius, window = 2 * r + 1, margin = frame.margin;
  const int disparities = frame.disparities, padded = frame.padded_disparities;
  const int x0 = region.x0, nx = region.x1 - region.x0 + 2 * r;
  const size_t row_size = static_cast<size_t>(nx) * padded;
  const int cameras = static_cast<int>(region.cameras.size());
  // Sum mode: one group of all cameras. Best-half: each camera its own group, and the
  // ceil(N/2) lowest group scores are added per candidate.
  const int groups = frame.best_half && cameras > 1 ? cameras : 1;
  const int kept = groups == 1 ? 1 : (cameras + 1) / 2;

  thread_local std::vector<Acc> ring_buffer, column_sum_buffer, score_buffer, combined_buffer;
  thread_local std::vector<uchar> table_buffer;
  thread_local std::vector<Acc> reverse_score_buffer, reverse_index_buffer;
  thread_local std::vector<Acc> row_cost_buffer, forward_path_buffer, backward_path_buffer;
  Acc* const ring = scratch(ring_buffer, groups * window * row_size);
  std::fill(ring, ring + groups * window * row_size, Acc{0});  // nothing leaves before the first rows
  // Column xe of group g is at column_sums + g * column_stride + (xe + 1) * padded; column -1 stays
  // zero, so the first pixel of a row slides its window in like every other one.
  const size_t column_stride = row_size + padded;
  Acc* const column_sums = scratch(column_sum_buffer, groups * column_stride);
  std::fill(column_sums, column_sums + groups * column_stride, Acc{0});
  Acc* const scores = scratch(score_buffer, static_cast<size_t>(groups) * padded);
  Acc* const combined = scratch(combined_buffer, padded);
  // Scanline: the scores of every pixel of a row, the paths from the left, and the last two of
  // the path from the right. A path's candidates sit between guard lanes that hold the largest
  // score, so that the neighbours of its first and last candidates are read without a test.
  const size_t row_pixels = frame.scanline ? static_cast<size_t>(region.x1 - region.x0) : 0;
  const size_t path_stride = static_cast<size_t>(padded) + 2 * Lanes::kCount;
  Acc* const row_costs = scratch(row_cost_buffer, row_pixels * padded);
  Acc* const forward_paths = scratch(forward_path_buffer, row_pixels * path_stride) + Lanes::kCount;
  Acc* const backward_paths = scratch(backward_path_buffer, 2 * path_stride) + Lanes::kCount;
  if (frame.scanline) {
    std::fill(forward_paths - Lanes::kCount, forward_paths - Lanes::kCount + row_pixels * path_stride, kMaxScore);
    std::fill(backward_paths - Lanes::kCount, backward_paths - Lanes::kCount + 2 * path_stride, kMaxScore);
  }
  uchar* const tables = scratch(table_buffer, cameras * row_size);

  const int chunks = padded / Lanes::kCount;
  const int whole_chunks = disparities / Lanes::kCount;  // chunks without padding lanes
  // Only the chunks of the last byte vector can hold padding lanes: there, kMaxScore.
  Vec padding[kVectorsPerBytes];
  Acc first_lanes[Lanes::kCount];
  for (int lane = 0; lane < Lanes::kCount; ++lane) first_lanes[lane] = static_cast<Acc>(lane);
  const Vec lane_index = cv::v_load(first_lanes);
  // Reverse match: entry p of a row holds the best score so far of secondary pixel
  // x1 - 1 - min_d - p (reverse_sign +1) or x0 + min_d + p (-1), and its candidate index; candidate
  // j of reference pixel x is entry reverse_first(x) + j, so a pixel's candidates are contiguous.
  const int reverse_sign = frame.reverse_sign;
  const size_t reverse_size = reverse_sign ? static_cast<size_t>(region.x1 - region.x0 + padded) : 0;
  Acc* const reverse_scores = scratch(reverse_score_buffer, reverse_size);
  Acc* const reverse_indices = scratch(reverse_index_buffer, reverse_size);
  for (int chunk = whole_chunks; chunk < chunks; ++chunk) {
    Acc pad[Lanes::kCount];
    for (int lane = 0; lane < Lanes::kCount; ++lane) pad[lane] = chunk * Lanes::kCount + lane < disparities ? 0 : kMaxScore;
    padding[chunk - whole_chunks] = cv::v_load(pad);
  }

  const uchar* candidates[kMaxCameras];
  ptrdiff_t candidate_x_step[kMaxCameras];

  // Absolute differences of reference row yy against every candidate, into the ring slot of
  // row yy, updating the column sums by (entering row - leaving row).
  const auto enterRow = [&](int yy) {
    const int slot = (yy - (region.y0 - r)) % window;
    const uchar* reference_row = frame.reference.ptr<uchar>(yy + margin) + margin;
    for (int c = 0; c < cameras; ++c) {
      const CandidateSource& source = frame.sources[region.cameras[c]];
      const uchar* pixel_row = source.buffer.data + source.origin + yy * source.y_step;
      if (!source.tabulated()) {
        candidates[c] = pixel_row;
        candidate_x_step[c] = source.x_step;
        continue;
      }
      uchar* table = tables + c * row_size;
      const ptrdiff_t step = static_cast<ptrdiff_t>(source.buffer.step);
      for (int xe = 0; xe < nx; ++xe) {
        const uchar* pixel = pixel_row + (x0 - r + xe);
        uchar* entry = table + static_cast<size_t>(xe) * padded;
        for (int j = 0; j < padded; ++j) {
          const BilinearTap& tap = source.taps[j];
          const uchar* q = pixel + tap.dy * step + tap.dx;
          entry[j] = static_cast<uchar>(
              (tap.w00 * q[0] + tap.w01 * q[1] + tap.w10 * q[step] + tap.w11 * q[step + 1] + (1 << 15)) >> 16);
        }
      }
      candidates[c] = table - static_cast<ptrdiff_t>(x0 - r) * padded;
      candidate_x_step[c] = padded;
    }
    for (int g = 0; g < groups; ++g) {
      const int first = groups == 1 ? 0 : g, last = groups == 1 ? cameras : g + 1;
      // Locals, so that the compiler keeps them in registers across the stores below.
      const uchar* const first_candidates = candidates[first];
      const ptrdiff_t first_x_step = candidate_x_step[first];
      Acc* const ring_row = ring + (static_cast<size_t>(g) * window + slot) * row_size;
      Acc* const sums = column_sums + g * column_stride + padded;
      const int count = padded;
      for (int xe = 0; xe < nx; ++xe) {
        const int x = x0 - r + xe;
        const cv::v_uint8x16 reference = cv::v_setall_u8(reference_row[x]);
        const uchar* const own_candidates = first_candidates + x * first_x_step;
        Acc* const slot_entry = ring_row + static_cast<size_t>(xe) * count;
        Acc* const sum_entry = sums + static_cast<size_t>(xe) * count;
        for (int b = 0; b < count; b += kByteLanes) {
          Vec entering[kVectorsPerBytes];
          Lanes::widen(cv::v_absdiff(reference, cv::v_load(own_candidates + b)), entering);
          for (int c = first + 1; c < last; ++c) {
            Vec more[kVectorsPerBytes];
            Lanes::widen(cv::v_absdiff(reference, cv::v_load(candidates[c] + x * candidate_x_step[c] + b)), more);
            for (int i = 0; i < kVectorsPerBytes; ++i) entering[i] = Lanes::add(entering[i], more[i]);
          }
          for (int i = 0; i < kVectorsPerBytes; ++i) {
            Acc* const ring_lanes = slot_entry + b + i * Lanes::kCount;
            Acc* const sum_lanes = sum_entry + b + i * Lanes::kCount;
            const Vec leaving = cv::v_load(ring_lanes);
            cv::v_store(ring_lanes, entering[i]);
            cv::v_store(sum_lanes, Lanes::slide(cv::v_load(sum_lanes), entering[i], leaving));
          }
        }
      }
    }
  };

  // Winner-takes-all over the scores `curve` of reference pixel x of row y (kept lanes of the padded
  // candidates), the sum of scores, the runner-up, and the reverse match's best-so-far entries.
  const bool subpixel = frame.subpixel, second_best = frame.second_best, sum_scores = frame.sum_scores;
  const int min_disparity = frame.min_disparity;
  const int chunk_count = chunks, unpadded_chunks = whole_chunks;
  // `descending`: the pixels of the row come in order of decreasing x.
  const auto decide = [&](int y, int x, const Acc* curve, bool descending) __attribute__((always_inline)) {
    const int reverse_first = reverse_sign > 0 ? region.x1 - 1 - x : x - region.x0;
    Vec candidate_index = lane_index;
    Vec best = Lanes::all(kMaxScore);
    cv::v_int32x4 score_sum = cv::v_setall_s32(0);
    for (int chunk = 0; chunk < chunk_count; ++chunk) {
      const int b = chunk * Lanes::kCount;
      Vec score = cv::v_load(curve + b);
      if (chunk >= unpadded_chunks) {
        // Scores are never negative: OR with the all-ones-but-sign padding makes those lanes
        // the largest score, AND with its complement makes them zero.
        const Vec& pad = padding[chunk - unpadded_chunks];
        if (sum_scores) score_sum += Lanes::widenSum(score & ~pad);
        score = score | pad;
      } else if (sum_scores) {
        score_sum += Lanes::widenSum(score);
      }
      best = cv::v_min(best, score);
      if (reverse_sign) {
        // With x increasing, candidates reach a secondary pixel in order of increasing disparity
        // for sign +1, so a strict < keeps the smallest of tied ones; for -1, or x decreasing, <=.
        Acc* const entry_scores = reverse_scores + reverse_first + b;
        Acc* const entry_indices = reverse_indices + reverse_first + b;
        const Vec previous = cv::v_load(entry_scores);
        const Vec better = (reverse_sign > 0) != descending ? score < previous : score <= previous;
        cv::v_store(entry_scores, cv::v_min(previous, score));
        cv::v_store(entry_indices, cv::v_select(better, candidate_index, cv::v_load(entry_indices)));
        candidate_index = Lanes::add(candidate_index, Lanes::all(Lanes::kCount));
      }
    }
    // The lowest score, then the first (smallest) disparity that has it: the lanes equal to it
    // as a bit mask, 64 candidates at a time, without data-dependent branches inside a block.
    const Acc best_score = static_cast<Acc>(cv::v_reduce_min(best));
    const int j = firstLaneEqual<Lanes>(curve, chunk_count, Lanes::all(best_score));
    float disparity = static_cast<float>(min_disparity + j);
    if (subpixel && j > 0 && j < disparities - 1) {
      const double before = curve[j - 1], after = curve[j + 1];
      const double curvature = before + after - 2.0 * best_score;
      if (curvature > 0) disparity += static_cast<float>(0.5 * (before - after) / curvature);
    }
    out.disparity(y, x) = disparity;
    out.best_score(y, x) = static_cast<int>(best_score);
    out.score_sum(y, x) = cv::v_reduce_sum(score_sum);
    if (second_best) {
      // The lowest score with the best and its two neighbours (and the padding) masked out;
      // only the chunks holding those neighbours need the mask.
      const int near_first = std::max(j - 1, 0) / Lanes::kCount, near_last = (j + 1) / Lanes::kCount;
      const Vec low = Lanes::all(j - 1), high = Lanes::all(j + 1), highest = Lanes::all(kMaxScore);
      Vec runner_up = highest;
      for (int chunk = 0; chunk < chunk_count; ++chunk) {
        Vec score = cv::v_load(curve + chunk * Lanes::kCount);
        if (chunk >= unpadded_chunks) score = score | padding[chunk - unpadded_chunks];
        if (chunk >= near_first && chunk <= near_last) {
          const Vec index = Lanes::add(lane_index, Lanes::all(chunk * Lanes::kCount));
          score = cv::v_select((index >= low) & (index <= high), highest, score);
        }
        runner_up = cv::v_min(runner_up, score);
      }
      const Acc second = static_cast<Acc>(cv::v_reduce_min(runner_up));
      out.second_score(y, x) = second == kMaxScore ? std::numeric_limits<int>::max() : static_cast<int>(second);
    }
  };

  // Scanline optimisation: the cost of a path reaching pixel x at candidate d from its neighbour
  // `previous` along the row is cost(d) + min(previous(d), previous(d +- 1) + p1, min previous + p2)
  // - min previous (Hirschmuller 2008, eq. 13; subtracting the minimum keeps it bounded by the
  // largest score + p2). `previous` has one guard lane before and after its candidates.
  const bool scanline = frame.scanline;
  const int scale = window * window * (groups == 1 ? cameras : kept);
  const Vec small_jump = Lanes::all(static_cast<int>(std::lround(frame.scanline_p1 * scale)));
  const Vec large_jump = Lanes::all(static_cast<int>(std::lround(frame.scanline_p2 * scale)));
  // Padding lanes of a path hold the largest score, so that no real candidate is reached through
  // them. Their sums may wrap to negative values, which the OR with `padding` alone would keep
  // negative: `real_lanes` (all ones in the lanes of real candidates) clears them first.
  Vec real_lanes[kVectorsPerBytes];
  for (int k = 0; k < chunk_count - unpadded_chunks; ++k) real_lanes[k] = padding[k] == Lanes::all(0);
  const auto padded_lanes = [&](const Vec& value, int chunk) {
    if (chunk < unpadded_chunks) return value;
    const Vec& pad = padding[chunk - unpadded_chunks];
    return (value & real_lanes[chunk - unpadded_chunks]) | pad;
  };
  // Writes the path reaching a pixel of scores `cost` from its neighbour's path `previous`, whose
  // lowest entry is `lowest` (none for the first pixel), and returns the new path's lowest entry.
  const auto followPath = [&](const Acc* cost, const Acc* previous, Acc lowest, Acc* path) {
    const Vec lowest_all = Lanes::all(lowest);
    const Vec jump_floor = Lanes::add(lowest_all, large_jump);
    Vec new_lowest = Lanes::all(kMaxScore);
    for (int chunk = 0; chunk < chunk_count; ++chunk) {
      const int b = chunk * Lanes::kCount;
      Vec value = cv::v_load(cost + b);
      if (previous) {
        const Vec neighbours = cv::v_min(cv::v_load(previous + b - 1), cv::v_load(previous + b + 1));
        const Vec reach = cv::v_min(cv::v_min(cv::v_load(previous + b), Lanes::add(neighbours, small_jump)), jump_floor);
        value = Lanes::add(value, Lanes::subtract(reach, lowest_all));
      }
      value = padded_lanes(value, chunk);
      new_lowest = cv::v_min(new_lowest, value);
      cv::v_store(path + b, value);
    }
    return static_cast<Acc>(cv::v_reduce_min(new_lowest));
  };

  // Horizontal running sum of the column sums gives every candidate's window score of each pixel
  // of row y; the winner is taken at once, or after the scanline paths over the whole row.
  const auto matchRow = [&](int y, auto combine_groups) {
    constexpr bool kCombine = decltype(combine_groups)::value;
    for (int g = 0; g < groups; ++g) {
      // The window of the first pixel minus its last column, which the first slide brings in.
      const Acc* sums = column_sums + g * column_stride;
      for (int b = 0; b < padded; b += Lanes::kCount) {
        Vec total = Lanes::all(0);
        for (int xe = 0; xe < window - 1; ++xe) {
          total = Lanes::add(total, cv::v_load(sums + static_cast<size_t>(xe + 1) * padded + b));
        }
        cv::v_store(scores + g * padded + b, total);
      }
    }
    // Locals, so that the compiler keeps them in registers across the stores below.
    Acc* const group_scores = scores;
    const Acc* const all_sums = column_sums;
    const size_t stride = column_stride;
    const int count = padded;
    Vec sorted[kMaxCameras];
    Acc forward_lowest = 0;
    if (reverse_sign) std::fill(reverse_scores, reverse_scores + reverse_size, kMaxScore);
    for (int x = region.x0; x < region.x1; ++x) {
      // Columns entering and leaving the window, relative to each group's column sums.
      const size_t entering = static_cast<size_t>(x - x0 + 2 * r + 1) * count;
      const size_t leaving = static_cast<size_t>(x - x0) * count;
      // The pixel's combined scores: in the group scores themselves for one group, else in a
      // buffer of their own; for the scanline, in the row's costs.
      Acc* const pixel_costs = scanline ? row_costs + static_cast<size_t>(x - region.x0) * count
                                        : (kCombine ? combined : group_scores);
      for (int chunk = 0; chunk < chunk_count; ++chunk) {
        const int b = chunk * Lanes::kCount;
        if constexpr (!kCombine) {
          const Vec value = Lanes::slide(cv::v_load(group_scores + b), cv::v_load(all_sums + b + entering),
                                         cv::v_load(all_sums + b + leaving));
          cv::v_store(group_scores + b, value);
          if (scanline) cv::v_store(pixel_costs + b, value);
        } else {
          for (int g = 0; g < groups; ++g) {
            Acc* const group_score = group_scores + g * count + b;
            const Acc* const sums = all_sums + g * stride + b;
            Vec value = Lanes::slide(cv::v_load(group_score), cv::v_load(sums + entering), cv::v_load(sums + leaving));
            cv::v_store(group_score, value);
            // Insert into the `kept` lowest so far (a min/max insertion network).
            for (int k = 0; k < std::min(g, kept); ++k) {
              const Vec low = cv::v_min(sorted[k], value);
              value = cv::v_max(sorted[k], value);
              sorted[k] = low;
            }
            if (g < kept) sorted[g] = value;
          }
          Vec score = sorted[0];
          for (int k = 1; k < kept; ++k) score = Lanes::add(score, sorted[k]);
          cv::v_store(pixel_costs + b, score);
        }
      }
      if (!scanline) {
        decide(y, x, pixel_costs, false);
      } else {
        // The path from the left, in the same sweep as the window scores.
        const size_t i = static_cast<size_t>(x - region.x0);
        forward_lowest = followPath(pixel_costs, i == 0 ? nullptr : forward_paths + (i - 1) * path_stride,
                                    forward_lowest, forward_paths + i * path_stride);
      }
    }
    if (!scanline) return;
    // The path from the right, added to the one from the left, gives the aggregated scores; the
    // winner is taken in the same sweep.
    Acc backward_lowest = 0;
    for (int x = region.x1 - 1; x >= region.x0; --x) {
      const size_t i = static_cast<size_t>(x - region.x0);
      const bool first = x == region.x1 - 1;
      Acc* const path = backward_paths + (i % 2) * path_stride;
      const Acc* const previous = first ? nullptr : backward_paths + ((i + 1) % 2) * path_stride;
      backward_lowest = followPath(row_costs + i * padded, previous, backward_lowest, path);
      const Acc* const forward = forward_paths + i * path_stride;
      for (int chunk = 0; chunk < chunk_count; ++chunk) {
        const int b = chunk * Lanes::kCount;
        const Vec sum = Lanes::add(cv::v_load(forward + b), cv::v_load(path + b));
        // Padding lanes (the largest score twice, wrapped) become zero; decide() pads them again.
        cv::v_store(combined + b, chunk < unpadded_chunks ? sum : sum & real_lanes[chunk - unpadded_chunks]);
      }
      decide(y, x, combined, true);
    }
  };

  const auto writeReverse = [&](int y) {
    if (!reverse_sign) return;
    float* reverse_row = out.reverse_disparity.ptr<float>(y);
    const int width = out.reverse_disparity.cols;
    for (size_t p = 0; p < reverse_size; ++p) {
      const int pixel = reverse_sign > 0 ? region.x1 - 1 - min_disparity - static_cast<int>(p)
                                         : region.x0 + min_disparity + static_cast<int>(p);
      if (pixel < 0 || pixel >= width || reverse_scores[p] == kMaxScore) continue;
      reverse_row[pixel] = static_cast<float>(min_disparity + reverse_indices[p]);
    }
  };

  for (int yy = region.y0 - r; yy < region.y0 + r; ++yy) enterRow(yy);
  for (int y = region.y0; y < region.y1; ++y) {
    enterRow(y + r);
    if (groups == 1) {
      matchRow(y, std::false_type{});
    } else {
      matchRow(y, std::true_type{});
    }
    writeReverse(y);
  }
}

}  // namespace

struct SadMatcher::Workspace {
  PreparedFrame prepared;
  SadMatch result;
};

namespace {

// The prefiltered, border-padded reference and the candidate sources of every secondary view.
void prepareFrame(const StereoFrame& frame, const StereoOptions& options, PreparedFrame& prepared) {
  prepared.radius = options.window / 2;
  prepared.min_disparity = options.min_disparity;
  prepared.disparities = options.disparityCount();
  prepared.padded_disparities = roundUp(prepared.disparities, kByteLanes);
  prepared.margin = prepared.radius + prepared.padded_disparities + 2;
  prepared.best_half = options.combination == CameraCombination::kBestHalf;
  prepared.subpixel = options.subpixel;
  prepared.second_best = options.second_best_ratio < 1.0;
  prepared.sum_scores = options.uniqueness_threshold < 1.0;
  prepared.scanline = options.aggregation == CostAggregation::kScanline;
  prepared.scanline_p1 = options.scanline_p1;
  prepared.scanline_p2 = options.scanline_p2;
  const auto prefilter = [&](const cv::Mat1b& image, cv::Mat1b& filtered) {
    prefilterImage(image, options.prefilter, options.prefilter_cap, options.texture_sigma, filtered);
  };
  prefilter(frame.reference, prepared.filtered_reference);
  cv::copyMakeBorder(prepared.filtered_reference, prepared.reference, prepared.margin, prepared.margin,
                     prepared.margin, prepared.margin, cv::BORDER_REPLICATE);
  prepared.sources.resize(frame.secondaries.size());
  for (size_t c = 0; c < frame.secondaries.size(); ++c) {
    CandidateSource& source = prepared.sources[c];
    prefilter(frame.secondaries[c].image, source.filtered);
    prepareCandidateSource(source.filtered, frame.secondaries[c].camera, prepared, source);
  }
}

// Every output image at its starting value; the left-right check's and the runner-up's images only
// when they are asked for (a binocular horizontal rig for the one-pass left-right check).
void resetResult(int height, int width, const StereoOptions& options, PreparedFrame& prepared, SadMatch& match) {
  match.disparity.create(height, width);
  match.disparity.setTo(kInvalidDisparity);
  match.best_score.create(height, width);
  match.best_score.setTo(0);
  match.score_sum.create(height, width);
  match.score_sum.setTo(0);
  const CandidateSource& first_source = prepared.sources.front();
  prepared.reverse_sign = options.left_right_check && prepared.sources.size() == 1 && first_source.step_y == 0
                              ? first_source.step_x
                              : 0;
  if (prepared.reverse_sign) {
    match.reverse_disparity.create(height, width);
    match.reverse_disparity.setTo(kInvalidDisparity);
  } else {
    match.reverse_disparity.release();
  }
  if (prepared.second_best) {
    match.second_score.create(height, width);
    match.second_score.setTo(std::numeric_limits<int>::max());
  } else {
    match.second_score.release();
  }
}

}  // namespace

SadMatcher::SadMatcher(const StereoOptions& options) : options_(options), workspace_(std::make_unique<Workspace>()) {
  validateStereoOptions(options_);
}

SadMatcher::~SadMatcher() = default;

const SadMatch& SadMatcher::match(const StereoFrame& frame) {
  checkStereoFrame(frame);
  if (frame.secondaries.size() > kMaxCameras) {
    throw std::invalid_argument("stereo frame: at most " + std::to_string(kMaxCameras) + " secondary views");
  }
  const StereoOptions& options = options_;
  PreparedFrame& prepared = workspace_->prepared;
  prepareFrame(frame, options, prepared);
  SadMatch& match = workspace_->result;
  resetResult(frame.reference.rows, frame.reference.cols, options, prepared, match);

  const int height = frame.reference.rows;
  const std::vector<MatchRegion> regions = matchRegions(frame, options.min_disparity, options.max_disparity);
  const long long largest_score = static_cast<long long>(options.window) * options.window *
                                  maxPrefilteredDifference(options.prefilter, options.prefilter_cap) *
                                  static_cast<long long>(frame.secondaries.size());
  // With the scanline, a score is the sum of two paths, each at most the largest window score plus
  // the large-jump cost.
  const long long largest_total =
      options.aggregation == CostAggregation::kScanline
          ? 2 * (largest_score + static_cast<long long>(std::ceil(options.scanline_p2 * options.window *
                                                                    options.window * frame.secondaries.size())))
          : largest_score;
  const bool narrow = largest_total <= std::numeric_limits<int16_t>::max();
  const int stripes = std::min(options.threads, height);
  const auto matchStripes = [&](const cv::Range& range) {
    for (int stripe = range.start; stripe < range.end; ++stripe) {
      const int top = height * stripe / stripes, bottom = height * (stripe + 1) / stripes;
      for (MatchRegion region : regions) {
        region.y0 = std::max(region.y0, top);
        region.y1 = std::min(region.y1, bottom);
        if (region.y0 >= region.y1) continue;
        if (narrow) {
          matchRegion<int16_t>(prepared, region, match);
        } else {
          matchRegion<int32_t>(prepared, region, match);
        }
      }
    }
  };
  if (stripes == 1) {
    matchStripes(cv::Range(0, 1));
  } else {
    cv::parallel_for_(cv::Range(0, stripes), matchStripes, stripes);
  }
  return match;
}

}  // namespace stereonav
