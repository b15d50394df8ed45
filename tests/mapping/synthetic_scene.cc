#include "synthetic_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stereonav::testing {
namespace {

constexpr double kLatticeM = 0.03;
constexpr uint8_t kFloorGrey = 90;
constexpr uint8_t kSkyGrey = 200;

uint32_t hash(uint32_t a, uint32_t b, uint32_t c) {
  uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u ^ (c + 0x165667B1u) * 0xC2B2AE3Du;
  h ^= h >> 15;
  h *= 0x2C1B3C6Du;
  h ^= h >> 12;
  h *= 0x297A2D39u;
  h ^= h >> 15;
  return h;
}

}  // namespace

SyntheticScene::SyntheticScene(std::vector<Wall> walls, uint32_t seed)
    : walls_(std::move(walls)), seed_(seed) {}

double SyntheticScene::brightness(size_t wall, double along, double up) const {
  // Bilinear value noise: random grey levels on the lattice, interpolated.
  const double u = along / kLatticeM, v = up / kLatticeM;
  const double fu = std::floor(u), fv = std::floor(v);
  const double tu = u - fu, tv = v - fv;
  const auto value = [&](double i, double j) {
    return static_cast<double>(hash(seed_ + static_cast<uint32_t>(wall), static_cast<uint32_t>(static_cast<int64_t>(i)),
                                    static_cast<uint32_t>(static_cast<int64_t>(j))) & 0xFF);
  };
  const double top = value(fu, fv + 1) * (1 - tu) + value(fu + 1, fv + 1) * tu;
  const double bottom = value(fu, fv) * (1 - tu) + value(fu + 1, fv) * tu;
  return 40.0 + 0.7 * (bottom * (1 - tv) + top * tv);
}

cv::Mat1b SyntheticScene::render(const mrpt::poses::CPose3D& optical_pose,
                                 const PinholeCamera& camera) const {
  const auto rotation = optical_pose.getRotationMatrix();
  const double ox = optical_pose.x(), oy = optical_pose.y(), oz = optical_pose.z();
  cv::Mat1b image(camera.height, camera.width);
  for (int row = 0; row < camera.height; ++row) {
    for (int col = 0; col < camera.width; ++col) {
      const double rx = (col - camera.cx) / camera.focal_px, ry = (row - camera.cy) / camera.focal_px;
      const double dx = rotation(0, 0) * rx + rotation(0, 1) * ry + rotation(0, 2);
      const double dy = rotation(1, 0) * rx + rotation(1, 1) * ry + rotation(1, 2);
      const double dz = rotation(2, 0) * rx + rotation(2, 1) * ry + rotation(2, 2);
      double nearest = std::numeric_limits<double>::infinity();
      double grey = dz < 0.0 ? kFloorGrey : kSkyGrey;
      for (size_t w = 0; w < walls_.size(); ++w) {
        const Wall& wall = walls_[w];
        const double ex = wall.x1 - wall.x0, ey = wall.y1 - wall.y0;
        const double denominator = dx * ey - dy * ex;
        if (std::abs(denominator) < 1e-12) continue;
        const double t = ((wall.x0 - ox) * ey - (wall.y0 - oy) * ex) / denominator;
        const double s = ((wall.x0 - ox) * dy - (wall.y0 - oy) * dx) / denominator;
        if (t <= 0.0 || t >= nearest || s < 0.0 || s > 1.0) continue;
        const double z = oz + t * dz;
        if (z < 0.0 || z > wall.height) continue;
        nearest = t;
        grey = brightness(w, s * std::hypot(ex, ey), z);
      }
      image(row, col) = cv::saturate_cast<uint8_t>(grey);
    }
  }
  return image;
}

RigFrame SyntheticScene::renderFrame(const CameraRig& rig, const mrpt::poses::CPose2D& robot_pose,
                                     mrpt::system::TTimeStamp timestamp) const {
  RigFrame frame;
  frame.timestamp = timestamp;
  frame.rig = rig;
  frame.odometry = robot_pose;
  const mrpt::poses::CPose3D reference = mrpt::poses::CPose3D(robot_pose) + rig.pose_on_robot;
  frame.reference = render(reference, rig.reference);
  for (const SecondaryCamera& secondary : rig.secondaries) {
    const mrpt::poses::CPose3D offset(secondary.bx * rig.baseline_m, secondary.by * rig.baseline_m,
                                      0.0, 0.0, 0.0, 0.0);
    frame.secondaries.push_back(render(reference + offset, rig.reference));
  }
  return frame;
}

double SyntheticScene::rangeToWall(double x, double y, double heading) const {
  const double dx = std::cos(heading), dy = std::sin(heading);
  double nearest = std::numeric_limits<double>::infinity();
  for (const Wall& wall : walls_) {
    const double ex = wall.x1 - wall.x0, ey = wall.y1 - wall.y0;
    const double denominator = dx * ey - dy * ex;
    if (std::abs(denominator) < 1e-12) continue;
    const double t = ((wall.x0 - x) * ey - (wall.y0 - y) * ex) / denominator;
    const double s = ((wall.x0 - x) * dy - (wall.y0 - y) * dx) / denominator;
    if (t > 0.0 && s >= 0.0 && s <= 1.0) nearest = std::min(nearest, t);
  }
  return nearest;
}

CameraRig testRig() {
  CameraRig rig;  // the defaults are exactly the rig described in the header
  rig.secondaries = {{-1.0, 0.0}, {0.0, -1.0}};
  rig.pose_on_robot = CameraRig::opticalPoseOnRobot(0.0, 0.0, 0.5, 0.0, 0.0);
  return rig;
}

}  // namespace stereonav::testing
