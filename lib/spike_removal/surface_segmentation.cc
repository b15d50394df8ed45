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

// Along a row, consecutive connected pixels form a run that shares one label. Within a run the
// row above mostly holds one label too, so remembering the last label already joined skips almost
// every union-find call; and pixels are counted per run, not with a store per pixel.
struct SurfaceSegmentation::RowScan {
  int32_t* labels = nullptr;  // this row's labels
  int32_t label = 0;          // the current run's label; 0 while the pixel has none yet
  int32_t last_joined = 0;    // a label of the row above already joined with `label`
  int32_t pending = 0;        // pixels of the current run not yet added to region_size_
  int32_t next_label = 1;
};

template <bool kEightConnected, bool kHasLeft, bool kHasUp, bool kHasUpRight>
inline void SurfaceSegmentation::labelPixel(const float* row, const float* row_above,
                                            const int32_t* labels_above, int x, RowScan& scan) {
  const float d = row[x];
  // An invalid neighbour is +inf, so |d - inf| <= max_difference is false: no separate test.
  const float max_difference = options_.max_difference;
  const auto connected = [d, max_difference](float neighbour) {
    return std::abs(d - neighbour) <= max_difference;
  };
  if (!(kHasLeft && isValidDisparity(d) && connected(row[x - 1]))) {
    // The run ends here: credit its pixels before starting another.
    region_size_[scan.label] += scan.pending;
    scan.pending = 0;
    scan.label = 0;
    scan.last_joined = 0;
    if (!isValidDisparity(d)) {
      scan.labels[x] = 0;
      return;
    }
  }
  const auto joinAbove = [this, &scan](int32_t above) {
    if (above == scan.last_joined) return;
    scan.last_joined = above;
    scan.label = join(scan.label, above);
  };
  if (kHasUp) {
    if (kEightConnected && kHasLeft && connected(row_above[x - 1])) joinAbove(labels_above[x - 1]);
    if (connected(row_above[x])) joinAbove(labels_above[x]);
    if (kEightConnected && kHasUpRight && connected(row_above[x + 1])) {
      joinAbove(labels_above[x + 1]);
    }
  }
  if (scan.label == 0) {
    scan.label = scan.next_label++;
    parent_[scan.label] = scan.label;
    region_size_[scan.label] = 0;
  }
  ++scan.pending;
  scan.labels[x] = scan.label;
}

template <bool kEightConnected>
int32_t SurfaceSegmentation::labelSurfaces(const cv::Mat1f& disparity) {
  const int width = disparity.cols;
  RowScan scan;
  region_size_[0] = 0;  // collects the (ignored) count of "no run"
  for (int y = 0; y < disparity.rows; ++y) {
    const float* row = disparity[y];
    scan.labels = labels_.data() + static_cast<size_t>(y) * width;
    if (y == 0) {
      labelPixel<kEightConnected, false, false, false>(row, nullptr, nullptr, 0, scan);
      for (int x = 1; x < width; ++x) {
        labelPixel<kEightConnected, true, false, false>(row, nullptr, nullptr, x, scan);
      }
      continue;
    }
    const float* row_above = disparity[y - 1];
    const int32_t* labels_above = scan.labels - width;
    if (width == 1) {
      labelPixel<kEightConnected, false, true, false>(row, row_above, labels_above, 0, scan);
      continue;
    }
    labelPixel<kEightConnected, false, true, true>(row, row_above, labels_above, 0, scan);
    for (int x = 1; x < width - 1; ++x) {
      labelPixel<kEightConnected, true, true, true>(row, row_above, labels_above, x, scan);
    }
    labelPixel<kEightConnected, true, true, false>(row, row_above, labels_above, width - 1, scan);
  }
  region_size_[scan.label] += scan.pending;
  return scan.next_label;
}

void SurfaceSegmentation::classifyLabels(int32_t label_count) {
  // parent_[l] <= l, so ascending order meets every label's parent already resolved to its root.
  for (int32_t label = 1; label < label_count; ++label) {
    parent_[label] = parent_[parent_[label]];
    if (parent_[label] != label) region_size_[parent_[label]] += region_size_[label];
  }
  reject_label_[0] = 0;
  for (int32_t label = 1; label < label_count; ++label) {
    reject_label_[label] = region_size_[parent_[label]] < options_.min_region_pixels ? 255 : 0;
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
      // Written without branches: which pixels go is as unpredictable as the spikes.
      const uint8_t reject = reject_label_[labels[x]];
      row[x] = reject ? kInvalidDisparity : row[x];
      mask[x] = reject;
    }
  }
}

}  // namespace stereonav
