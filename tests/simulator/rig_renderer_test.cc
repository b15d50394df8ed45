#include "simulator/rig_renderer.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "disparity/disparity_image.h"
#include "simulator/moving_traffic.h"
#include "world_text.h"

namespace stereonav {
namespace {

// 160 x 120 with f = 100 px, B = 0.1 m, looking along the robot's x axis from 0.5 m up.
CameraRig smallRig() {
  CameraRig rig;
  rig.reference = {160, 120, 100.0, 79.5, 59.5};
  rig.baseline_m = 0.1;
  rig.secondaries = {{-1.0, 0.0}, {0.0, -1.0}};
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(0.0, 0.0, 0.5, 0.0, 0.0);
  return rig;
}

SensorOptions noiseless() {
  SensorOptions sensor;
  sensor.noise_sigma = 0.0;
  return sensor;
}

float bilinear(const cv::Mat1b& image, double x, double y) {
  const int x0 = static_cast<int>(std::floor(x));
  const int y0 = static_cast<int>(std::floor(y));
  const double ax = x - x0;
  const double ay = y - y0;
  const auto at = [&](int xx, int yy) { return static_cast<double>(image(yy, xx)); };
  return static_cast<float>((1 - ay) * ((1 - ax) * at(x0, y0) + ax * at(x0 + 1, y0)) +
                            ay * ((1 - ax) * at(x0, y0 + 1) + ax * at(x0 + 1, y0 + 1)));
}

TEST(RigRenderer, TrueDisparityOfAFrontoParallelWallAndTheFloorIsFBOverZ) {
  // Wall face at x = 3 (centre line 3.05, 0.1 thick), tall enough to fill the upper image.
  const World world = worldFromText("[wall.w]\npoints = 3.05 -50; 3.05 50\nheight = 50\n");
  RigRenderer renderer(world, smallRig(), noiseless());
  const RigImages images = renderer.render(mrpt::poses::CPose2D(0, 0, 0), 0.0, {});
  ASSERT_EQ(images.true_disparity.size(), cv::Size(160, 120));
  const double f = 100.0, baseline = 0.1, camera_height = 0.5, cy = 59.5;
  for (int y = 0; y < 120; ++y) {
    // A row below the horizon meets the floor at depth Z = h f / (y - cy), unless the wall at
    // Z = 3 comes first.
    const double floor_depth = y > cy ? camera_height * f / (y - cy) : INFINITY;
    const double depth = std::min(3.0, floor_depth);
    for (int x = 0; x < 160; ++x) {
      ASSERT_NEAR(images.true_disparity(y, x), f * baseline / depth, 1e-4) << x << "," << y;
    }
  }
}

TEST(RigRenderer, NothingHitIsInvalidDisparity) {
  const World world = worldFromText("[box.b]\ncenter = 3 0\nsize = 1 1\nheight = 1\n");
  RigRenderer renderer(world, smallRig(), noiseless());
  const RigImages images = renderer.render(mrpt::poses::CPose2D(0, 0, 0), 0.0, {});
  // The top row looks up into the empty sky; the centre sees the box at 2.5 m.
  for (int x = 0; x < 160; ++x) EXPECT_FALSE(isValidDisparity(images.true_disparity(0, x)));
  EXPECT_NEAR(images.true_disparity(59, 79), 10.0 / 2.5, 1e-4);
}

TEST(RigRenderer, SecondaryImagesAgreeWithTheTrueDisparity) {
  const World world = loadWorld(worldsDirectory() + "/office.ini");
  SensorOptions sensor;
  sensor.noise_sigma = 1.0;
  const CameraRig rig = smallRig();
  RigRenderer renderer(world, rig, sensor);
  const mrpt::poses::CPose2D robot(world.start_pose[0], world.start_pose[1], world.start_pose[2]);
  const RigImages images = renderer.render(robot, 0.0, {});
  const mrpt::poses::CPose3D reference = mrpt::poses::CPose3D(robot) + rig.pose_on_robot;
  for (size_t i = 0; i < rig.secondaries.size(); ++i) {
    SCOPED_TRACE(i);
    const SecondaryCamera& offset = rig.secondaries[i];
    const mrpt::poses::CPose3D secondary =
        reference + mrpt::poses::CPose3D(offset.bx * rig.baseline_m, offset.by * rig.baseline_m, 0, 0, 0, 0);
    std::vector<double> differences, wrong_differences;
    for (int y = 2; y < 118; y += 3) {
      for (int x = 2; x < 158; x += 3) {
        const float d = images.true_disparity(y, x);
        if (!isValidDisparity(d)) continue;
        // The reference pixel's scene point, reprojected into the secondary camera.
        const double depth = rig.depthForDisparity(d);
        const mrpt::math::TPoint3D in_reference((x - rig.reference.cx) * depth / rig.reference.focal_px,
                                                (y - rig.reference.cy) * depth / rig.reference.focal_px, depth);
        const mrpt::math::TPoint3D in_secondary = secondary.inverseComposePoint(reference.composePoint(in_reference));
        const double sx = rig.reference.cx + rig.reference.focal_px * in_secondary.x / in_secondary.z;
        const double sy = rig.reference.cy + rig.reference.focal_px * in_secondary.y / in_secondary.z;
        ASSERT_NEAR(sx, x - offset.bx * d, 1e-6);
        ASSERT_NEAR(sy, y - offset.by * d, 1e-6);
        const double wrong_x = sx - offset.bx * 3.0;
        const double wrong_y = sy - offset.by * 3.0;
        if (std::min(sx, wrong_x) < 0 || std::max(sx, wrong_x) > 158 || std::min(sy, wrong_y) < 0 ||
            std::max(sy, wrong_y) > 118) {
          continue;
        }
        differences.push_back(std::abs(images.reference(y, x) - bilinear(images.secondaries[i], sx, sy)));
        wrong_differences.push_back(
            std::abs(images.reference(y, x) - bilinear(images.secondaries[i], wrong_x, wrong_y)));
      }
    }
    ASSERT_GT(differences.size(), 500u);
    std::sort(differences.begin(), differences.end());
    std::sort(wrong_differences.begin(), wrong_differences.end());
    const double median = differences[differences.size() / 2];
    const double wrong_median = wrong_differences[wrong_differences.size() / 2];
    // Noise of sigma 1 on both pixels gives a median |difference| near 1; interpolation adds some.
    EXPECT_LT(median, 3.0);
    EXPECT_GT(wrong_median, 3.0 * median);
  }
}

TEST(RigRenderer, IntegerDisparityPixelsMatchExactlyWithoutNoise) {
  // Wall at Z = 2.5 m: d = 100 * 0.1 / 2.5 = 4 px, so the secondary pixel lies on the grid.
  const World world = worldFromText("[wall.w]\npoints = 2.55 -50; 2.55 50\nheight = 50\n");
  RigRenderer renderer(world, smallRig(), noiseless());
  const RigImages images = renderer.render(mrpt::poses::CPose2D(0, 0, 0), 0.0, {});
  int compared = 0;
  for (int y = 10; y < 60; ++y) {
    for (int x = 10; x < 150; ++x) {
      ASSERT_FLOAT_EQ(images.true_disparity(y, x), 4.0f);
      EXPECT_NEAR(images.reference(y, x), images.secondaries[0](y, x + 4), 1) << x << "," << y;
      EXPECT_NEAR(images.reference(y, x), images.secondaries[1](y + 4, x), 1) << x << "," << y;
      ++compared;
    }
  }
  EXPECT_GT(compared, 5000);
  // And the wall is textured, not blank.
  cv::Scalar mean, deviation;
  cv::meanStdDev(images.reference(cv::Rect(10, 10, 140, 50)), mean, deviation);
  EXPECT_GT(deviation[0], 10.0);
}

TEST(RigRenderer, DetailFinerThanAPixelIsAveragedNotAliased) {
  // 1 cm stripes 5 m away: a pixel covers 5 cm, five periods. Point sampling would alias them
  // into a moire of full contrast (0.2 .. 0.8 albedo) that changes with every small motion.
  const World world = worldFromText(
      "[texture.fine]\ntype = stripes\nperiod_m = 0.01\nmean = 0.5\ncontrast = 0.3\n"
      "[wall.w]\npoints = 5.05 -50; 5.05 50\nheight = 50\ntexture = fine\n");
  RigRenderer renderer(world, smallRig(), noiseless());
  const cv::Rect wall(0, 0, 160, 55);
  for (double y : {0.0, 0.003, 0.0071}) {
    const RigImages images = renderer.render(mrpt::poses::CPose2D(0, y, 0), 0.0, {});
    cv::Scalar mean, deviation;
    cv::meanStdDev(images.reference(wall), mean, deviation);
    EXPECT_LT(deviation[0], 1.0) << "camera at y = " << y;
  }
}

TEST(RigRenderer, NoiseIsSeededAndHasTheRequestedDeviation) {
  const World world = worldFromText("[wall.w]\npoints = 2.55 -50; 2.55 50\nheight = 50\n");
  SensorOptions first;
  first.noise_sigma = 3.0;
  first.seed = 11;
  SensorOptions second = first;
  second.seed = 12;
  const mrpt::poses::CPose2D pose(0, 0, 0);
  const RigImages a = RigRenderer(world, smallRig(), first).render(pose, 0.0, {});
  const RigImages again = RigRenderer(world, smallRig(), first).render(pose, 0.0, {});
  const RigImages b = RigRenderer(world, smallRig(), second).render(pose, 0.0, {});
  EXPECT_EQ(cv::norm(a.reference, again.reference, cv::NORM_INF), 0.0);
  cv::Mat1f difference;
  cv::subtract(a.reference, b.reference, difference, cv::noArray(), CV_32F);
  cv::Scalar mean, deviation;
  cv::meanStdDev(difference, mean, deviation);
  // Two independent draws of sigma 3 (plus rounding): sigma 3 sqrt(2) = 4.24.
  EXPECT_NEAR(deviation[0], 3.0 * std::sqrt(2.0), 0.3);
  EXPECT_NEAR(mean[0], 0.0, 0.1);
}

TEST(RigRenderer, LightingChangesBrightnessOverTime) {
  const World world = worldFromText(
      "[world]\nlighting_change = 0.2\nlighting_period_s = 4\n"
      "[texture.grey]\ntype = paint\nmean = 0.4\n[wall.w]\npoints = 2.55 -50; 2.55 50\nheight = 50\n"
      "texture = grey\n");
  RigRenderer renderer(world, smallRig(), noiseless());
  // The upper half of the image sees only the painted wall.
  const cv::Rect wall(0, 0, 160, 60);
  const double at_zero = cv::mean(renderer.render(mrpt::poses::CPose2D(0, 0, 0), 0.0, {}).reference(wall))[0];
  const double at_peak = cv::mean(renderer.render(mrpt::poses::CPose2D(0, 0, 0), 1.0, {}).reference(wall))[0];
  EXPECT_NEAR(at_peak / at_zero, 1.2, 0.01);
}

TEST(RigRenderer, MovingObstaclesAreRenderedWhereTheTrafficHasThem) {
  // A person (r = 0.25) walking from y = -2 to y = 2 along x = 3 at 1 m/s, in front of a wall at 6.
  const World world = worldFromText(
      "[wall.w]\npoints = 6.05 -50; 6.05 50\nheight = 50\n"
      "[moving.person]\nshape = cylinder\nradius = 0.25\npath = 3 -2; 3 2\nspeed = 1\n");
  RigRenderer renderer(world, smallRig(), noiseless());
  const mrpt::poses::CPose2D pose(0, 0, 0);
  MovingTraffic traffic(world);
  EXPECT_NEAR(renderer.render(pose, 0.0, traffic.solids()).true_disparity(59, 79), 10.0 / 6.0, 1e-3);
  // At t = 2 s the person stands on the optical axis: its surface is at 3 - 0.25.
  traffic.advance(2.0, pose, 0.0, 0.3);
  EXPECT_NEAR(renderer.render(pose, 2.0, traffic.solids()).true_disparity(59, 79), 10.0 / 2.75, 1e-3);
}

TEST(RigRenderer, PoseOfTheRobotMovesTheView) {
  // Turning the robot left by 90 degrees in front of a wall at y = 4 sees it at Z = 4.
  const World world = worldFromText("[wall.w]\npoints = -50 4.05; 50 4.05\nheight = 50\n");
  RigRenderer renderer(world, smallRig(), noiseless());
  const RigImages images = renderer.render(mrpt::poses::CPose2D(1.0, 0.0, M_PI / 2), 0.0, {});
  EXPECT_NEAR(images.true_disparity(30, 79), 10.0 / 4.0, 1e-4);
}

TEST(RigRenderer, ARobotStandingStillSeesWhatAFreshRendererSeesWhateverMoves) {
  // The robot stands at the origin facing a wall at x = 6 while a person (r = 0.25) walks behind
  // it, steps onto the optical axis at x = 3 and back out of view. The renderer traces again only
  // when something changes in view; every frame must equal a fresh renderer's.
  const World world = worldFromText("[wall.w]\npoints = 6.05 -50; 6.05 50\nheight = 50\n");
  const mrpt::poses::CPose2D pose(0, 0, 0);
  const auto person = [](double x, double y) { return std::vector<Solid>{Solid::cylinder(x, y, 0.25, 0.0, 1.8, 0)}; };
  const std::vector<std::vector<Solid>> frames = {person(-3, 0), person(-3, 1), person(3, 0), person(-3, 1), person(-3, 1)};
  const auto same = [](const cv::Mat& a, const cv::Mat& b) { return cv::countNonZero(a != b) == 0; };
  RigRenderer standing(world, smallRig(), noiseless());
  for (size_t i = 0; i < frames.size(); ++i) {
    const RigImages seen = standing.render(pose, 0.0, frames[i]);
    RigRenderer fresh(world, smallRig(), noiseless());
    const RigImages expected = fresh.render(pose, 0.0, frames[i]);
    EXPECT_TRUE(same(seen.reference, expected.reference)) << "frame " << i;
    EXPECT_TRUE(same(seen.true_disparity, expected.true_disparity)) << "frame " << i;
    ASSERT_EQ(seen.secondaries.size(), 2u);
    for (size_t j = 0; j < seen.secondaries.size(); ++j) {
      EXPECT_TRUE(same(seen.secondaries[j], expected.secondaries[j])) << "frame " << i << ", camera " << j;
    }
    // On the optical axis the wall, or the person's front at 3 - 0.25 m.
    EXPECT_NEAR(seen.true_disparity(59, 79), i == 2 ? 10.0 / 2.75 : 10.0 / 6.0, 1e-3) << "frame " << i;
  }
}

}  // namespace
}  // namespace stereonav
