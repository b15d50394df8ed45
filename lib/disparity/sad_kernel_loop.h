// The matching loop of SadMatcher (see sad_matcher.cc for the method), written once with OpenCV's
// universal intrinsics at the widest vector width of the including translation unit. Each of
// sad_kernel_sse2.cc and sad_kernel_avx2.cc includes opencv2/core/hal/intrin.hpp configured for
// its instruction set, defines STEREONAV_SAD_KERNEL_NAMESPACE (the code of each build must have
// names of its own) and then includes this file.

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

#include "disparity/disparity_image.h"
#include "disparity/sad_kernel.h"

#ifndef STEREONAV_SAD_KERNEL_NAMESPACE
#error "define STEREONAV_SAD_KERNEL_NAMESPACE before including sad_kernel_loop.h"
#endif

namespace stereonav {
namespace STEREONAV_SAD_KERNEL_NAMESPACE {

constexpr int kByteLanes = cv::v_uint8::nlanes;  // candidates compared per 8-bit vector

// The vector type that accumulates scores: 16-bit when the largest possible window score fits in
// an int16 (SSE2 and AVX2 compare and take minima of signed 16-bit lanes natively), 32-bit
// otherwise. Vectors are the widest the translation unit was built for (cv::v_int16 is 8 lanes
// with SSE2, 16 with AVX2).
template <typename Acc>
struct AccumulatorLanes;

template <>
struct AccumulatorLanes<int16_t> {
  using Vec = cv::v_int16;
  static constexpr int kCount = Vec::nlanes;
  static void widen(const cv::v_uint8& bytes, Vec* out) {
    cv::v_uint16 low, high;
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
  static cv::v_int32 widenSum(const Vec& v) { return cv::v_dotprod(v, cv::vx_setall_s16(1)); }
  static Vec all(int value) { return cv::vx_setall_s16(static_cast<short>(value)); }
  // Sign bits of a's lanes then b's (lanes of comparison masks are 0 or -1).
  static uint64_t packedSignMask(const Vec& a, const Vec& b) {
    return static_cast<unsigned>(cv::v_signmask(cv::v_pack(a, b)));
  }
};

// The sum of each group of 8 bytes of `v` in a 64-bit lane (psadbw against zero), as 32-bit lanes.
CV_ALWAYS_INLINE cv::v_int32x4 byteGroupSums(const cv::v_uint8x16& v) {
  return cv::v_int32x4(_mm_sad_epu8(v.val, _mm_setzero_si128()));
}
#if CV_SIMD256
CV_ALWAYS_INLINE cv::v_int32x8 byteGroupSums(const cv::v_uint8x32& v) {
  return cv::v_int32x8(_mm256_sad_epu8(v.val, _mm256_setzero_si256()));
}
#endif

// (a + b + 1) >> 1 per byte (pavgb; OpenCV 4.6's universal intrinsics have no average).
CV_ALWAYS_INLINE cv::v_uint8x16 roundedAverage(const cv::v_uint8x16& a, const cv::v_uint8x16& b) {
  return cv::v_uint8x16(_mm_avg_epu8(a.val, b.val));
}
#if CV_SIMD256
CV_ALWAYS_INLINE cv::v_uint8x32 roundedAverage(const cv::v_uint8x32& a, const cv::v_uint8x32& b) {
  return cv::v_uint8x32(_mm256_avg_epu8(a.val, b.val));
}
#endif

// Scanline paths in bytes (PreparedFrame::path_shift): twice the candidates of 16-bit lanes per
// instruction. OpenCV's 8-bit + and - saturate, so a path that reaches 255 stays there instead of
// wrapping; the window scores are scaled so that only candidates far worse than any match the
// validation keeps saturate (scanlinePathShift).
template <>
struct AccumulatorLanes<uint8_t> {
  using Vec = cv::v_uint8;
  static constexpr int kCount = Vec::nlanes;
  static Vec add(const Vec& a, const Vec& b) { return a + b; }
  static Vec subtract(const Vec& a, const Vec& b) { return a - b; }
  static cv::v_int32 widenSum(const Vec& v) { return byteGroupSums(v); }
  static Vec all(int value) { return cv::vx_setall_u8(static_cast<uchar>(value)); }
  static uint64_t packedSignMask(const Vec& a, const Vec& b) {
    return static_cast<uint32_t>(cv::v_signmask(a)) |
           static_cast<uint64_t>(static_cast<uint32_t>(cv::v_signmask(b))) << kCount;
  }
};

template <>
struct AccumulatorLanes<int32_t> {
  using Vec = cv::v_int32;
  static constexpr int kCount = Vec::nlanes;
  static void widen(const cv::v_uint8& bytes, Vec* out) {
    cv::v_uint16 low, high;
    cv::v_expand(bytes, low, high);
    cv::v_uint32 parts[4];
    cv::v_expand(low, parts[0], parts[1]);
    cv::v_expand(high, parts[2], parts[3]);
    for (int i = 0; i < 4; ++i) out[i] = cv::v_reinterpret_as_s32(parts[i]);
  }
  static Vec add(const Vec& a, const Vec& b) { return a + b; }
  static Vec subtract(const Vec& a, const Vec& b) { return a - b; }
  static Vec slide(const Vec& sum, const Vec& entering, const Vec& leaving) { return sum + entering - leaving; }
  static cv::v_int32 widenSum(const Vec& v) { return v; }
  static Vec all(int value) { return cv::vx_setall_s32(value); }
  static uint64_t packedSignMask(const Vec& a, const Vec& b) {
    return static_cast<unsigned>(cv::v_signmask(cv::v_pack(a, b)));
  }
};

// The smallest lane of `v`, in every lane.
CV_ALWAYS_INLINE cv::v_int16x8 minInEveryLane(const cv::v_int16x8& v) { return cv::v_setall_s16(cv::v_reduce_min(v)); }
CV_ALWAYS_INLINE cv::v_int32x4 minInEveryLane(const cv::v_int32x4& v) { return cv::v_setall_s32(cv::v_reduce_min(v)); }
CV_ALWAYS_INLINE cv::v_uint8x16 minInEveryLane(const cv::v_uint8x16& v) { return cv::v_setall_u8(cv::v_reduce_min(v)); }
#if CV_SIMD256
CV_ALWAYS_INLINE cv::v_uint8x32 minInEveryLane(const cv::v_uint8x32& v) {
  // The byte minimum of each 16-bit lane, zero-extended, then phminposuw over the 8 lanes.
  const __m128i half = _mm_min_epu8(_mm256_castsi256_si128(v.val), _mm256_extracti128_si256(v.val, 1));
  const __m128i words = _mm_min_epu16(_mm_and_si128(half, _mm_set1_epi16(0xFF)), _mm_srli_epi16(half, 8));
  return cv::v_uint8x32(_mm256_broadcastb_epi8(_mm_minpos_epu16(words)));
}
CV_ALWAYS_INLINE cv::v_int16x16 minInEveryLane(const cv::v_int16x16& v) {
  // The lanes it is used on (scores and paths) are never negative, so their unsigned minimum is
  // the minimum, which phminposuw finds among 8 lanes in one instruction.
  const __m128i half = _mm_min_epu16(_mm256_castsi256_si128(v.val), _mm256_extracti128_si256(v.val, 1));
  return cv::v_int16x16(_mm256_broadcastw_epi16(_mm_minpos_epu16(half)));
}
CV_ALWAYS_INLINE cv::v_int32x8 minInEveryLane(const cv::v_int32x8& v) {
  return cv::v256_setall_s32(cv::v_reduce_min(v));
}
#endif

// Grows `buffer` if needed (buffers are reused from call to call: frames of one size need no new
// memory) and returns `size` elements of it that start on a cache line: the loop reads and writes
// whole vectors at whole-vector offsets, and a 32-byte vector on a 16-byte boundary (all that
// std::vector promises) straddles two lines every other time, which costs AVX2 more than it saves.
template <typename T>
T* scratch(std::vector<T>& buffer, size_t size) {
  constexpr size_t kLine = 64;
  constexpr size_t kSlack = kLine / sizeof(T);
  if (buffer.size() < size + kSlack) buffer.resize(size + kSlack);
  void* start = buffer.data();
  size_t space = buffer.size() * sizeof(T);
  return static_cast<T*>(std::align(kLine, size * sizeof(T), start, space));
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
      const typename Lanes::Vec a = cv::vx_load(first) == wanted;
      const typename Lanes::Vec b = chunk + 1 < block_chunks ? cv::vx_load(first + Lanes::kCount) == wanted : Lanes::all(0);
      hits |= Lanes::packedSignMask(a, b) << (chunk * Lanes::kCount);
    }
    if (hits) return block * Lanes::kCount + __builtin_ctzll(hits);
  }
  return 0;
}

// Birchfield and Tomasi's sampling interval along a row of an arranged image whose interior is
// [margin, margin + width) and whose margins replicate the border (as samplingInterval in
// sad_matcher.cc, then padded): each interior pixel's lowest and highest of its value and the
// values halfway (rounded up: pavgb) to its two neighbours; each margin pixel's, its nearest
// border pixel's.
inline void samplingIntervalRow(const uchar* row, int width, int margin, uchar* low, uchar* high) {
  const int end = margin + width;
  int i = margin;
  for (; i + kByteLanes <= end; i += kByteLanes) {
    const cv::v_uint8 value = cv::vx_load(row + i);
    const cv::v_uint8 half_before = roundedAverage(value, cv::vx_load(row + i - 1));
    const cv::v_uint8 half_after = roundedAverage(value, cv::vx_load(row + i + 1));
    cv::v_store(low + i, cv::v_min(value, cv::v_min(half_before, half_after)));
    cv::v_store(high + i, cv::v_max(value, cv::v_max(half_before, half_after)));
  }
  for (; i < end; ++i) {
    const int value = row[i];
    const int half_before = (value + row[i - 1] + 1) >> 1, half_after = (value + row[i + 1] + 1) >> 1;
    low[i] = static_cast<uchar>(std::min({value, half_before, half_after}));
    high[i] = static_cast<uchar>(std::max({value, half_before, half_after}));
  }
  std::fill(low, low + margin, low[margin]);
  std::fill(high, high + margin, high[margin]);
  std::fill(low + end, low + end + margin, low[end - 1]);
  std::fill(high + end, high + end + margin, high[end - 1]);
}

template <typename Acc, bool kPathsFromAbove, bool kBytePaths>
void matchRegion(const PreparedFrame& frame, const MatchRegion& region, SadMatch& out) {
  static_assert(!kBytePaths || (std::is_same_v<Acc, int16_t> && !kPathsFromAbove),
                "byte paths take 16-bit window scores, and only the two horizontal paths");
  using Lanes = AccumulatorLanes<Acc>;
  using Vec = typename Lanes::Vec;
  // What the winner is taken from: the window scores, or the scanline's paths and their sums, which
  // are bytes with kBytePaths.
  using PathAcc = std::conditional_t<kBytePaths, uint8_t, Acc>;
  using PathLanes = AccumulatorLanes<PathAcc>;
  using PathVec = typename PathLanes::Vec;
  constexpr int kVectorsPerBytes = kByteLanes / Lanes::kCount;
  constexpr int kPathVectorsPerBytes = kByteLanes / PathLanes::kCount;
  constexpr PathAcc kMaxScore = std::numeric_limits<PathAcc>::max();

  const int r = frame.radius, window = 2 * r + 1, margin = frame.margin;
  const int disparities = frame.disparities, padded = frame.padded_disparities;
  const int x0 = region.x0, nx = region.x1 - region.x0 + 2 * r;
  const size_t row_size = static_cast<size_t>(nx) * padded;
  const int cameras = static_cast<int>(region.cameras.size());
  // Sum mode: one group of all cameras. Best-half: each camera its own group, and the
  // ceil(N/2) lowest group scores are added per candidate.
  const int groups = frame.best_half && cameras > 1 ? cameras : 1;
  const int kept = groups == 1 ? 1 : (cameras + 1) / 2;

  thread_local std::vector<Acc> column_sum_buffer, score_buffer, combined_buffer;
  thread_local std::vector<uchar> ring_buffer, table_buffer;
  thread_local std::vector<PathAcc> reverse_score_buffer, reverse_index_buffer;
  thread_local std::vector<PathAcc> row_cost_buffer, forward_path_buffer, backward_path_buffer, path_sum_buffer;
  // The ring keeps each row's costs until they leave the window: as bytes when a group's costs
  // add up within a byte (x-Sobel and up to four cameras, or any single camera), which halves
  // its memory traffic, else as scores.
  const bool byte_costs = (groups == 1 ? cameras : 1) * frame.max_difference <= 255;
  const size_t ring_size = groups * window * row_size * (byte_costs ? 1 : sizeof(Acc));
  uchar* const ring = scratch(ring_buffer, ring_size);
  std::fill(ring, ring + ring_size, uchar{0});  // nothing leaves before the first rows
  // Column xe of group g is at column_sums + g * column_stride + (xe + 1) * padded; column -1 stays
  // zero, so the first pixel of a row slides its window in like every other one.
  const size_t column_stride = row_size + padded;
  Acc* const column_sums = scratch(column_sum_buffer, groups * column_stride);
  std::fill(column_sums, column_sums + groups * column_stride, Acc{0});
  Acc* const scores = scratch(score_buffer, static_cast<size_t>(groups) * padded);
  Acc* const combined = scratch(combined_buffer, padded);
  // Scanline: the scores of every pixel of a row, the paths from the left, the last two of the
  // path from the right, and the sum of the paths at one pixel.
  const size_t row_pixels = frame.scanline ? static_cast<size_t>(region.x1 - region.x0) : 0;
  const size_t path_stride = static_cast<size_t>(padded);
  PathAcc* const row_costs = scratch(row_cost_buffer, row_pixels * padded);
  PathAcc* const forward_paths = scratch(forward_path_buffer, row_pixels * path_stride);
  PathAcc* const backward_paths = scratch(backward_path_buffer, 2 * path_stride);
  PathAcc* const path_sums = scratch(path_sum_buffer, path_stride);
  // A tabulated camera's candidates in each channel: those of the images the pixel cost reads.
  const int channels = static_cast<int>(frame.reference.size());
  const bool candidate_values = frame.candidateValues(), candidate_intervals = frame.candidateIntervals();
  const bool reference_intervals = frame.referenceIntervals();
  const int images_per_channel = (candidate_values ? 1 : 0) + (candidate_intervals ? 2 : 0);
  const int images_per_camera = channels * images_per_channel;
  uchar* const tables = scratch(table_buffer, images_per_camera * cameras * row_size);
  // Cameras whose candidates' sampling intervals are taken row by row: each row's, per channel.
  thread_local std::vector<uchar> interval_row_buffer;
  size_t interval_row_size = 0;
  for (int camera : region.cameras) {
    const CandidateSource& source = frame.sources[camera];
    if (source.row_intervals) interval_row_size = std::max(interval_row_size, source.channels.front().values.buffer.step[0]);
  }
  uchar* const interval_rows = scratch(interval_row_buffer, 2 * channels * cameras * interval_row_size);
  // Semi-global: the paths that come down from the row above (from the upper left, above and the
  // upper right) to every pixel of this row and of the previous one, and each path's lowest entry.
  constexpr int kDirectionsFromAbove = 3;
  const size_t above_pixels = kPathsFromAbove ? row_pixels : 0;
  thread_local std::vector<PathAcc> above_path_buffer, above_lowest_buffer;
  PathAcc* const above_paths = scratch(above_path_buffer, 2 * kDirectionsFromAbove * above_pixels * path_stride);
  PathAcc* const above_lowest = scratch(above_lowest_buffer, 2 * kDirectionsFromAbove * above_pixels);
  // Index of pixel i's path from `direction` (0: upper left, 1: above, 2: upper right) in row y.
  const auto aboveIndex = [&](int y, int direction, size_t i) {
    return (static_cast<size_t>(y % 2) * kDirectionsFromAbove + direction) * above_pixels + i;
  };

  const int score_chunks = padded / Lanes::kCount;
  // Chunks of what the winner is taken from; the first whole_chunks hold no padding lanes.
  const int chunks = padded / PathLanes::kCount;
  const int whole_chunks = disparities / PathLanes::kCount;
  // Only the chunks of the last byte vector can hold padding lanes: there, kMaxScore.
  PathVec padding[kPathVectorsPerBytes];
  PathAcc first_lanes[PathLanes::kCount];
  for (int lane = 0; lane < PathLanes::kCount; ++lane) first_lanes[lane] = static_cast<PathAcc>(lane);
  const PathVec lane_index = cv::vx_load(first_lanes), one = PathLanes::all(1);
  // Reverse match: entry p of a row holds the best score so far of secondary pixel
  // x1 - 1 - min_d - p (reverse_sign +1) or x0 + min_d + p (-1), and its candidate index; candidate
  // j of reference pixel x is entry reverse_first(x) + j, so a pixel's candidates are contiguous.
  const int reverse_sign = frame.reverse_sign;
  const size_t reverse_size = reverse_sign ? static_cast<size_t>(region.x1 - region.x0 + padded) : 0;
  PathAcc* const reverse_scores = scratch(reverse_score_buffer, reverse_size);
  PathAcc* const reverse_indices = scratch(reverse_index_buffer, reverse_size);
  for (int chunk = whole_chunks; chunk < chunks; ++chunk) {
    PathAcc pad[PathLanes::kCount];
    for (int lane = 0; lane < PathLanes::kCount; ++lane) {
      pad[lane] = chunk * PathLanes::kCount + lane < disparities ? 0 : kMaxScore;
    }
    padding[chunk - whole_chunks] = cv::vx_load(pad);
  }

  // Per camera and channel: where row yy's candidates start and (per camera) the step from pixel to
  // pixel; for Birchfield-Tomasi also the candidates' sampling intervals (same addresses in their
  // images) and, symmetric, the reference's along that camera's baseline. The reference's row per
  // channel.
  const uchar* reference_rows[kMaxChannels];
  const uchar* candidates[kMaxCameras][kMaxChannels];
  const uchar* candidate_lows[kMaxCameras][kMaxChannels];
  const uchar* candidate_highs[kMaxCameras][kMaxChannels];
  ptrdiff_t candidate_x_step[kMaxCameras];
  const uchar* reference_low_rows[kMaxCameras][kMaxChannels];
  const uchar* reference_high_rows[kMaxCameras][kMaxChannels];

  // The candidates of a tabulated camera along row yy, sampled from `image` (arranged as the
  // camera's values), into `table`; returns where pixel 0's candidates would be.
  const auto tabulate = [&](const CandidateSource& source, const cv::Mat1b& image, int yy, uchar* table) {
    const uchar* pixel_row = image.data + source.origin + yy * source.y_step;
    const ptrdiff_t step = static_cast<ptrdiff_t>(image.step);
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
    return table - static_cast<ptrdiff_t>(x0 - r) * padded;
  };

  // The pixel costs of reference row yy against every candidate, into the ring slot of the row,
  // updating the column sums by (entering row - leaving row).
  // A group of one or two cameras whose costs fit a byte (a binocular or L-shaped rig, each camera
  // of best-half, unless raw grey levels and the intensity term add up past 255) compiles to a
  // loop that holds the cameras' pointers in locals and has none of the other cameras' machinery
  // (kHeldCameras; 0: any group).
  const auto enterGroups = [&](int slot, auto cost_tag, auto intensity_tag, auto held_cameras_tag) {
    constexpr int kHeldCameras = decltype(held_cameras_tag)::value;
    constexpr int kLocalCameras = kHeldCameras == 0 ? 1 : kHeldCameras;
    constexpr PixelCost kCost = decltype(cost_tag)::value;
    constexpr bool kCandidateValues = readsCandidateValues(kCost);
    constexpr bool kCandidateIntervals = readsCandidateIntervals(kCost);
    constexpr bool kReferenceIntervals = readsReferenceIntervals(kCost);
    constexpr int kChannels = decltype(intensity_tag)::value ? 2 : 1;
    for (int g = 0; g < groups; ++g) {
      const int first = groups == 1 ? 0 : g, last = groups == 1 ? cameras : g + 1;
      // The group's first cameras' pointers in locals, so that the compiler keeps them in registers
      // across the stores below (the arrays indexed by camera could alias them and would be read
      // again after every store). Each set by enterRow only for the costs that read it.
      const uchar* local_candidates[kLocalCameras][kChannels];
      const uchar* local_lows[kLocalCameras][kChannels];
      const uchar* local_highs[kLocalCameras][kChannels];
      const uchar* local_reference_low_rows[kLocalCameras][kChannels];
      const uchar* local_reference_high_rows[kLocalCameras][kChannels];
      ptrdiff_t local_x_step[kLocalCameras];
      for (int h = 0; h < kLocalCameras; ++h) {
        const int c = first + h;
        local_x_step[h] = candidate_x_step[c];
        for (int k = 0; k < kChannels; ++k) {
          if constexpr (kCandidateValues) local_candidates[h][k] = candidates[c][k];
          if constexpr (kCandidateIntervals) {
            local_lows[h][k] = candidate_lows[c][k];
            local_highs[h][k] = candidate_highs[c][k];
          }
          if constexpr (kReferenceIntervals) {
            local_reference_low_rows[h][k] = reference_low_rows[c][k];
            local_reference_high_rows[h][k] = reference_high_rows[c][k];
          }
        }
      }
      const uchar* reference_channel_rows[kChannels];
      for (int k = 0; k < kChannels; ++k) reference_channel_rows[k] = reference_rows[k];
      const bool group_byte_costs = byte_costs;
      const size_t ring_row_offset = (static_cast<size_t>(g) * window + slot) * row_size;
      uchar* const byte_ring_row = ring + ring_row_offset;
      Acc* const ring_row = reinterpret_cast<Acc*>(ring) + ring_row_offset;
      Acc* const sums = column_sums + g * column_stride + padded;
      const int count = padded;
      for (int xe = 0; xe < nx; ++xe) {
        const int x = x0 - r + xe;
        // The reference's sampling interval along the local cameras' baselines in locals; the
        // other cameras' (several in a group) are broadcast where they are used.
        cv::v_uint8 reference[kChannels], local_reference_low[kLocalCameras][kChannels],
            local_reference_high[kLocalCameras][kChannels];
        for (int k = 0; k < kChannels; ++k) {
          reference[k] = cv::vx_setall_u8(reference_channel_rows[k][x]);
          for (int h = 0; h < kLocalCameras; ++h) {
            if constexpr (kReferenceIntervals) {
              local_reference_low[h][k] = cv::vx_setall_u8(local_reference_low_rows[h][k][x]);
              local_reference_high[h][k] = cv::vx_setall_u8(local_reference_high_rows[h][k][x]);
            }
          }
        }
        // A camera's cost of the candidates at `offset`, summed over the channels: the absolute
        // difference, or the distance of the reference pixel to the candidate's sampling interval
        // (u8 subtraction saturates at 0, so the larger of the two signed gaps is the distance),
        // symmetric: the smaller of that and the candidate's distance to the reference's. The
        // channels' costs add up within a byte (max_difference).
        const auto pixelCost = [&](const uchar* const* values, const uchar* const* lows, const uchar* const* highs,
                                   const cv::v_uint8* reference_lows, const cv::v_uint8* reference_highs,
                                   ptrdiff_t offset) __attribute__((always_inline)) {
          cv::v_uint8 cost;
          for (int k = 0; k < kChannels; ++k) {
            cv::v_uint8 channel_cost;
            if constexpr (kCost == PixelCost::kAbsoluteDifference) {
              channel_cost = cv::v_absdiff(reference[k], cv::vx_load(values[k] + offset));
            } else {
              channel_cost = cv::v_max(reference[k] - cv::vx_load(highs[k] + offset),
                                       cv::vx_load(lows[k] + offset) - reference[k]);
            }
            if constexpr (kReferenceIntervals) {
              const cv::v_uint8 candidate = cv::vx_load(values[k] + offset);
              channel_cost =
                  cv::v_min(channel_cost, cv::v_max(candidate - reference_highs[k], reference_lows[k] - candidate));
            }
            cost = k == 0 ? channel_cost : cv::v_add_wrap(cost, channel_cost);
          }
          return cost;
        };
        ptrdiff_t local_offset[kLocalCameras];
        for (int h = 0; h < kLocalCameras; ++h) local_offset[h] = x * local_x_step[h];
        Acc* const sum_entry = sums + static_cast<size_t>(xe) * count;
        for (int b = 0; b < count; b += kByteLanes) {
          Vec entering[kVectorsPerBytes], leaving[kVectorsPerBytes];
          const auto localCost = [&](int h) __attribute__((always_inline)) {
            return pixelCost(local_candidates[h], local_lows[h], local_highs[h], local_reference_low[h],
                             local_reference_high[h], local_offset[h] + b);
          };
          const cv::v_uint8 own = localCost(0);
          const auto otherCost = [&](int c) __attribute__((always_inline)) {
            cv::v_uint8 reference_low[kChannels], reference_high[kChannels];
            for (int k = 0; k < kChannels; ++k) {
              if constexpr (kReferenceIntervals) {
                reference_low[k] = cv::vx_setall_u8(reference_low_rows[c][k][x]);
                reference_high[k] = cv::vx_setall_u8(reference_high_rows[c][k][x]);
              }
            }
            return pixelCost(candidates[c], candidate_lows[c], candidate_highs[c], reference_low, reference_high,
                             x * candidate_x_step[c] + b);
          };
          if (kHeldCameras > 0 || group_byte_costs) {
            // The costs of every camera of the group add up within a byte: widen once.
            cv::v_uint8 total = own;
            if constexpr (kHeldCameras == 0) {
              for (int c = first + 1; c < last; ++c) total = cv::v_add_wrap(total, otherCost(c));
            }
            for (int h = 1; h < kHeldCameras; ++h) total = cv::v_add_wrap(total, localCost(h));
            uchar* const ring_lanes = byte_ring_row + static_cast<size_t>(xe) * count + b;
            Lanes::widen(cv::vx_load(ring_lanes), leaving);
            cv::v_store(ring_lanes, total);
            Lanes::widen(total, entering);
          } else {
            Lanes::widen(own, entering);
            for (int c = first + 1; c < last; ++c) {
              Vec more[kVectorsPerBytes];
              Lanes::widen(otherCost(c), more);
              for (int i = 0; i < kVectorsPerBytes; ++i) entering[i] = Lanes::add(entering[i], more[i]);
            }
            for (int i = 0; i < kVectorsPerBytes; ++i) {
              Acc* const ring_lanes = ring_row + static_cast<size_t>(xe) * count + b + i * Lanes::kCount;
              leaving[i] = cv::vx_load(ring_lanes);
              cv::v_store(ring_lanes, entering[i]);
            }
          }
          for (int i = 0; i < kVectorsPerBytes; ++i) {
            Acc* const sum_lanes = sum_entry + b + i * Lanes::kCount;
            cv::v_store(sum_lanes, Lanes::slide(cv::vx_load(sum_lanes), entering[i], leaving[i]));
          }
        }
      }
    }
  };

  const auto enterRow = [&](int yy) {
    for (int k = 0; k < channels; ++k) reference_rows[k] = frame.reference[k].padded.ptr<uchar>(yy + margin) + margin;
    for (int c = 0; c < cameras; ++c) {
      const int camera = region.cameras[c];
      const CandidateSource& source = frame.sources[camera];
      for (int k = 0; k < channels; ++k) {
        const CandidateChannel& channel = source.channels[k];
        if (reference_intervals) {
          reference_low_rows[c][k] = frame.reference[k].low[camera].ptr<uchar>(yy + margin) + margin;
          reference_high_rows[c][k] = frame.reference[k].high[camera].ptr<uchar>(yy + margin) + margin;
        }
        if (source.row_intervals) {
          // The candidates lie along row yy + margin of the arranged values.
          const cv::Mat1b& values = channel.values.buffer;
          const uchar* const row = values.ptr<uchar>(yy + margin);
          const ptrdiff_t row_offset = source.origin + yy * source.y_step - (row - values.data);
          uchar* const low = interval_rows + static_cast<size_t>(2 * (c * channels + k)) * interval_row_size;
          uchar* const high = low + interval_row_size;
          samplingIntervalRow(row, values.cols - 2 * margin, margin, low, high);
          if (candidate_values) candidates[c][k] = row + row_offset;
          candidate_lows[c][k] = low + row_offset;
          candidate_highs[c][k] = high + row_offset;
          continue;
        }
        if (!source.tabulated()) {
          const ptrdiff_t row_offset = source.origin + yy * source.y_step;
          if (candidate_values) candidates[c][k] = channel.values.buffer.data + row_offset;
          if (candidate_intervals) {
            candidate_lows[c][k] = channel.low.buffer.data + row_offset;
            candidate_highs[c][k] = channel.high.buffer.data + row_offset;
          }
          continue;
        }
        uchar* const channel_tables =
            tables + static_cast<size_t>(c * images_per_camera + k * images_per_channel) * row_size;
        uchar* table = channel_tables;
        if (candidate_values) {
          candidates[c][k] = tabulate(source, channel.values.buffer, yy, table);
          table += row_size;
        }
        if (candidate_intervals) {
          candidate_lows[c][k] = tabulate(source, channel.low.buffer, yy, table);
          candidate_highs[c][k] = tabulate(source, channel.high.buffer, yy, table + row_size);
        }
      }
      candidate_x_step[c] = source.tabulated() ? padded : source.x_step;
    }
    const int slot = (yy - (region.y0 - r)) % window;
    // Every group of one camera (one camera, or best-half), or one group of two, in bytes.
    const int held_cameras = !byte_costs ? 0 : groups == cameras ? 1 : cameras == 2 ? 2 : 0;
    const auto enterWithCost = [&](auto cost_tag) {
      const auto enterWithChannels = [&](auto held_cameras_tag) {
        if (channels == 2) {
          enterGroups(slot, cost_tag, std::true_type{}, held_cameras_tag);
        } else {
          enterGroups(slot, cost_tag, std::false_type{}, held_cameras_tag);
        }
      };
      if (held_cameras == 1) {
        enterWithChannels(std::integral_constant<int, 1>{});
      } else if (held_cameras == 2) {
        enterWithChannels(std::integral_constant<int, 2>{});
      } else {
        enterWithChannels(std::integral_constant<int, 0>{});
      }
    };
    switch (frame.pixel_cost) {
      case PixelCost::kAbsoluteDifference:
        enterWithCost(std::integral_constant<PixelCost, PixelCost::kAbsoluteDifference>{});
        break;
      case PixelCost::kBirchfieldTomasi:
        enterWithCost(std::integral_constant<PixelCost, PixelCost::kBirchfieldTomasi>{});
        break;
      case PixelCost::kBirchfieldTomasiOneSided:
        enterWithCost(std::integral_constant<PixelCost, PixelCost::kBirchfieldTomasiOneSided>{});
        break;
    }
  };

  // Winner-takes-all over the scores `curve` of reference pixel x of row y (kept lanes of the padded
  // candidates), the sum of scores, the runner-up, and the reverse match's best-so-far entries.
  const bool subpixel = frame.subpixel, second_best = frame.second_best, sum_scores = frame.sum_scores;
  // The output rows of the row being matched (matchRow sets them).
  float* disparity_row = nullptr;
  int *best_score_row = nullptr, *score_sum_row = nullptr, *second_score_row = nullptr;
  const int min_disparity = frame.min_disparity;
  const int chunk_count = chunks, unpadded_chunks = whole_chunks;
  // `descending`: the pixels of the row come in order of decreasing x.
  const auto decide = [&](int x, const PathAcc* curve, bool descending) __attribute__((always_inline)) {
    const int reverse_first = reverse_sign > 0 ? region.x1 - 1 - x : x - region.x0;
    PathVec candidate_index = lane_index;
    PathVec best = PathLanes::all(kMaxScore);
    cv::v_int32 score_sum = cv::vx_setall_s32(0);
    for (int chunk = 0; chunk < chunk_count; ++chunk) {
      const int b = chunk * PathLanes::kCount;
      PathVec score = cv::vx_load(curve + b);
      if (chunk >= unpadded_chunks) {
        // Scores are never negative: OR with the padding (the largest score in its lanes: all
        // ones but the sign for 16 and 32 bits, all ones for bytes) makes those lanes the
        // largest score, AND with its complement makes them zero.
        const PathVec& pad = padding[chunk - unpadded_chunks];
        if (sum_scores) score_sum += PathLanes::widenSum(score & ~pad);
        score = score | pad;
      } else if (sum_scores) {
        score_sum += PathLanes::widenSum(score);
      }
      best = cv::v_min(best, score);
      if (reverse_sign) {
        // With x increasing, candidates reach a secondary pixel in order of increasing disparity
        // for sign +1, so a strict < keeps the smallest of tied ones; for -1, or x decreasing, <=.
        PathAcc* const entry_scores = reverse_scores + reverse_first + b;
        PathAcc* const entry_indices = reverse_indices + reverse_first + b;
        const PathVec previous = cv::vx_load(entry_scores), lowest = cv::v_min(previous, score);
        const PathVec previous_indices = cv::vx_load(entry_indices);
        cv::v_store(entry_scores, lowest);
        // Equality tests rather than < and <=, which byte lanes (unsigned) would emulate.
        cv::v_store(entry_indices, (reverse_sign > 0) != descending
                                       ? cv::v_select(lowest == previous, previous_indices, candidate_index)
                                       : cv::v_select(lowest == score, candidate_index, previous_indices));
        candidate_index = PathLanes::add(candidate_index, PathLanes::all(PathLanes::kCount));
      }
    }
    // The lowest score, then the first (smallest) disparity that has it: the lanes equal to it
    // as a bit mask, 64 candidates at a time, without data-dependent branches inside a block.
    const PathVec best_all = minInEveryLane(best);
    const PathAcc best_score = static_cast<PathAcc>(cv::v_extract_n<0>(best_all));
    const int j = firstLaneEqual<PathLanes>(curve, chunk_count, best_all);
    float disparity = static_cast<float>(min_disparity + j);
    if (subpixel && j > 0 && j < disparities - 1) {
      const double before = curve[j - 1], after = curve[j + 1];
      const double curvature = before + after - 2.0 * best_score;
      if (curvature > 0) disparity += static_cast<float>(0.5 * (before - after) / curvature);
    }
    disparity_row[x] = disparity;
    best_score_row[x] = static_cast<int>(best_score);
    // Zero when the quality-of-match test is off (SadMatch), without a reduction per pixel.
    score_sum_row[x] = sum_scores ? cv::v_reduce_sum(score_sum) : 0;
    if (second_best) {
      // The lowest score with the best and its two neighbours (and the padding) masked out, at
      // every chunk: a branch on which chunks hold them would follow the data and mispredict.
      // Equality tests work alike for every lane type. Byte lanes saturate, so `low` and `high`
      // stay the best itself at 0 and 255 (there are at most 256 candidates).
      const PathVec best_index = PathLanes::all(j), highest = PathLanes::all(kMaxScore);
      const PathVec low = PathLanes::subtract(best_index, one), high = PathLanes::add(best_index, one);
      PathVec index = lane_index, runner_up = highest;
      for (int chunk = 0; chunk < chunk_count; ++chunk) {
        PathVec score = cv::vx_load(curve + chunk * PathLanes::kCount);
        if (chunk >= unpadded_chunks) score = score | padding[chunk - unpadded_chunks];
        score = cv::v_select((index == low) | (index == best_index) | (index == high), highest, score);
        runner_up = cv::v_min(runner_up, score);
        index = PathLanes::add(index, PathLanes::all(PathLanes::kCount));
      }
      // A byte path's score can be 255 itself (saturated), so whether there is a runner-up is
      // told by the candidates' count.
      const bool has_runner_up = j >= 2 || j + 2 < disparities;
      second_score_row[x] = has_runner_up ? static_cast<int>(cv::v_extract_n<0>(minInEveryLane(runner_up)))
                                          : std::numeric_limits<int>::max();
    }
  };

  // Scanline optimisation: the cost of a path reaching pixel x at candidate d from its neighbour
  // `previous` along the row is cost(d) + min(previous(d), previous(d +- 1) + p1, min previous + p2)
  // - min previous (Hirschmuller 2008, eq. 13; subtracting the minimum keeps it bounded by the
  // largest score + p2).
  const bool scanline = frame.scanline;
  // Byte paths: the window scores and the jump costs divided by 2^path_shift.
  const int path_shift = kBytePaths ? frame.path_shift : 0;
  const double jump_scale = std::ldexp(window * window * (groups == 1 ? cameras : kept), -path_shift);
  const PathVec small_jump = PathLanes::all(static_cast<int>(std::lround(frame.scanline_p1 * jump_scale)));
  const PathVec large_jump = PathLanes::all(static_cast<int>(std::lround(frame.scanline_p2 * jump_scale)));
  // Padding lanes of a path hold the largest score, so that no real candidate is reached through
  // them. Their sums may wrap to negative values, which the OR with `padding` alone would keep
  // negative: `real_lanes` (all ones in the lanes of real candidates) clears them first.
  PathVec real_lanes[kPathVectorsPerBytes];
  for (int k = 0; k < chunk_count - unpadded_chunks; ++k) real_lanes[k] = padding[k] == PathLanes::all(0);
  const auto padded_lanes = [&](const PathVec& value, int chunk) {
    if (chunk < unpadded_chunks) return value;
    const PathVec& pad = padding[chunk - unpadded_chunks];
    return (value & real_lanes[chunk - unpadded_chunks]) | pad;
  };
  // Writes the path reaching a pixel of scores `cost` from its neighbour's path `previous`, whose
  // lowest entry is in every lane of `lowest_all` (none for the first pixel), and returns the new
  // path's lowest entry the same way: that minimum is the step from pixel to pixel that nothing
  // can overlap, so it stays in a vector register.
  const auto followPath = [&](const PathAcc* cost, const PathAcc* previous, const PathVec& lowest_all,
                              PathAcc* path) {
    const PathVec jump_floor = PathLanes::add(lowest_all, large_jump);
    const PathVec beyond = PathLanes::all(kMaxScore);  // the neighbours of the first and last candidates
    PathVec new_lowest = PathLanes::all(kMaxScore);
    // The neighbouring candidates come from whole vectors of `previous`: loading them one lane off
    // the vectors just stored would wait for those stores to reach the cache, at every pixel.
    PathVec below = beyond, here = previous ? cv::vx_load(previous) : beyond;
    for (int chunk = 0; chunk < chunk_count; ++chunk) {
      const int b = chunk * PathLanes::kCount;
      PathVec value = cv::vx_load(cost + b);
      if (previous) {
        const PathVec above = chunk + 1 < chunk_count ? cv::vx_load(previous + b + PathLanes::kCount) : beyond;
        const PathVec neighbours =
            cv::v_min(cv::v_extract<PathLanes::kCount - 1>(below, here), cv::v_extract<1>(here, above));
        const PathVec reach = cv::v_min(cv::v_min(here, PathLanes::add(neighbours, small_jump)), jump_floor);
        below = here;
        here = above;
        value = PathLanes::add(value, PathLanes::subtract(reach, lowest_all));
      }
      value = padded_lanes(value, chunk);
      new_lowest = cv::v_min(new_lowest, value);
      cv::v_store(path + b, value);
    }
    return minInEveryLane(new_lowest);
  };

  // followPath for a path of kChunks vectors (known at compile time), whose neighbour's path is
  // read from, and the new one left in, the vectors `held` rather than memory: the step from
  // pixel to pixel then does not wait for the neighbour's stores to be read back (12% of the
  // scanline's time at 64 candidates with AVX2). Used for two vectors (64 candidates in bytes with
  // AVX2, 32 with SSE2) only: adding the other counts to the same loop, or one function templated
  // for both ways, measured slower at 640x480 (docs/experiments.md).
  const auto followHeldPath = [&](auto chunks_tag, const PathAcc* cost, PathVec* held, bool first,
                                  const PathVec& lowest_all, PathAcc* path) __attribute__((always_inline)) {
    constexpr int kChunks = decltype(chunks_tag)::value;
    const PathVec jump_floor = PathLanes::add(lowest_all, large_jump);
    const PathVec beyond = PathLanes::all(kMaxScore);
    PathVec new_lowest = PathLanes::all(kMaxScore);
    PathVec next[kChunks];
    for (int chunk = 0; chunk < kChunks; ++chunk) {
      const int b = chunk * PathLanes::kCount;
      PathVec value = cv::vx_load(cost + b);
      if (!first) {
        const PathVec below = chunk > 0 ? held[chunk - 1] : beyond;
        const PathVec above = chunk + 1 < kChunks ? held[chunk + 1] : beyond;
        const PathVec neighbours =
            cv::v_min(cv::v_extract<PathLanes::kCount - 1>(below, held[chunk]), cv::v_extract<1>(held[chunk], above));
        const PathVec reach = cv::v_min(cv::v_min(held[chunk], PathLanes::add(neighbours, small_jump)), jump_floor);
        value = PathLanes::add(value, PathLanes::subtract(reach, lowest_all));
      }
      value = padded_lanes(value, chunk);
      new_lowest = cv::v_min(new_lowest, value);
      cv::v_store(path + b, value);
      next[chunk] = value;
    }
    for (int chunk = 0; chunk < kChunks; ++chunk) held[chunk] = next[chunk];
    return minInEveryLane(new_lowest);
  };

  // Horizontal running sum of the column sums gives every candidate's window score of each pixel
  // of row y; the winner is taken at once, or after the scanline paths over the whole row.
  const auto matchRow = [&](int y, auto combine_groups) {
    constexpr bool kCombine = decltype(combine_groups)::value;
    disparity_row = out.disparity.ptr<float>(y);
    best_score_row = out.best_score.ptr<int>(y);
    score_sum_row = out.score_sum.ptr<int>(y);
    second_score_row = second_best ? out.second_score.ptr<int>(y) : nullptr;
    for (int g = 0; g < groups; ++g) {
      // The window of the first pixel minus its last column, which the first slide brings in.
      const Acc* sums = column_sums + g * column_stride;
      for (int b = 0; b < padded; b += Lanes::kCount) {
        Vec total = Lanes::all(0);
        for (int xe = 0; xe < window - 1; ++xe) {
          total = Lanes::add(total, cv::vx_load(sums + static_cast<size_t>(xe + 1) * padded + b));
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
    PathVec forward_lowest = PathLanes::all(0);
    // The paths from the left and from the right held in registers (followHeldPath).
    constexpr std::integral_constant<int, 2> kHeldChunks{};
    PathVec forward_held[kHeldChunks] = {PathLanes::all(kMaxScore), PathLanes::all(kMaxScore)};
    PathVec backward_held[kHeldChunks] = {PathLanes::all(kMaxScore), PathLanes::all(kMaxScore)};
    if (reverse_sign) std::fill(reverse_scores, reverse_scores + reverse_size, kMaxScore);
    for (int x = region.x0; x < region.x1; ++x) {
      // Columns entering and leaving the window, relative to each group's column sums.
      const size_t entering = static_cast<size_t>(x - x0 + 2 * r + 1) * count;
      const size_t leaving = static_cast<size_t>(x - x0) * count;
      const size_t i = static_cast<size_t>(x - region.x0);
      // The pixel's window scores of candidates b.., slid from the previous pixel's at `from`, written
      // to `to`; with several groups, the sum of the `kept` lowest group scores (each group's own
      // scores slide in place).
      const auto windowScores = [&](int b, const Acc* from, Acc* to) __attribute__((always_inline)) {
        if constexpr (!kCombine) {
          const Vec value =
              Lanes::slide(cv::vx_load(from + b), cv::vx_load(all_sums + b + entering), cv::vx_load(all_sums + b + leaving));
          cv::v_store(to + b, value);
          return value;
        } else {
          for (int g = 0; g < groups; ++g) {
            Acc* const group_score = group_scores + g * count + b;
            const Acc* const sums = all_sums + g * stride + b;
            Vec value = Lanes::slide(cv::vx_load(group_score), cv::vx_load(sums + entering), cv::vx_load(sums + leaving));
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
          cv::v_store(to + b, score);
          return score;
        }
      };
      if constexpr (kBytePaths) {
        // The window scores slide in place (the best half's sums go to `combined`, unread); the
        // row's costs are those scores divided by 2^path_shift, as bytes (saturated at 255).
        PathAcc* const pixel_costs = row_costs + i * count;
        Acc* const window_scores = kCombine ? combined : group_scores;
        for (int b = 0; b < count; b += kByteLanes) {
          const Vec low = windowScores(b, group_scores, window_scores);
          const Vec high = windowScores(b + Lanes::kCount, group_scores, window_scores);
          cv::v_store(pixel_costs + b, cv::v_pack_u(low >> path_shift, high >> path_shift));
        }
        if (chunk_count == kHeldChunks) {
          forward_lowest = followHeldPath(kHeldChunks, pixel_costs, forward_held, i == 0, forward_lowest,
                                          forward_paths + i * path_stride);
        } else {
          forward_lowest = followPath(pixel_costs, i == 0 ? nullptr : forward_paths + (i - 1) * path_stride,
                                      forward_lowest, forward_paths + i * path_stride);
        }
      } else {
        // The pixel's combined scores: in the group scores themselves for one group, else in a
        // buffer of their own; for the scanline, in the row's costs.
        Acc* const pixel_costs = scanline ? row_costs + i * count : (kCombine ? combined : group_scores);
        // One group: with the scanline the window slides from the previous pixel's scores in the
        // row's costs (so they are stored once), else in place.
        const Acc* const sliding = scanline && x > region.x0 ? pixel_costs - count : group_scores;
        for (int chunk = 0; chunk < score_chunks; ++chunk) windowScores(chunk * Lanes::kCount, sliding, pixel_costs);
        if (!scanline) {
          decide(x, pixel_costs, false);
        } else {
          // The path from the left, in the same sweep as the window scores.
          forward_lowest = followPath(pixel_costs, i == 0 ? nullptr : forward_paths + (i - 1) * path_stride,
                                      forward_lowest, forward_paths + i * path_stride);
          for (int direction = 0; direction < kDirectionsFromAbove && kPathsFromAbove; ++direction) {
            const ptrdiff_t from = static_cast<ptrdiff_t>(i) + direction - 1;
            const bool starts = y == region.y0 || from < 0 || from >= static_cast<ptrdiff_t>(row_pixels);
            const size_t previous = starts ? 0 : aboveIndex(y - 1, direction, static_cast<size_t>(from));
            const size_t current = aboveIndex(y, direction, i);
            above_lowest[current] = cv::v_extract_n<0>(followPath(
                pixel_costs, starts ? nullptr : above_paths + previous * path_stride,
                PathLanes::all(starts ? 0 : above_lowest[previous]), above_paths + current * path_stride));
          }
        }
      }
    }
    if (!scanline) return;
    // The path from the right, added to the one from the left, gives the aggregated scores; the
    // winner is taken in the same sweep.
    PathVec backward_lowest = PathLanes::all(0);
    for (int x = region.x1 - 1; x >= region.x0; --x) {
      const size_t i = static_cast<size_t>(x - region.x0);
      const bool first = x == region.x1 - 1;
      PathAcc* const path = backward_paths + (i % 2) * path_stride;
      const PathAcc* const previous = first ? nullptr : backward_paths + ((i + 1) % 2) * path_stride;
      if (kBytePaths && chunk_count == kHeldChunks) {
        backward_lowest = followHeldPath(kHeldChunks, row_costs + i * padded, backward_held, first, backward_lowest, path);
      } else {
        backward_lowest = followPath(row_costs + i * padded, previous, backward_lowest, path);
      }
      const PathAcc* const forward = forward_paths + i * path_stride;
      for (int chunk = 0; chunk < chunk_count; ++chunk) {
        const int b = chunk * PathLanes::kCount;
        PathVec sum = PathLanes::add(cv::vx_load(forward + b), cv::vx_load(path + b));
        for (int direction = 0; direction < kDirectionsFromAbove && kPathsFromAbove; ++direction) {
          sum = PathLanes::add(sum, cv::vx_load(above_paths + aboveIndex(y, direction, i) * path_stride + b));
        }
        // Padding lanes (the largest score, added up and wrapped) become zero; decide() pads them again.
        cv::v_store(path_sums + b, chunk < unpadded_chunks ? sum : sum & real_lanes[chunk - unpadded_chunks]);
      }
      decide(x, path_sums, true);
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

// This build's kernel.
inline SadKernel makeSadKernel() {
  return SadKernel{kByteLanes,
                   {{&matchRegion<int16_t, false, false>, &matchRegion<int16_t, true, false>},
                    {&matchRegion<int32_t, false, false>, &matchRegion<int32_t, true, false>}},
                   &matchRegion<int16_t, false, true>};
}

}  // namespace STEREONAV_SAD_KERNEL_NAMESPACE
}  // namespace stereonav
