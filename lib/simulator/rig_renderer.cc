#include "simulator/rig_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "disparity/disparity_image.h"

namespace stereonav {
namespace {

// Matte surfaces under one distant light plus ambient light. Lambertian shading does not depend
// on the viewpoint, so all cameras of the rig see the same brightness at a scene point.
const Eigen::Vector3d kLightDirection = Eigen::Vector3d(0.4, 0.3, 0.87).normalized();
constexpr double kAmbient = 0.55;
constexpr double kDiffuse = 0.45;
// Brightness of rays that meet nothing (open sky above a ceiling-less world), grey levels.
constexpr double kEmptyBrightness = 140.0;
// Grazing views would have unbounded footprints; past this obliquity detail is simply gone.
constexpr double kMinimumCosine = 0.15;

bool sameSolid(const Solid& a, const Solid& b) {
  return a.shape == b.shape && a.x == b.x && a.y == b.y && a.half_x == b.half_x && a.half_y == b.half_y &&
         a.cos_yaw == b.cos_yaw && a.sin_yaw == b.sin_yaw && a.radius == b.radius && a.z_min == b.z_min &&
         a.z_max == b.z_max && a.texture == b.texture && a.texture_offset == b.texture_offset;
}

}  // namespace

SensorOptions loadSensorOptions(IniSection& section) {
  SensorOptions options;
  options.noise_sigma = section.getNonNegative("noise_sigma", options.noise_sigma, 255.0);
  options.seed = section.getInt("seed", options.seed);
  return options;
}

RigRenderer::RigRenderer(const World& world, CameraRig rig, SensorOptions sensor)
    : world_(world),
      rig_(std::move(rig)),
      sensor_(sensor),
      ray_caster_(world),
      noise_(static_cast<uint64_t>(sensor.seed) * 0x9e3779b97f4a7c15ull + 1) {}

mrpt::poses::CPose3D RigRenderer::referencePose(const mrpt::poses::CPose2D& robot_pose) const {
  return mrpt::poses::CPose3D(robot_pose) + rig_.pose_on_robot;
}

mrpt::poses::CPose3D RigRenderer::secondaryPose(const mrpt::poses::CPose2D& robot_pose,
                                                size_t i) const {
  const SecondaryCamera& camera = rig_.secondaries.at(i);
  return referencePose(robot_pose) +
         mrpt::poses::CPose3D(camera.bx * rig_.baseline_m, camera.by * rig_.baseline_m, 0.0, 0.0,
                              0.0, 0.0);
}

bool RigRenderer::mayBeSeen(const Solid& solid, const mrpt::poses::CPose2D& robot_pose) const {
  // Only the pixels its bounding box projects onto can see a solid; that box lies in front of a
  // camera, or partly behind it (then every pixel may see it), or wholly behind.
  const FloorExtent extent = solid.floorExtent();
  const PinholeCamera& camera = rig_.reference;
  const auto seen_by = [&](const mrpt::poses::CPose3D& optical_pose) {
    double u_min = std::numeric_limits<double>::infinity(), u_max = -u_min, v_min = u_min, v_max = -u_min;
    int behind = 0;
    for (const double x : {extent.x_min, extent.x_max}) {
      for (const double y : {extent.y_min, extent.y_max}) {
        for (const double z : {solid.z_min, solid.z_max}) {
          double cam_x = 0.0, cam_y = 0.0, cam_z = 0.0;
          optical_pose.inverseComposePoint(x, y, z, cam_x, cam_y, cam_z);
          if (cam_z <= 0.0) {
            ++behind;
            continue;
          }
          const double u = camera.cx + camera.focal_px * cam_x / cam_z, v = camera.cy + camera.focal_px * cam_y / cam_z;
          u_min = std::min(u_min, u);
          u_max = std::max(u_max, u);
          v_min = std::min(v_min, v);
          v_max = std::max(v_max, v);
        }
      }
    }
    if (behind == 8) return false;
    if (behind > 0) return true;
    // A pixel's ray passes through its centre; a pixel of margin covers the rounding.
    return u_max >= -1.0 && u_min <= camera.width && v_max >= -1.0 && v_min <= camera.height;
  };
  const mrpt::poses::CPose3D reference_pose = referencePose(robot_pose);
  if (seen_by(reference_pose)) return true;
  for (size_t i = 0; i < rig_.secondaries.size(); ++i) {
    if (seen_by(secondaryPose(robot_pose, i))) return true;
  }
  return false;
}

bool RigRenderer::sameView(const mrpt::poses::CPose2D& robot_pose, double gain,
                           const std::vector<Solid>& moving_solids) const {
  if (!traced_.valid || robot_pose.x() != traced_.robot_pose.x() || robot_pose.y() != traced_.robot_pose.y() ||
      robot_pose.phi() != traced_.robot_pose.phi() || gain != traced_.gain ||
      moving_solids.size() != traced_.moving_solids.size()) {
    return false;
  }
  for (size_t i = 0; i < moving_solids.size(); ++i) {
    const Solid& now = moving_solids[i];
    const Solid& then = traced_.moving_solids[i];
    if (!sameSolid(now, then) && (mayBeSeen(now, robot_pose) || mayBeSeen(then, robot_pose))) return false;
  }
  return true;
}

RigImages RigRenderer::render(const mrpt::poses::CPose2D& robot_pose, double time_s,
                              const std::vector<Solid>& moving_solids) {
  const double gain = world_.lightingGain(time_s);
  const PinholeCamera& camera = rig_.reference;
  // A robot standing still (a look held at a frontier) sees what it saw: the noise-free
  // images are traced again only when the view or something in it changed.
  if (!sameView(robot_pose, gain, moving_solids)) {
    ray_caster_.setMovingSolids(moving_solids);
    traced_.reference.create(camera.height, camera.width);
    traced_.depth.create(camera.height, camera.width);
    const mrpt::poses::CPose3D reference_pose = referencePose(robot_pose);
    const Eigen::Vector3d viewpoint(reference_pose.x(), reference_pose.y(), reference_pose.z());
    traceCamera(reference_pose, viewpoint, gain, &traced_.reference, &traced_.depth);
    traced_.secondaries.resize(rig_.secondaries.size());
    for (size_t i = 0; i < rig_.secondaries.size(); ++i) {
      traced_.secondaries[i].create(camera.height, camera.width);
      traceCamera(secondaryPose(robot_pose, i), viewpoint, gain, &traced_.secondaries[i], nullptr);
    }
    traced_.valid = true;
    traced_.robot_pose = robot_pose;
    traced_.gain = gain;
  }
  traced_.moving_solids = moving_solids;
  RigImages images;
  images.reference = withSensorNoise(traced_.reference);
  images.true_disparity.create(camera.height, camera.width);
  const double f_times_b = camera.focal_px * rig_.baseline_m;
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      const float z = traced_.depth(y, x);
      images.true_disparity(y, x) = z == kNoHit ? kInvalidDisparity : static_cast<float>(f_times_b / z);
    }
  }
  for (const cv::Mat1f& brightness : traced_.secondaries) images.secondaries.push_back(withSensorNoise(brightness));
  return images;
}

void RigRenderer::traceCamera(const mrpt::poses::CPose3D& optical_pose,
                              const Eigen::Vector3d& footprint_viewpoint, double gain,
                              cv::Mat1f* brightness, cv::Mat1f* depth) {
  const PinholeCamera& camera = rig_.reference;
  const Eigen::Matrix3d rotation = optical_pose.getRotationMatrix().asEigen();
  PixelRays rays;
  rays.origin = Eigen::Vector3d(optical_pose.x(), optical_pose.y(), optical_pose.z());
  // Camera-frame directions ((x - cx)/f, (y - cy)/f, 1) in the world: t is then the depth Z.
  rays.forward = rotation.col(2);
  rays.right = rotation.col(0) / camera.focal_px;
  rays.down = rotation.col(1) / camera.focal_px;
  rays.width = camera.width;
  rays.height = camera.height;
  rays.cx = camera.cx;
  rays.cy = camera.cy;
  ray_caster_.cast(rays);
  for (int y = 0; y < camera.height; ++y) {
    ray_caster_.rowSurfaces(y, row_);
    float* brightness_row = brightness->ptr<float>(y);
    if (depth) {
      float* depth_row = depth->ptr<float>(y);
      for (int x = 0; x < camera.width; ++x) depth_row[x] = static_cast<float>(row_.t[x]);
    }
    std::fill(brightness_row, brightness_row + camera.width, static_cast<float>(gain * kEmptyBrightness));
    const size_t count = row_.count;
    seen_.shade(row_, footprint_viewpoint, camera.focal_px);
    queries_.resize(count);
    for (size_t i = 0; i < count; ++i) {
      queries_[i] = {&world_.textures[row_.texture[i]], row_.u[i], row_.v[i], seen_.footprint[i],
                     row_.texture_offset[i]};
    }
    albedo_sampler_.sample(queries_, albedos_);
    for (size_t i = 0; i < count; ++i) {
      brightness_row[row_.column[i]] = static_cast<float>(255.0 * gain * seen_.shade_factor[i] * albedos_[i]);
    }
  }
}

// Built for AVX2 as well (chosen at load time): four pixels per square root and division. Not
// with FMA, whose fused rounding would change the images from one machine to another.
__attribute__((target_clones("avx2", "default")))
void RigRenderer::SeenSurfaces::shade(const RowSurfaces& row, const Eigen::Vector3d& viewpoint, double focal_px) {
  const size_t count = row.count;
  footprint.resize(row.x.size());
  shade_factor.resize(row.x.size());
  const double* __restrict px = row.x.data();
  const double* __restrict py = row.y.data();
  const double* __restrict pz = row.z.data();
  const double* __restrict nx = row.normal_x.data();
  const double* __restrict ny = row.normal_y.data();
  const double* __restrict nz = row.normal_z.data();
  double* __restrict footprints = footprint.data();
  double* __restrict shades = shade_factor.data();
  const double vx = viewpoint.x(), vy = viewpoint.y(), vz = viewpoint.z();
  const double light_x = kLightDirection.x(), light_y = kLightDirection.y(), light_z = kLightDirection.z();
  // A value, not the constant itself: std::max of a reference to a global is a load the loop
  // could not do four at a time.
  const double minimum_cosine = kMinimumCosine;
  for (size_t i = 0; i < count; ++i) {
    // Pixel footprint on the surface: distance / f, stretched by the obliquity of the view. The
    // sums run in the order of Eigen's norm() and dot(), which this loop replaced bit for bit.
    const double sight_x = px[i] - vx, sight_y = py[i] - vy, sight_z = pz[i] - vz;
    const double distance = std::sqrt(sight_x * sight_x + sight_y * sight_y + sight_z * sight_z);
    const double facing = std::max(std::abs(nx[i] * sight_x + ny[i] * sight_y + nz[i] * sight_z) / distance, minimum_cosine);
    footprints[i] = distance / (focal_px * facing);
  }
  // A loop of its own: GCC 12 vectorizes neither when they share one.
  for (size_t i = 0; i < count; ++i) {
    shades[i] = kAmbient + kDiffuse * std::abs(nx[i] * light_x + ny[i] * light_y + nz[i] * light_z);
  }
}

cv::Mat1b RigRenderer::withSensorNoise(const cv::Mat1f& brightness) {
  cv::Mat1f noisy = brightness.clone();
  if (sensor_.noise_sigma > 0.0) {
    cv::Mat1f noise(brightness.size());
    noise_.fill(noise, cv::RNG::NORMAL, 0.0, sensor_.noise_sigma);
    noisy += noise;
  }
  cv::Mat1b image;
  noisy.convertTo(image, CV_8U);
  return image;
}

}  // namespace stereonav
