// Writes rawlogs/sample_trinocular.rawlog: a short trinocular run through a synthetic office
// room (tests/mapping/synthetic_scene.h) with odometry, for scripts/demo and for trying
// `stereonav map` without recording anything:
//   make_sample_rawlog OUT.rawlog
// The robot drives a loop through a room 8 m x 6 m with a low desk, a pillar and a partition,
// 0.35 m per frame, turning on the spot 45 degrees per frame at the corners. 320x240 Triclops-L
// rig as in ini/sample_trinocular.ini, 5 frames per second (paper abstract: 5 Hz), Gaussian
// pixel noise of 2 grey levels per camera so that the matcher makes some mistakes to remove.

#include <cmath>
#include <iostream>
#include <opencv2/core.hpp>

#include "observations/rawlog_writer.h"
#include "synthetic_scene.h"

namespace {

using stereonav::testing::Wall;

std::vector<Wall> box(double x0, double y0, double x1, double y1, double height) {
  return {Wall{x0, y0, x1, y0, height}, Wall{x1, y0, x1, y1, height}, Wall{x1, y1, x0, y1, height},
          Wall{x0, y1, x0, y0, height}};
}

std::vector<Wall> office() {
  std::vector<Wall> walls = box(-1.0, -3.0, 7.0, 3.0, 2.5);  // the room
  walls.push_back(Wall{4.5, -3.0, 4.5, -1.2, 2.5});           // a partition
  for (const auto& part : box(2.6, 0.8, 3.4, 1.4, 0.75)) walls.push_back(part);   // a desk
  for (const auto& part : box(1.85, -1.35, 2.15, -1.05, 2.5)) walls.push_back(part);  // a pillar
  return walls;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_sample_rawlog OUT.rawlog\n";
    return 2;
  }
  try {
    const stereonav::testing::SyntheticScene scene(office());
    const stereonav::CameraRig rig = stereonav::testing::testRig();
    stereonav::RawlogWriterOptions options;
    options.compression_level = 9;
    stereonav::RawlogWriter writer(argv[1], options);
    constexpr double kFrameRate = 5.0;
    constexpr double kStep = 0.35;  // metres per frame: 1.75 m/s
    constexpr double kNoiseSigma = 2.0;
    double time = 0.0;
    cv::RNG noise(1);
    const auto record = [&](const mrpt::poses::CPose2D& pose) {
      stereonav::RigFrame frame = scene.renderFrame(rig, pose, mrpt::Clock::fromDouble(1.7e9 + time));
      for (cv::Mat* image : {&frame.reference, &frame.secondaries[0], &frame.secondaries[1]}) {
        cv::Mat1s deviation(image->size());
        noise.fill(deviation, cv::RNG::NORMAL, 0.0, kNoiseSigma);
        cv::Mat1s noisy;
        image->convertTo(noisy, CV_16S);
        noisy += deviation;
        noisy.convertTo(*image, CV_8U);  // saturates
      }
      writer.write(frame);
      time += 1.0 / kFrameRate;
    };
    // Straight legs between the corners of the loop, then a quarter turn to the left at each.
    const double corners[][2] = {{0.0, 0.0}, {4.9, 0.0}, {4.9, 2.1}, {0.0, 2.1}, {0.0, 0.0}};
    for (int leg = 0; leg < 4; ++leg) {
      const double heading = leg * M_PI / 2;
      const double length = std::hypot(corners[leg + 1][0] - corners[leg][0], corners[leg + 1][1] - corners[leg][1]);
      const int steps = static_cast<int>(std::lround(length / kStep));
      for (int i = 0; i < steps; ++i) {
        record({corners[leg][0] + std::cos(heading) * kStep * i, corners[leg][1] + std::sin(heading) * kStep * i,
                heading});
      }
      for (int i = 0; i < 2; ++i) {
        record({corners[leg + 1][0], corners[leg + 1][1], heading + M_PI / 4 * i});
      }
    }
    writer.finish();
    std::cout << "wrote " << writer.framesWritten() << " frames to " << argv[1] << "\n";
    return 0;
  } catch (const std::exception& error) {
    std::cerr << "make_sample_rawlog: " << error.what() << "\n";
    return 1;
  }
}
