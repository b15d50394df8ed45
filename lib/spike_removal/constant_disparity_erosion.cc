#include "spike_removal/constant_disparity_erosion.h"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

#include "disparity/disparity_image.h"

namespace stereonav {

ConstantDisparityErosion::ConstantDisparityErosion(int kernel) {
  if (kernel < 3 || kernel % 2 == 0) {
    throw std::invalid_argument("ConstantDisparityErosion: kernel must be odd and >= 3, got " +
                                std::to_string(kernel));
  }
  structuring_element_ = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(kernel, kernel));
}

void ConstantDisparityErosion::apply(cv::Mat1f& disparity, cv::Mat1b& rejected) {
  rejected.create(disparity.size());
  if (disparity.empty()) return;
  // The default border value of erode/dilate never wins the min/max, so pixels outside the image
  // do not count against a pixel near the border.
  cv::erode(disparity, lowest_, structuring_element_);
  cv::dilate(disparity, highest_, structuring_element_);
  for (int y = 0; y < disparity.rows; ++y) {
    float* row = disparity[y];
    const float* lowest = lowest_[y];
    const float* highest = highest_[y];
    uint8_t* mask = rejected[y];
    for (int x = 0; x < disparity.cols; ++x) {
      // An invalid neighbour makes the maximum +inf, which fails the test.
      const bool survives =
          isValidDisparity(highest[x]) && std::round(lowest[x]) == std::round(highest[x]);
      const bool reject = isValidDisparity(row[x]) && !survives;
      if (reject) row[x] = kInvalidDisparity;
      mask[x] = reject ? 255 : 0;
    }
  }
}

}  // namespace stereonav
