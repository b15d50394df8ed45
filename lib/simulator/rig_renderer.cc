#include "simulator/rig_renderer.h"

#include <algorithm>
#include <cmath>

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

RigImages RigRenderer::render(const mrpt::poses::CPose2D& robot_pose, double time_s,
                              const std::vector<Solid>& moving_solids) {
  ray_caster_.setMovingSolids(moving_solids);
  const double gain = world_.lightingGain(time_s);
  const PinholeCamera& camera = rig_.reference;
  RigImages images;
  cv::Mat1f brightness(camera.height, camera.width);
  cv::Mat1f depth(camera.height, camera.width);
  const mrpt::poses::CPose3D reference_pose = referencePose(robot_pose);
  const Eigen::Vector3d viewpoint(reference_pose.x(), reference_pose.y(), reference_pose.z());
  traceCamera(reference_pose, viewpoint, gain, &brightness, &depth);
  images.reference = withSensorNoise(brightness);
  images.true_disparity.create(camera.height, camera.width);
  const double f_times_b = camera.focal_px * rig_.baseline_m;
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      const float z = depth(y, x);
      images.true_disparity(y, x) = z == kNoHit ? kInvalidDisparity : static_cast<float>(f_times_b / z);
    }
  }
  for (size_t i = 0; i < rig_.secondaries.size(); ++i) {
    traceCamera(secondaryPose(robot_pose, i), viewpoint, gain, &brightness, nullptr);
    images.secondaries.push_back(withSensorNoise(brightness));
  }
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
