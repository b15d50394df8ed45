#include "spike_removal/surface_segmentation.h"

#include <opencv2/core/hal/intrin.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "disparity/disparity_image.h"

namespace stereonav {
namespace {

constexpr int kWordBits = 64;

inline void setBit(std::vector<uint64_t>& bits, int x, bool on) {
  bits[x / kWordBits] |= static_cast<uint64_t>(on) << (x % kWordBits);
}

// Whether any bit in columns [begin, end) is set.
inline bool anyInRange(const std::vector<uint64_t>& bits, int begin, int end) {
  if (begin >= end) return false;
  const int first = begin / kWordBits, last = (end - 1) / kWordBits;
  const uint64_t first_mask = ~uint64_t{0} << (begin % kWordBits);
  const uint64_t last_mask = ~uint64_t{0} >> (kWordBits - 1 - (end - 1) % kWordBits);
  if (first == last) return (bits[first] & first_mask & last_mask) != 0;
  if (bits[first] & first_mask) return true;
  for (int word = first + 1; word < last; ++word) {
    if (bits[word]) return true;
  }
  return (bits[last] & last_mask) != 0;
}

// The first column at or after `from` whose bit is clear. Bits past the row's end are clear,
// and a word past its last one (RowMasks) ends the search in a row whose every bit is set.
inline int firstClear(const std::vector<uint64_t>& bits, int from) {
  int word = from / kWordBits;
  uint64_t clear = ~bits[word] & (~uint64_t{0} << (from % kWordBits));
  while (clear == 0) clear = ~bits[++word];
  return word * kWordBits + __builtin_ctzll(clear);
}

}  // namespace

SurfaceSegmentation::SurfaceSegmentation(const SurfaceSegmentationOptions& options)
    : options_(options) {}

int32_t SurfaceSegmentation::findRoot(int32_t label) {
  while (parent_[label] != label) {
    parent_[label] = parent_[parent_[label]];  // path halving keeps the trees flat
    label = parent_[label];
  }
  return label;
}

int32_t SurfaceSegmentation::join(int32_t label, int32_t neighbour_label) {
  if (label == 0) return neighbour_label;
  if (label == neighbour_label) return label;
  const int32_t a = findRoot(label);
  const int32_t b = findRoot(neighbour_label);
  // The smaller label becomes the root, so parent_[l] <= l holds and classifyLabels() can
  // resolve every label in one ascending sweep.
  if (a < b) {
    parent_[b] = a;
    return a;
  }
  parent_[a] = b;
  return b;
}

template <bool kEightConnected>
void SurfaceSegmentation::labelRow(int y, int width, int32_t& next_label) {
  // An above run [begin, end) can touch this row's columns from begin - reach to end - 1 + reach.
  constexpr int kReach = kEightConnected ? 1 : 0;
  size_t above = y > 0 ? row_first_run_[y - 1] : 0;
  const size_t above_end = row_first_run_[y];
  const int words = (width + kWordBits - 1) / kWordBits;
  for (int word = 0; word < words; ++word) {
    // A run starts at a valid pixel not joined to its left neighbour.
    uint64_t starts = masks_.valid[word] & ~masks_.left[word];
    while (starts) {
      const int begin = word * kWordBits + __builtin_ctzll(starts);
      starts &= starts - 1;
      const int end = std::min(firstClear(masks_.left, begin + 1), width);
      while (above < above_end && runs_[above].end + kReach <= begin) ++above;
      int32_t label = 0, last_joined = 0;
      // The next run may touch the last above run this one touches, so `above` stays.
      for (size_t j = above; j < above_end && runs_[j].begin < end + kReach; ++j) {
        const Run& neighbour = runs_[j];
        if (neighbour.label == last_joined) continue;
        bool touches = anyInRange(masks_.up, std::max(begin, neighbour.begin), std::min(end, neighbour.end));
        if (kEightConnected && !touches) {
          touches = anyInRange(masks_.up_left, std::max(begin, neighbour.begin + 1), std::min(end, neighbour.end + 1)) ||
                    anyInRange(masks_.up_right, std::max(begin, neighbour.begin - 1), std::min(end, neighbour.end - 1));
        }
        if (!touches) continue;
        label = join(label, neighbour.label);
        last_joined = neighbour.label;
      }
      if (label == 0) {
        label = next_label++;
        parent_[label] = label;
        region_size_[label] = 0;
      }
      region_size_[label] += end - begin;
      runs_.push_back({begin, end, label});
    }
  }
}

template <bool kEightConnected>
int32_t SurfaceSegmentation::labelSurfaces(const cv::Mat1f& disparity) {
  const int width = disparity.cols;
  const size_t words = (width + kWordBits - 1) / kWordBits;
  runs_.clear();
  row_first_run_.resize(disparity.rows + 1);
  int32_t next_label = 1;
  // An invalid pixel is +inf, so |d - neighbour| <= max_difference is false when either is
  // invalid (inf - inf is NaN): one comparison tells both validity and closeness.
  const float max_difference = options_.max_difference;
  const auto close = [max_difference](float a, float b) { return std::abs(a - b) <= max_difference; };
  for (int y = 0; y < disparity.rows; ++y) {
    const float* row = disparity[y];
    const float* row_above = y > 0 ? disparity[y - 1] : nullptr;
    masks_.clearRow(words);
    const auto maskPixel = [&](int x) {
      setBit(masks_.valid, x, isValidDisparity(row[x]));
      setBit(masks_.left, x, x > 0 && close(row[x], row[x - 1]));
      if (!row_above) return;
      setBit(masks_.up, x, close(row[x], row_above[x]));
      if (!kEightConnected) return;
      setBit(masks_.up_left, x, x > 0 && close(row[x], row_above[x - 1]));
      setBit(masks_.up_right, x, x + 1 < width && close(row[x], row_above[x + 1]));
    };
    // Lane groups start at multiples of the lane count, so none straddles a word; the first group
    // and the tail (reading x - 1 and x + 1) are done one pixel at a time.
    int x = 0;
#if CV_SIMD
    constexpr int kLanes = cv::v_float32::nlanes;
    const int first_vector = std::min(kLanes, width);
    for (; x < first_vector; ++x) maskPixel(x);
    const cv::v_float32 invalid = cv::vx_setall_f32(kInvalidDisparity), limit = cv::vx_setall_f32(max_difference);
    const auto closeLanes = [&limit](const cv::v_float32& a, const cv::v_float32& b) {
      return static_cast<uint64_t>(cv::v_signmask(cv::v_abs(a - b) <= limit));
    };
    for (; x + kLanes < width; x += kLanes) {
      const cv::v_float32 d = cv::vx_load(row + x);
      const int word = x / kWordBits, shift = x % kWordBits;
      masks_.valid[word] |= static_cast<uint64_t>(cv::v_signmask(d != invalid)) << shift;
      masks_.left[word] |= closeLanes(d, cv::vx_load(row + x - 1)) << shift;
      if (!row_above) continue;
      masks_.up[word] |= closeLanes(d, cv::vx_load(row_above + x)) << shift;
      if (!kEightConnected) continue;
      masks_.up_left[word] |= closeLanes(d, cv::vx_load(row_above + x - 1)) << shift;
      masks_.up_right[word] |= closeLanes(d, cv::vx_load(row_above + x + 1)) << shift;
    }
#endif
    for (; x < width; ++x) maskPixel(x);
    row_first_run_[y] = runs_.size();
    labelRow<kEightConnected>(y, width, next_label);
  }
  row_first_run_[disparity.rows] = runs_.size();
  return next_label;
}

void SurfaceSegmentation::classifyLabels(int32_t label_count) {
  // parent_[l] <= l, so ascending order meets every label's parent already resolved to its root.
  for (int32_t label = 1; label < label_count; ++label) {
    parent_[label] = parent_[parent_[label]];
    if (parent_[label] != label) region_size_[parent_[label]] += region_size_[label];
  }
  for (int32_t label = 1; label < label_count; ++label) {
    reject_label_[label] = region_size_[parent_[label]] < options_.min_region_pixels ? 255 : 0;
  }
}

void SurfaceSegmentation::apply(cv::Mat1f& disparity, cv::Mat1b& rejected) {
  const size_t pixels = disparity.total();
  rejected.create(disparity.size());
  rejected.setTo(0);
  if (pixels == 0) return;
  if (parent_.size() < pixels + 1) {
    // Without any connection every pixel is its own surface: at most one label per pixel.
    parent_.resize(pixels + 1);
    region_size_.resize(pixels + 1);
    reject_label_.resize(pixels + 1);
  }

  const int32_t label_count = options_.connectivity == 4 ? labelSurfaces<false>(disparity)
                                                         : labelSurfaces<true>(disparity);
  classifyLabels(label_count);

  for (int y = 0; y < disparity.rows; ++y) {
    float* row = disparity[y];
    uint8_t* mask = rejected[y];
    for (size_t i = row_first_run_[y]; i < row_first_run_[y + 1]; ++i) {
      const Run& run = runs_[i];
      if (!reject_label_[run.label]) continue;
      std::fill(row + run.begin, row + run.end, kInvalidDisparity);
      std::memset(mask + run.begin, 255, run.end - run.begin);
    }
  }
}

}  // namespace stereonav
