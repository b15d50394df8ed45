#include "spike_removal/spike_filter.h"

namespace stereonav {

SpikeFilter::SpikeFilter(const SpikeRemovalOptions& options)
    : type_(options.filter),
      segmentation_(options.segmentation),
      median_(options.median_kernel),
      erosion_(options.erosion_kernel) {}

void SpikeFilter::apply(cv::Mat1f& disparity, cv::Mat1b& rejected) {
  switch (type_) {
    case SpikeFilterType::kNone:
      rejected.create(disparity.size());
      rejected.setTo(0);
      return;
    case SpikeFilterType::kMedian:
      median_.apply(disparity, rejected);
      return;
    case SpikeFilterType::kErosion:
      erosion_.apply(disparity, rejected);
      return;
    case SpikeFilterType::kSegmentation:
      segmentation_.apply(disparity, rejected);
      return;
  }
}

}  // namespace stereonav
