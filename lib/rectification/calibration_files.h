#pragma once

#include <mrpt/img/TCamera.h>
#include <mrpt/poses/CPose3D.h>

#include <string>
#include <vector>

#include "rectification/rig_calibration.h"

namespace stereonav {

// The calibration formats of the tools a robotics engineer calibrates with, cameras in the order
// listed (the first is the rig's reference):
//  - OpenCV FileStorage (YAML or XML), stereo: M1 D1 M2 D2 R T as OpenCV's stereo_calib sample
//    writes them (its intrinsics.yml and extrinsics.yml may be given as two files) and
//    `stereonav calibrate` does (plus image_width, image_height); trinocular: cameraMatrix1..3,
//    distCoeffs1..3, R12 T12 R13 T13 as the 3calibration sample writes them.
//  - ROS camera_info YAML (camera_calibration's output), one file per camera: intrinsics and
//    distortion, and the cameras' relative pose from each one's rectification_matrix and
//    projection_matrix (the Tx, Ty of stereo_image_proc).
//  - EuRoC sensor.yaml, one file per camera: intrinsics, radial-tangential distortion, T_BS.
//  - MRPT ini holding a TStereoCamera (sections <P>_LEFT, <P>_RIGHT, <P>_LEFT2RIGHT_POSE, as
//    mrpt::img::TStereoCamera::saveToConfigFile and MRPT's stereo-calib-gui write them).
// An image size the file does not give (OpenCV's stereo_calib) is left 0 x 0, for the images to
// supply (withImageSizes). Throws RectificationError naming the file on anything missing or
// malformed.
RigCalibration loadRigCalibration(const std::vector<std::string>& paths);

// Writes `calibration` (two or three cameras) in the OpenCV format above, atomically.
void saveRigCalibration(const RigCalibration& calibration, const std::string& path);

// `calibration` with every unknown (0 x 0) image size set from `sizes` (camera order); throws
// RectificationError if a known size differs.
RigCalibration withImageSizes(RigCalibration calibration, const std::vector<cv::Size>& sizes);

// The same head described from camera `reference`: it becomes camera 0, the old camera 0 takes
// its place, every pose re-expressed relative to it.
RigCalibration withReference(const RigCalibration& calibration, size_t reference);

// MRPT's camera model as a CameraCalibration at the reference's place. Throws RectificationError
// for a fisheye (kannala_brandt) model.
CameraCalibration cameraCalibrationOf(const mrpt::img::TCamera& camera);

// Places `camera` at `pose`, an optical frame given in the reference camera's optical frame (what
// MRPT poses relative to each other give).
void placeCamera(CameraCalibration& camera, const mrpt::poses::CPose3D& pose);

// The other way: MRPT's camera model (plumb_bob with the first five coefficients), named `name`,
// and the camera's optical frame in the reference camera's (e.g. a pair's rightCameraPose).
mrpt::img::TCamera tcameraOf(const CameraCalibration& camera, const std::string& name);
mrpt::poses::CPose3D poseInReference(const CameraCalibration& camera);

}  // namespace stereonav
