#pragma once

#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/system/datetime.h>

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "observations/rig_frame.h"
#include "support/scratch_directory.h"

namespace stereonav {

// Tiny rigs and frames for the rawlog tests. Pixels are random so that a swapped, shifted or
// re-encoded image cannot pass for the original.

inline CameraRig sampleRig(std::vector<SecondaryCamera> secondaries) {
  CameraRig rig;
  rig.reference = {64, 48, 50.0, 31.5, 23.5};
  rig.baseline_m = 0.1;
  rig.secondaries = std::move(secondaries);
  rig.pose_on_robot =
      CameraRig::opticalPoseOnRobot(0.2, 0.05, 0.8, mrpt::DEG2RAD(5.0), mrpt::DEG2RAD(10.0));
  return rig;
}
// Triclops L: reference = right camera, left and top secondaries (paper section 2.1).
inline CameraRig triclopsRig() { return sampleRig({{-1.0, 0.0}, {0.0, -1.0}}); }
// Binocular head: reference = left camera.
inline CameraRig binocularRig() { return sampleRig({{1.0, 0.0}}); }

// `count` frames 0.1 s apart; with odometry every frame but each third, to show that a frame
// without odometry stays without it and the next one gets its own absolute pose back.
inline std::vector<RigFrame> sampleFrames(const CameraRig& rig, size_t count, int type = CV_8UC1) {
  cv::RNG random(1234);
  std::vector<RigFrame> frames(count);
  for (size_t i = 0; i < count; ++i) {
    RigFrame& frame = frames[i];
    frame.rig = rig;
    frame.timestamp = mrpt::Clock::fromDouble(1.7e9 + 0.1 * static_cast<double>(i));
    const auto image = [&] {
      cv::Mat pixels(rig.reference.height, rig.reference.width, type);
      random.fill(pixels, cv::RNG::UNIFORM, 0, 256);
      return pixels;
    };
    frame.reference = image();
    for (size_t k = 0; k < rig.secondaries.size(); ++k) frame.secondaries.push_back(image());
    if (i % 3 != 2) {
      const double t = static_cast<double>(i);
      frame.odometry = mrpt::poses::CPose2D(0.3 * t, 0.05 * t * t, 0.1 * t);
    }
  }
  return frames;
}

inline bool samePixels(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

inline void expectSameRig(const CameraRig& expected, const CameraRig& actual) {
  constexpr double kTolerance = 1e-9;
  EXPECT_EQ(actual.reference.width, expected.reference.width);
  EXPECT_EQ(actual.reference.height, expected.reference.height);
  EXPECT_NEAR(actual.reference.focal_px, expected.reference.focal_px, kTolerance);
  EXPECT_NEAR(actual.reference.cx, expected.reference.cx, kTolerance);
  EXPECT_NEAR(actual.reference.cy, expected.reference.cy, kTolerance);
  EXPECT_NEAR(actual.baseline_m, expected.baseline_m, kTolerance);
  ASSERT_EQ(actual.secondaries.size(), expected.secondaries.size());
  for (size_t i = 0; i < expected.secondaries.size(); ++i) {
    EXPECT_NEAR(actual.secondaries[i].bx, expected.secondaries[i].bx, kTolerance) << i;
    EXPECT_NEAR(actual.secondaries[i].by, expected.secondaries[i].by, kTolerance) << i;
  }
  const auto difference = (actual.pose_on_robot - expected.pose_on_robot).asVectorVal();
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(difference[i], 0.0, kTolerance) << "pose component " << i;
}

inline void expectSameFrame(const RigFrame& expected, const RigFrame& actual) {
  EXPECT_EQ(actual.timestamp, expected.timestamp);
  EXPECT_TRUE(samePixels(actual.reference, expected.reference));
  ASSERT_EQ(actual.secondaries.size(), expected.secondaries.size());
  for (size_t i = 0; i < expected.secondaries.size(); ++i) {
    EXPECT_TRUE(samePixels(actual.secondaries[i], expected.secondaries[i])) << "secondary " << i;
  }
  expectSameRig(expected.rig, actual.rig);
  ASSERT_EQ(actual.odometry.has_value(), expected.odometry.has_value());
  if (expected.odometry) {
    EXPECT_NEAR(actual.odometry->x(), expected.odometry->x(), 1e-9);
    EXPECT_NEAR(actual.odometry->y(), expected.odometry->y(), 1e-9);
    EXPECT_NEAR(actual.odometry->phi(), expected.odometry->phi(), 1e-9);
  }
}

}  // namespace stereonav
