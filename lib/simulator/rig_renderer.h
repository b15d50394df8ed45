#pragma once

#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <opencv2/core.hpp>

#include <vector>

#include "common/ini_section.h"
#include "rig/camera_rig.h"
#include "simulator/ray_caster.h"
#include "simulator/surface_texture.h"
#include "simulator/world.h"

namespace stereonav {

// The simulated cameras' sensor: what is added on top of the ideal rendering.
struct SensorOptions {
  double noise_sigma = 2.0;  // Gaussian pixel noise, grey levels, independent per camera and frame
  int seed = 1;              // the noise sequence is reproducible from this
};

// Section [sim_sensor]: noise_sigma (grey levels, >= 0), seed (integer).
SensorOptions loadSensorOptions(IniSection& section);

// One simulated exposure of the whole rig, plus the truth the stereo pipeline should recover.
struct RigImages {
  cv::Mat1b reference;
  std::vector<cv::Mat1b> secondaries;  // in CameraRig::secondaries order
  // Exact disparity of the reference camera for the rig's unit baseline, f * B / Z per pixel
  // (Z: depth along the optical axis of the first surface the pixel's centre ray meets);
  // kInvalidDisparity where the ray meets nothing.
  cv::Mat1f true_disparity;
};

// Ray-traces the rectified images of every camera of a CameraRig standing on a robot in a World.
// All cameras share the reference camera's intrinsics and orientation; a secondary camera sits
// at (bx, by) * B along the reference image axes (rig/camera_rig.h), so a scene point at
// disparity d seen at (x, y) in the reference projects to (x - bx d, y - by d) there — the
// rectified geometry the Triclops delivers (paper section 2.1). Each camera is traced from its
// own centre, so occlusions differ between cameras as they do in the real rig (section 6.1).
class RigRenderer {
 public:
  RigRenderer(const World& world, CameraRig rig, SensorOptions sensor);

  // The rig's view at `time_s` (the world's lighting), with the moving obstacles where they are
  // then (MovingTraffic::solids; empty for a world without them).
  RigImages render(const mrpt::poses::CPose2D& robot_pose, double time_s, const std::vector<Solid>& moving_solids);

  // The optical-frame pose in the world of the reference camera and of secondary camera i.
  mrpt::poses::CPose3D referencePose(const mrpt::poses::CPose2D& robot_pose) const;
  mrpt::poses::CPose3D secondaryPose(const mrpt::poses::CPose2D& robot_pose, size_t i) const;

 private:
  // Noise-free brightness in grey levels; also the depth Z of each pixel if `depth` is given.
  // Texture detail is filtered for the footprint of a pixel seen from `footprint_viewpoint`
  // (the reference camera's centre for every camera), so that all cameras see exactly the same
  // albedo at a scene point.
  void traceCamera(const mrpt::poses::CPose3D& optical_pose, const Eigen::Vector3d& footprint_viewpoint,
                   double gain, cv::Mat1f* brightness, cv::Mat1f* depth);
  cv::Mat1b withSensorNoise(const cv::Mat1f& brightness);
  // Whether any camera of the rig at `robot_pose` may see `solid` (conservative).
  bool mayBeSeen(const Solid& solid, const mrpt::poses::CPose2D& robot_pose) const;
  // Whether tracing at `robot_pose` with lighting `gain` and `moving_solids` gives traced_ again:
  // the same pose and light, and no moving solid moved where a camera may see it, before or after.
  bool sameView(const mrpt::poses::CPose2D& robot_pose, double gain, const std::vector<Solid>& moving_solids) const;

  const World& world_;
  CameraRig rig_;
  SensorOptions sensor_;
  RayCaster ray_caster_;
  cv::RNG noise_;
  // The pixels of a camera row that see a surface (RayCaster::rowSurfaces), and from their lines
  // of sight (from the footprint viewpoint) and normals, their footprints and Lambertian shading.
  RowSurfaces row_;
  struct SeenSurfaces {
    std::vector<double> footprint, shade_factor;

    // footprint and shade_factor of row.count surfaces.
    void shade(const RowSurfaces& row, const Eigen::Vector3d& viewpoint, double focal_px);
  };
  SeenSurfaces seen_;
  AlbedoSampler albedo_sampler_;
  // The last noise-free images traced, and what they were traced from.
  struct TracedView {
    bool valid = false;
    mrpt::poses::CPose2D robot_pose;
    double gain = 0.0;
    std::vector<Solid> moving_solids;  // where they were at the last frame, traced or not
    cv::Mat1f reference, depth;
    std::vector<cv::Mat1f> secondaries;
  };
  TracedView traced_;
  std::vector<AlbedoQuery> queries_;  // what to sample at each of seen_
  std::vector<double> albedos_;
};

}  // namespace stereonav
