#pragma once

#include <opencv2/imgcodecs.hpp>

#include <string>

#include "disparity/disparity_evaluation.h"
#include "disparity/stereo_frame.h"

namespace stereonav::testing {

// The bundled Middlebury tsukuba views (tests/data/tsukuba/README.md): column 3 is the reference;
// a point at disparity d is at x - d in column 4, x - 2d in 5, x + d in 2 and x + 2d in 1.
inline cv::Mat1b tsukubaView(int column) {
  const std::string path =
      std::string(STEREONAV_TEST_DATA_DIR) + "/tsukuba/scene1.row3.col" + std::to_string(column) + ".ppm";
  return cv::imread(path, cv::IMREAD_GRAYSCALE);
}

inline cv::Mat1f tsukubaGroundTruth() {
  return loadMiddleburyGroundTruth(std::string(STEREONAV_TEST_DATA_DIR) + "/tsukuba/truedisp.row3.col3.pgm", 16.0);
}

inline StereoFrame tsukubaBinocular() { return {tsukubaView(3), {{tsukubaView(4), {1, 0}}}}; }

// The camera listed first is the one the left-right check uses.
inline StereoFrame tsukubaMultiBaseline() {
  return {tsukubaView(3),
          {{tsukubaView(4), {1, 0}}, {tsukubaView(1), {-2, 0}}, {tsukubaView(2), {-1, 0}}, {tsukubaView(5), {2, 0}}}};
}

}  // namespace stereonav::testing
