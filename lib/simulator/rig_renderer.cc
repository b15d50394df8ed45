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
    float* brightness_row = brightness->ptr<float>(y);
    float* depth_row = depth ? depth->ptr<float>(y) : nullptr;
    queries_.clear();
    query_columns_.clear();
    shades_.clear();
    for (int x = 0; x < camera.width; ++x) {
      const RayHit hit = ray_caster_.hit(x, y);
      if (depth_row) depth_row[x] = static_cast<float>(hit.t);
      if (hit.t == kNoHit) {
        brightness_row[x] = static_cast<float>(gain * kEmptyBrightness);
        continue;
      }
      // Pixel footprint on the surface: distance / f, stretched by the obliquity of the view.
      const Eigen::Vector3d line_of_sight = hit.surface.position - footprint_viewpoint;
      const double distance = line_of_sight.norm();
      const double facing =
          std::max(std::abs(hit.surface.normal.dot(line_of_sight)) / distance, kMinimumCosine);
      const double footprint = distance / (camera.focal_px * facing);
      queries_.push_back({&world_.textures[hit.texture], hit.surface.u, hit.surface.v, footprint, hit.texture_offset});
      query_columns_.push_back(x);
      shades_.push_back(kAmbient + kDiffuse * std::abs(hit.surface.normal.dot(kLightDirection)));
    }
    albedo_sampler_.sample(queries_, albedos_);
    for (size_t i = 0; i < queries_.size(); ++i) {
      brightness_row[query_columns_[i]] = static_cast<float>(255.0 * gain * shades_[i] * albedos_[i]);
    }
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
