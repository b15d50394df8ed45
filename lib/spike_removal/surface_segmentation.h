#pragma once

#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

#include "spike_removal/spike_removal_options.h"

namespace stereonav {

// Spike removal by surface segmentation (paper section 4.2). Mismatches come in small, locally
// stable patches with sharp disparity jumps at all their borders, so they are found as small
// surfaces: pixels are joined when they are neighbours (4- or 8-connected) and their disparities
// differ by at most max_difference, and every surface of fewer than min_region_pixels pixels is
// invalidated. A thin structure (a pole, a table edge) survives because it is joined to the larger
// surface it stands on, which median and morphological filters cannot know (section 4.1).
//
// Two-pass union-find labelling of runs (a row's consecutive joined pixels): linear in the number
// of pixels, with the per-pixel work done as vector comparisons into bit masks, and the rest per
// run. The buffers are kept between frames, so a frame of an unchanged size allocates nothing.
class SurfaceSegmentation {
 public:
  explicit SurfaceSegmentation(const SurfaceSegmentationOptions& options);

  // Invalidates the small surfaces of `disparity` in place. `rejected` becomes a mask of the same
  // size: 255 where this call invalidated a pixel, 0 elsewhere.
  void apply(cv::Mat1f& disparity, cv::Mat1b& rejected);

 private:
  struct Run {
    int32_t begin, end;  // columns [begin, end) of one row
    int32_t label;
  };
  // Which pixels of a row join which neighbours, one bit per pixel (bit x % 64 of word x / 64),
  // and one more word, always clear.
  struct RowMasks {
    std::vector<uint64_t> valid, left, up, up_left, up_right;
    // All bits clear, for a row of `words` words.
    void clearRow(size_t words) {
      for (std::vector<uint64_t>* bits : {&valid, &left, &up, &up_left, &up_right}) bits->assign(words + 1, 0);
    }
  };

  // First pass: the runs of every row in runs_ (row y's from row_first_run_[y]), label
  // equivalences in parent_, pixels per label in region_size_. Returns the number of labels used
  // (including 0, which none has).
  template <bool kEightConnected>
  int32_t labelSurfaces(const cv::Mat1f& disparity);
  // Labels the runs of row y, joining each to the runs of row y - 1 it touches.
  template <bool kEightConnected>
  void labelRow(int y, int width, int32_t& next_label);
  int32_t join(int32_t label, int32_t neighbour_label);
  int32_t findRoot(int32_t label);
  // Second pass: marks every label whose whole surface is too small in reject_label_.
  void classifyLabels(int32_t label_count);

  SurfaceSegmentationOptions options_;
  RowMasks masks_;
  std::vector<Run> runs_;
  std::vector<size_t> row_first_run_;  // rows + 1 entries
  std::vector<int32_t> parent_;        // union-find forest over labels; parent_[l] <= l
  std::vector<int32_t> region_size_;
  std::vector<uint8_t> reject_label_;  // 255 = the label's surface is too small, else 0
};

}  // namespace stereonav
