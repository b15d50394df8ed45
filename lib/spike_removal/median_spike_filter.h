#pragma once

#include <opencv2/core.hpp>

namespace stereonav {

// Median filtering of the disparity image, one of the filters paper section 4.1 compares with
// surface segmentation (it smooths isolated noise but keeps coherent mismatch patches and wipes
// out structures thinner than half the kernel).
//
// Invalid pixels (+inf) take part in cv::medianBlur as values above every disparity, then:
//  - a pixel invalid on input stays invalid (the filter never invents data where the matcher
//    found none);
//  - a valid pixel whose neighbourhood is mostly invalid gets an invalid median and is rejected,
//    which is what removes an isolated spike surrounded by invalid pixels.
// The flip side: at the border of valid data the median leans towards larger disparities.
class MedianSpikeFilter {
 public:
  // kernel: 3 or 5 (the sizes cv::medianBlur accepts for float images).
  explicit MedianSpikeFilter(int kernel);

  // Filters `disparity` in place; `rejected` = 255 where a valid pixel became invalid, else 0.
  void apply(cv::Mat1f& disparity, cv::Mat1b& rejected);

 private:
  int kernel_;
  cv::Mat1f filtered_;
};

}  // namespace stereonav
