#include "disparity/opencv_matchers.h"

#include <opencv2/calib3d.hpp>

#include <cmath>
#include <stdexcept>

#include "disparity/disparity_image.h"

namespace stereonav {
namespace {

// How to turn the rig so that the secondary camera becomes OpenCV's right camera (a point at
// disparity d at x in the reference is at x - d in it).
struct Orientation {
  bool transpose = false;
  bool flip = false;  // horizontally, after transposing
};

Orientation orientationFor(const SecondaryCamera& camera) {
  if (camera.by == 0.0 && camera.bx == 1.0) return {false, false};
  if (camera.by == 0.0 && camera.bx == -1.0) return {false, true};
  if (camera.bx == 0.0 && camera.by == 1.0) return {true, false};
  if (camera.bx == 0.0 && camera.by == -1.0) return {true, true};
  throw std::invalid_argument(
      "OpenCV stereo backends need a binocular rig with baseline (1,0), (-1,0), (0,1) or (0,-1)");
}

cv::Mat arrange(const cv::Mat& image, const Orientation& orientation) {
  cv::Mat result = image;
  if (orientation.transpose) cv::transpose(image, result);
  if (orientation.flip) cv::flip(result.clone(), result, 1);
  return result;
}

cv::Mat restore(const cv::Mat& image, const Orientation& orientation) {
  cv::Mat result = image;
  if (orientation.flip) cv::flip(image, result, 1);
  if (orientation.transpose) cv::transpose(result.clone(), result);
  return result;
}

cv::Ptr<cv::StereoMatcher> createMatcher(const StereoOptions& options, int disparity_range) {
  const int disp12_max_diff =
      options.left_right_check ? static_cast<int>(std::ceil(options.left_right_max_diff)) : -1;
  if (options.backend == StereoBackend::kOpenCvBm) {
    if (options.window < 5) throw std::invalid_argument("[stereo] window: cv::StereoBM needs a window >= 5");
    auto bm = cv::StereoBM::create(disparity_range, options.window);
    bm->setPreFilterType(options.prefilter == Prefilter::kXSobel ? cv::StereoBM::PREFILTER_XSOBEL
                                                                 : cv::StereoBM::PREFILTER_NORMALIZED_RESPONSE);
    bm->setPreFilterCap(std::min(options.prefilter_cap, 63));
    bm->setTextureThreshold(options.opencv_texture_threshold);
    bm->setUniquenessRatio(options.opencv_uniqueness_ratio);
    bm->setMinDisparity(options.min_disparity);
    bm->setSpeckleWindowSize(options.opencv_speckle_window);
    bm->setSpeckleRange(options.opencv_speckle_range);
    bm->setDisp12MaxDiff(disp12_max_diff);
    return bm;
  }
  const int area = options.window * options.window;
  return cv::StereoSGBM::create(options.min_disparity, disparity_range, options.window, 8 * area, 32 * area,
                                disp12_max_diff, std::min(options.prefilter_cap, 63),
                                options.opencv_uniqueness_ratio, options.opencv_speckle_window,
                                options.opencv_speckle_range, cv::StereoSGBM::MODE_SGBM);
}

}  // namespace

cv::Mat1f matchOpenCv(const StereoFrame& frame, const StereoOptions& options) {
  checkStereoFrame(frame);
  if (frame.secondaries.size() != 1) {
    throw std::invalid_argument(std::string("[stereo] backend ") + toString(options.backend) +
                                ": OpenCV's matchers take exactly one secondary camera, the rig has " +
                                std::to_string(frame.secondaries.size()) + " (use backend = sad)");
  }
  const Orientation orientation = orientationFor(frame.secondaries.front().camera);
  // OpenCV searches a multiple of 16 disparities; candidates above max_disparity are discarded.
  const int disparity_range = (options.disparityCount() + 15) / 16 * 16;
  cv::Mat fixed_point;  // CV_16S, 16 * disparity
  createMatcher(options, disparity_range)
      ->compute(arrange(frame.reference, orientation), arrange(frame.secondaries.front().image, orientation),
                fixed_point);
  const cv::Mat turned_back = restore(fixed_point, orientation);
  cv::Mat1f disparity(turned_back.size());
  for (int y = 0; y < disparity.rows; ++y) {
    const short* in = turned_back.ptr<short>(y);
    float* out = disparity.ptr<float>(y);
    for (int x = 0; x < disparity.cols; ++x) {
      float d = in[x] / 16.0f;
      if (!options.subpixel) d = std::round(d);
      const bool found = in[x] >= options.min_disparity * 16 && d <= options.max_disparity;
      out[x] = found ? d : kInvalidDisparity;
    }
  }
  return disparity;
}

}  // namespace stereonav
