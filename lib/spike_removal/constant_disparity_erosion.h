#pragma once

#include <opencv2/core.hpp>

namespace stereonav {

// Morphological erosion of every region of constant (integer) disparity, the morphological filter
// paper section 4.1 compares with surface segmentation: a pixel survives only if every pixel of
// its kernel x kernel neighbourhood (inside the image) is valid and has the same disparity rounded
// to an integer. Built from OpenCV's grey-level erosion and dilation (the neighbourhood minimum and
// maximum): because rounding is monotonic, all neighbours share the rounded disparity exactly when
// the minimum and the maximum do.
class ConstantDisparityErosion {
 public:
  // kernel: odd, >= 3.
  explicit ConstantDisparityErosion(int kernel);

  // Invalidates eroded pixels in place; `rejected` = 255 where a valid pixel became invalid.
  void apply(cv::Mat1f& disparity, cv::Mat1b& rejected);

 private:
  cv::Mat structuring_element_;
  cv::Mat1f lowest_;
  cv::Mat1f highest_;
};

}  // namespace stereonav
