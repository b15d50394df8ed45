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
  // Sized once and written in place, a row at a time. Built aside and copied in, each pixel's
  // query stalled on reading back its own just-written bytes behind the divisions of its
  // footprint, which then ran one pixel after another instead of overlapping.
  seen_.resize(camera.width);
  queries_.resize(camera.width);
  for (int y = 0; y < camera.height; ++y) {
    float* brightness_row = brightness->ptr<float>(y);
    float* depth_row = depth ? depth->ptr<float>(y) : nullptr;
    size_t count = 0;
    for (int x = 0; x < camera.width; ++x) {
      const RayHit hit = ray_caster_.hit(x, y);
      if (depth_row) depth_row[x] = static_cast<float>(hit.t);
      if (hit.t == kNoHit) {
        brightness_row[x] = static_cast<float>(gain * kEmptyBrightness);
        continue;
      }
      seen_.add(count, x, hit.surface.position - footprint_viewpoint, hit.surface.normal);
      AlbedoQuery& query = queries_[count];
      query.texture = &world_.textures[hit.texture];
      query.u = hit.surface.u;
      query.v = hit.surface.v;
      query.noise_shift = hit.texture_offset;
      ++count;
    }
    seen_.shade(count, camera.focal_px);
    for (size_t i = 0; i < count; ++i) queries_[i].footprint_m = seen_.footprint[i];
    queries_.resize(count);
    albedo_sampler_.sample(queries_, albedos_);
    queries_.resize(camera.width);
    for (size_t i = 0; i < count; ++i) {
      brightness_row[seen_.column[i]] = static_cast<float>(255.0 * gain * seen_.shade_factor[i] * albedos_[i]);
    }
  }
}

void RigRenderer::SeenSurfaces::resize(size_t width) {
  for (auto* values : {&sight_x, &sight_y, &sight_z, &normal_x, &normal_y, &normal_z, &footprint, &shade_factor}) {
    values->resize(width);
  }
  column.resize(width);
}

// Built for AVX2 as well (chosen at load time): four pixels per square root and division. Not
// with FMA, whose fused rounding would change the images from one machine to another.
__attribute__((target_clones("avx2", "default")))
void RigRenderer::SeenSurfaces::shade(size_t count, double focal_px) {
  const double* __restrict sx = sight_x.data();
  const double* __restrict sy = sight_y.data();
  const double* __restrict sz = sight_z.data();
  const double* __restrict nx = normal_x.data();
  const double* __restrict ny = normal_y.data();
  const double* __restrict nz = normal_z.data();
  double* __restrict footprints = footprint.data();
  double* __restrict shades = shade_factor.data();
  const double light_x = kLightDirection.x(), light_y = kLightDirection.y(), light_z = kLightDirection.z();
  // A value, not the constant itself: std::max of a reference to a global is a load the loop
  // could not do four at a time.
  const double minimum_cosine = kMinimumCosine;
  for (size_t i = 0; i < count; ++i) {
    // Pixel footprint on the surface: distance / f, stretched by the obliquity of the view. The
    // sums run in the order of Eigen's norm() and dot(), which this loop replaced bit for bit.
    const double distance = std::sqrt(sx[i] * sx[i] + sy[i] * sy[i] + sz[i] * sz[i]);
    const double facing = std::max(std::abs(nx[i] * sx[i] + ny[i] * sy[i] + nz[i] * sz[i]) / distance, minimum_cosine);
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
