#include "spike_removal/median_spike_filter.h"

#include <opencv2/imgproc.hpp>

#include <stdexcept>
#include <string>

#include "disparity/disparity_image.h"

namespace stereonav {

MedianSpikeFilter::MedianSpikeFilter(int kernel) : kernel_(kernel) {
  if (kernel != 3 && kernel != 5) {
    throw std::invalid_argument("MedianSpikeFilter: kernel must be 3 or 5, got " +
                                std::to_string(kernel));
  }
}

void MedianSpikeFilter::apply(cv::Mat1f& disparity, cv::Mat1b& rejected) {
  rejected.create(disparity.size());
  if (disparity.empty()) return;
  cv::medianBlur(disparity, filtered_, kernel_);
  for (int y = 0; y < disparity.rows; ++y) {
    float* row = disparity[y];
    const float* median = filtered_[y];
    uint8_t* mask = rejected[y];
    for (int x = 0; x < disparity.cols; ++x) {
      const bool was_valid = isValidDisparity(row[x]);
      if (was_valid) row[x] = median[x];
      mask[x] = was_valid && !isValidDisparity(median[x]) ? 255 : 0;
    }
  }
}

}  // namespace stereonav
