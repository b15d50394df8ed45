#include "rectification/stereo_rectifier.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "synthetic_heads.h"

namespace stereonav {
namespace {

// After rectification every scene point must sit at (x - bx d, y - by d) in secondary k, with one
// disparity d per point: the rig's model (rig/camera_rig.h) that the matcher relies on.
void expectRigModelHolds(const RigCalibration& head) {
  const StereoRectifier rectifier(head);
  const CameraRig& rig = rectifier.rig();
  ASSERT_EQ(rig.secondaries.size(), head.cameras.size() - 1);
  EXPECT_NEAR(std::abs(rig.secondaries[0].bx), 1.0, 1e-9);
  EXPECT_NEAR(rig.secondaries[0].by, 0.0, 1e-9);
  EXPECT_NEAR(rig.baseline_m, cv::norm(head.cameras[1].centreInReference()), 1e-12);
  double worst = 0.0;
  for (const cv::Vec3d& point : scenePoints(200)) {
    std::vector<cv::Point2f> rectified;
    for (size_t k = 0; k < head.cameras.size(); ++k) {
      rectified.push_back(rectifier.rectifyPoints(k, {projectRaw(head.cameras[k], point)})[0]);
    }
    const double d = (rectified[0].x - rectified[1].x) / rig.secondaries[0].bx;
    EXPECT_GT(d, 0.0);
    for (size_t k = 1; k < head.cameras.size(); ++k) {
      const SecondaryCamera& camera = rig.secondaries[k - 1];
      worst = std::max({worst, std::abs(rectified[0].x - camera.bx * d - rectified[k].x),
                        std::abs(rectified[0].y - camera.by * d - rectified[k].y)});
    }
  }
  // undistortPoints iterates; 0.02 px is far below what the matcher resolves.
  EXPECT_LT(worst, 0.02);
}

TEST(StereoRectifierTest, BinocularHeadWithDistortionAndATurnedPartnerMeetsTheRigModel) {
  expectRigModelHolds(rawBinocularHead());
}

TEST(StereoRectifierTest, LShapedTrinocularHeadMeetsTheRigModelForBothPartners) {
  const RigCalibration head = rawLShapedHead();
  expectRigModelHolds(head);
  const StereoRectifier rectifier(head);
  const CameraRig& rig = rectifier.rig();
  // Reference = right camera: the partner on the left (bx = -1), the third one above (by < 0) and,
  // its baselines not quite square, a little along x as well.
  EXPECT_NEAR(rig.secondaries[0].bx, -1.0, 1e-9);
  EXPECT_NEAR(rig.secondaries[1].by, -1.0, 0.05);
  EXPECT_NEAR(rig.secondaries[1].bx, 0.0, 0.1);
}

TEST(StereoRectifierTest, DepthFollowsTheRectifiedFocalLengthAndBaseline) {
  const RigCalibration head = rawBinocularHead();
  const StereoRectifier rectifier(head);
  // A point straight ahead at 3 m: d = f B / Z up to the small turn of the rectified frame.
  const cv::Vec3d point(0.06, 0.0, 3.0);
  const auto left = rectifier.rectifyPoints(0, {projectRaw(head.cameras[0], point)})[0];
  const auto right = rectifier.rectifyPoints(1, {projectRaw(head.cameras[1], point)})[0];
  const double depth = rectifier.rig().depthForDisparity(left.x - right.x);
  EXPECT_NEAR(depth, 3.0, 0.03);
}

TEST(StereoRectifierTest, RectifiedImagesShowAScenePointOnOneRow) {
  // A bright dot drawn where the point falls in each raw image comes out on one rectified row.
  const RigCalibration head = rawBinocularHead();
  const StereoRectifier rectifier(head);
  const cv::Vec3d point(-0.3, 0.4, 2.5);
  std::vector<cv::Mat> raw;
  for (const auto& camera : head.cameras) {
    cv::Mat image(camera.size, CV_8UC1, cv::Scalar(0));
    const cv::Point2f centre = projectRaw(camera, point);
    constexpr int kShift = 4;  // sub-pixel centre: 1/16 px
    cv::circle(image, cv::Point(cvRound(centre.x * 16), cvRound(centre.y * 16)), 4 * 16,
               cv::Scalar(255), cv::FILLED, cv::LINE_AA, kShift);
    raw.push_back(image);
  }
  const std::vector<cv::Mat> rectified = rectifier.rectify(raw);
  ASSERT_EQ(rectified.size(), 2u);
  std::vector<double> rows;
  for (const cv::Mat& image : rectified) {
    const cv::Moments m = cv::moments(image);
    ASSERT_GT(m.m00, 0.0);
    rows.push_back(m.m01 / m.m00);
  }
  EXPECT_NEAR(rows[0], rows[1], 0.1);
}

TEST(StereoRectifierTest, RectifiedCalibrationPassesThroughUnchanged) {
  RigCalibration head;
  head.cameras = {rawCamera(400, 400, 320, 240, {}), rawCamera(400, 400, 320, 240, {})};
  head.cameras[1].translation = {-0.2, 0, 0};
  ASSERT_TRUE(isRectified(head));
  const CameraRig rig = rigOfRectifiedCalibration(head);
  EXPECT_DOUBLE_EQ(rig.baseline_m, 0.2);
  EXPECT_DOUBLE_EQ(rig.secondaries[0].bx, 1.0);
  EXPECT_DOUBLE_EQ(rig.reference.cx, 320.0);
  EXPECT_FALSE(isRectified(rawBinocularHead()));
}

TEST(StereoRectifierTest, SaysWhyAHeadCannotBeRectified) {
  const auto message = [](const RigCalibration& head) {
    try {
      StereoRectifier rectifier(head);
    } catch (const RectificationError& e) {
      return std::string(e.what());
    }
    return std::string("not rejected");
  };
  RigCalibration zero_baseline = rawBinocularHead();
  zero_baseline.cameras[1].translation = {0, 0, 0};
  EXPECT_NE(message(zero_baseline).find("zero baseline"), std::string::npos);

  RigCalibration collinear = rawLShapedHead();
  collinear.cameras[2] = placed(collinear.cameras[2], {0, 0, 0}, {-0.2, 0.001, 0});
  EXPECT_NE(message(collinear).find("one line"), std::string::npos);

  RigCalibration sideways = rawBinocularHead();
  sideways.cameras[1] = placed(sideways.cameras[1], {0, 1.8, 0}, {0.12, 0, 0});
  EXPECT_NE(message(sideways).find("degrees away"), std::string::npos);

  RigCalibration no_focal = rawBinocularHead();
  no_focal.cameras[0].camera_matrix(0, 0) = 0;
  EXPECT_NE(message(no_focal).find("no focal length"), std::string::npos);
}

}  // namespace
}  // namespace stereonav
