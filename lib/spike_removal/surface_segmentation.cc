#include "spike_removal/surface_segmentation.h"

#include <cmath>

#include "disparity/disparity_image.h"

namespace stereonav {

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

template <bool kEightConnected, bool kHasLeft, bool kHasUp, bool kHasUpRight>
inline int32_t SurfaceSegmentation::labelPixel(const float* row, const float* row_above,
                                               const int32_t* labels,
                                               const int32_t* labels_above, int x,
                                               int32_t& next_label) {
  const float d = row[x];
  if (!isValidDisparity(d)) return 0;
  // An invalid neighbour is +inf, so |d - inf| <= max_difference is false: no separate test.
  const float max_difference = options_.max_difference;
  const auto connected = [d, max_difference](float neighbour) {
    return std::abs(d - neighbour) <= max_difference;
  };
  int32_t label = 0;
  if (kHasLeft && connected(row[x - 1])) label = labels[x - 1];
  if (kHasUp) {
    if (connected(row_above[x])) label = join(label, labels_above[x]);
    if (kEightConnected && kHasLeft && connected(row_above[x - 1])) {
      label = join(label, labels_above[x - 1]);
    }
    if (kEightConnected && kHasUpRight && connected(row_above[x + 1])) {
      label = join(label, labels_above[x + 1]);
    }
  }
  if (label == 0) {
    label = next_label++;
    parent_[label] = label;
    region_size_[label] = 0;
  }
  ++region_size_[label];
  return label;
}

template <bool kEightConnected>
int32_t SurfaceSegmentation::labelSurfaces(const cv::Mat1f& disparity) {
  const int width = disparity.cols;
  int32_t next_label = 1;
  for (int y = 0; y < disparity.rows; ++y) {
    const float* row = disparity[y];
    int32_t* labels = labels_.data() + static_cast<size_t>(y) * width;
    if (y == 0) {
      labels[0] = labelPixel<kEightConnected, false, false, false>(row, nullptr, labels, nullptr,
                                                                    0, next_label);
      for (int x = 1; x < width; ++x) {
        labels[x] = labelPixel<kEightConnected, true, false, false>(row, nullptr, labels,
                                                                     nullptr, x, next_label);
      }
      continue;
    }
    const float* row_above = disparity[y - 1];
    const int32_t* labels_above = labels - width;
    if (width == 1) {
      labels[0] = labelPixel<kEightConnected, false, true, false>(row, row_above, labels,
                                                                   labels_above, 0, next_label);
      continue;
    }
    labels[0] = labelPixel<kEightConnected, false, true, true>(row, row_above, labels,
                                                                labels_above, 0, next_label);
    for (int x = 1; x < width - 1; ++x) {
      labels[x] = labelPixel<kEightConnected, true, true, true>(row, row_above, labels,
                                                                 labels_above, x, next_label);
    }
    labels[width - 1] = labelPixel<kEightConnected, true, true, false>(
        row, row_above, labels, labels_above, width - 1, next_label);
  }
  return next_label;
}

void SurfaceSegmentation::classifyLabels(int32_t label_count) {
  // parent_[l] <= l, so ascending order meets every label's parent already resolved to its root.
  for (int32_t label = 1; label < label_count; ++label) {
    parent_[label] = parent_[parent_[label]];
    if (parent_[label] != label) region_size_[parent_[label]] += region_size_[label];
  }
  reject_label_[0] = 0;
  for (int32_t label = 1; label < label_count; ++label) {
    reject_label_[label] = region_size_[parent_[label]] < options_.min_region_pixels;
  }
}

void SurfaceSegmentation::apply(cv::Mat1f& disparity, cv::Mat1b& rejected) {
  const size_t pixels = disparity.total();
  rejected.create(disparity.size());
  if (pixels == 0) return;
  if (labels_.size() < pixels) {
    labels_.resize(pixels);
    // Without any connection every pixel is its own surface: at most one label per pixel.
    parent_.resize(pixels + 1);
    region_size_.resize(pixels + 1);
    reject_label_.resize(pixels + 1);
  }

  const int32_t label_count = options_.connectivity == 4 ? labelSurfaces<false>(disparity)
                                                         : labelSurfaces<true>(disparity);
  classifyLabels(label_count);

  const int width = disparity.cols;
  for (int y = 0; y < disparity.rows; ++y) {
    float* row = disparity[y];
    uint8_t* mask = rejected[y];
    const int32_t* labels = labels_.data() + static_cast<size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      const uint8_t reject = reject_label_[labels[x]];
      if (reject) row[x] = kInvalidDisparity;
      mask[x] = reject ? 255 : 0;
    }
  }
}

}  // namespace stereonav
