#pragma once

#include <mrpt/poses/CPose2D.h>
#include <opencv2/core.hpp>

#include <optional>
#include <vector>

#include "localization/turn_doubt.h"
#include "rig/camera_rig.h"

namespace stereonav {

// How the floor's texture measures the robot's motion between two frames (section
// [localization], keys floor_*). The paper drives on dead reckoning and names its drift as the
// open problem (section 5); the floor the reference camera sees is a plane at a known pose, so
// two views of it fix the planar motion between them at the scale of the rig's mount, without
// the wheels' distance and turn biases.
struct FloorMotionOptions {
  bool enabled = false;  // key floor_motion
  // The floor taken into account, by its distance from the robot: near pixels move too far
  // between frames, far ones too little to measure.
  double min_range_m = 0.3;
  double max_range_m = 3.0;
  // A pixel is floor when its stereo disparity is within this of the floor plane's there: walls,
  // furniture and people are left out, and so are pixels stereo could not match (no texture).
  double disparity_tolerance_px = 0.5;
  int pixel_step = 2;   // every pixel_step-th pixel in x and y
  int min_pixels = 300;  // floor pixels seen in both frames, fewer: no measurement
  // The measurement is refused when it differs from the wheels' by more than this (plus the
  // share of the wheels' distance / turn): a failed alignment, not the wheels' few percent.
  double max_disagreement_m = 0.01;
  double max_disagreement_deg = 0.5;
  double max_disagreement_fraction = 0.1;
  // How far the wheels' turns may be off in scale before the floor has measured it: the doubt of
  // a wheel step's turn until then (a wheel base off its nominal length).
  double wheel_turn_scale_sigma = 0.05;
  // The wheels' own random turn error per step, which the floor's steps do not have: the
  // localizer's noise model then describes the floor's steps, and each wheel step adds this.
  double wheel_turn_noise_per_rad = 0.0;
  double wheel_heading_noise_deg_per_m = 0.0;
};

// One frame's floor: its pixels on the floor plane, on the robot, with their brightness.
struct FloorPixels {
  std::vector<cv::Point2d> on_robot;  // metres, robot frame at this frame
  std::vector<float> brightness;      // of the smoothed reference image
};

// The reference image as the alignment reads it: smoothed, so that its gradient reaches across
// the pixel or two the wheels' guess may be off.
cv::Mat1f smoothedForFloor(const cv::Mat1b& grey);

// The floor pixels of a frame: `smoothed` its reference image (smoothedForFloor), `disparity`
// its disparity image (kInvalidDisparity where there is no match), both in `rig`'s reference
// camera.
FloorPixels floorPixels(const CameraRig& rig, const cv::Mat1f& smoothed, const cv::Mat1f& disparity,
                        const FloorMotionOptions& options);

struct FloorAlignment {
  mrpt::poses::CPose2D motion;  // this frame's robot pose in the previous frame's
  int pixels = 0;               // floor pixels that took part (seen in both frames)
  bool converged = false;
};

// Aligns the floor pixels of the current frame with the previous frame's smoothed image,
// starting from `guess` (the wheels' motion): Gauss-Newton on the motion and an affine
// brightness change (exposure), robust to the pixels that do not fit (Huber weights).
FloorAlignment alignFloor(const CameraRig& rig, const FloorPixels& current, const cv::Mat1f& previous_smoothed,
                          const mrpt::poses::CPose2D& guess);

// Odometry whose every step is the floor's measurement where it is accepted and the wheels'
// otherwise, their distance and turn scaled by what the accepted steps measured of them (a
// wheel radius off by 1% would otherwise return in every step the floor cannot see: facing a
// wall, in the dark). The pose it returns is the wheels' first pose chained with these steps.
//
//   FloorOdometry odometry(rig, options);
//   for each frame: localizer.update(odometry.update(wheel_pose, grey, disparity), ...)
class FloorOdometry {
 public:
  FloorOdometry(const CameraRig& rig, const FloorMotionOptions& options);

  const mrpt::poses::CPose2D& update(const mrpt::poses::CPose2D& wheels, const cv::Mat1b& grey,
                                     const cv::Mat1f& disparity);

  // Frames whose step came from the floor, and all frames after the first.
  int measuredSteps() const { return measured_steps_; }
  // The doubt of the last step's turn that the localizer's noise model of odometry does not
  // cover: a wheel step's while the wheels' turn scale is not yet measured, and on the step it
  // is, the scale that corrected those wheel steps' turns.
  const TurnDoubt& lastTurnDoubt() const { return last_turn_doubt_; }
  int steps() const { return steps_; }
  // What the floor measured per unit of the wheels' distance and turn (1 until it has seen
  // enough of both to tell).
  double distanceScale() const;
  double turnScale() const;

 private:
  bool turnCalibrated() const;
  // The floor's measurement of the step from the previous frame, if it is accepted: enough floor
  // seen in both frames, the alignment converged and within the limits of `predicted`.
  std::optional<mrpt::poses::CPose2D> floorStep(const cv::Mat1f& smoothed, const cv::Mat1f& disparity,
                                                const mrpt::poses::CPose2D& predicted) const;

  CameraRig rig_;
  FloorMotionOptions options_;
  std::optional<mrpt::poses::CPose2D> previous_wheels_;
  cv::Mat1f previous_smoothed_;
  mrpt::poses::CPose2D pose_;
  int measured_steps_ = 0;
  int steps_ = 0;
  TurnDoubt last_turn_doubt_;
  double uncalibrated_turn_ = 0.0;  // the wheel steps' turn taken before the scale was known
  // Least squares of floor = scale * wheels over the accepted steps, forward distance and turn.
  double distance_products_ = 0.0, distance_squares_ = 0.0;
  double turn_products_ = 0.0, turn_squares_ = 0.0;
};

}  // namespace stereonav
