#pragma once

#include <opencv2/core.hpp>

#include "spike_removal/constant_disparity_erosion.h"
#include "spike_removal/median_spike_filter.h"
#include "spike_removal/spike_removal_options.h"
#include "spike_removal/surface_segmentation.h"

namespace stereonav {

// The spike removal stage: applies the filter chosen in [spike_removal] filter = ... to each
// disparity image. Keeps the chosen filter's buffers between frames.
class SpikeFilter {
 public:
  explicit SpikeFilter(const SpikeRemovalOptions& options);

  // Filters `disparity` in place; `rejected` = 255 where a valid pixel was invalidated (for debug
  // pictures), 0 elsewhere.
  void apply(cv::Mat1f& disparity, cv::Mat1b& rejected);

  SpikeFilterType type() const { return type_; }

 private:
  SpikeFilterType type_;
  SurfaceSegmentation segmentation_;
  MedianSpikeFilter median_;
  ConstantDisparityErosion erosion_;
};

}  // namespace stereonav
