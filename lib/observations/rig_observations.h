#pragma once

#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationStereoImages.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "observations/frame_rectifier.h"
#include "observations/rig_frame.h"

namespace stereonav {

// How one RigFrame maps onto stock MRPT observations, so rawlog-edit, RawLogViewer and the MRPT
// SLAM apps read what we record:
//
//  - Cameras are numbered by their place in the rig: 0 = reference, k = rig.secondaries[k-1].
//  - Cameras 0 and 1 (the reference and the first secondary, which must sit beside it: by = 0)
//    form one CObservationStereoImages labelled <label> (e.g. "TRICLOPS"). MRPT calls its cameras
//    left and right: with a secondary at bx < 0 (the Triclops: reference = right camera) the
//    secondary is imageLeft; with bx > 0 (a binocular head) the reference is imageLeft.
//    cameraPose is the LEFT camera's optical frame on the robot, rightCameraPose the right camera
//    in the left one's frame, (|bx| B, 0, 0).
//  - Every further camera k >= 2 (the Triclops top camera is camera 2) is a CObservationImage
//    labelled <label>_CAM<k> (e.g. "TRICLOPS_CAM2") with the pair's timestamp, its own optical
//    pose on the robot and its intrinsics.
//  - Each TCamera::cameraName is <label>_CAM<k> as well, which is how a reader tells whether the
//    reference is the left or the right camera of the pair.
//  - What we write carries the reference intrinsics and no distortion: the images are rectified
//    (paper section 2.1). What we read may be raw: cameras with distortion, different intrinsics
//    or rotated relative to each other are rectified on the fly (frame_rectifier.h).
struct RigObservations {
  mrpt::obs::CObservationStereoImages::Ptr pair;
  std::vector<mrpt::obs::CObservationImage::Ptr> extra_cameras;  // cameras 2, 3, ...
};

// "<pair_label>_CAM<camera_index>".
std::string cameraLabel(const std::string& pair_label, size_t camera_index);

// Whether an MRPT stereo observation can describe `rig`: its first secondary camera sits beside
// the reference (by = 0, bx != 0) and forms the CObservationStereoImages pair.
bool formsStereoPair(const CameraRig& rig);

// The observations of `frame`, images embedded (sharing the frame's pixels). Throws
// std::invalid_argument if the frame does not match its rig or its first secondary camera is not
// beside the reference (by != 0), which no MRPT stereo observation can describe.
RigObservations toRigObservations(const RigFrame& frame, const std::string& pair_label);

// Why a set of observations does not make a usable RigFrame.
enum class RejectReason {
  kMissingCalibration,  // a camera without focal length or image size, or a zero baseline
  kWrongImageFormat,    // an image whose size differs from its camera's, or not 8-bit grey/BGR
  kNotRectified,        // a calibration no rectification can use (the message says why)
  kMissingImage,        // an externally stored image whose file cannot be read
  kWrongCameraCount,    // not the number of cameras the caller expects
  kMissingPartner,      // a separately recorded camera image with no partner close enough in time
};
constexpr size_t kRejectReasonCount = 6;

class ObservationRejected : public std::runtime_error {
 public:
  ObservationRejected(RejectReason reason, const std::string& message)
      : std::runtime_error(message), reason_(reason) {}
  RejectReason reason() const { return reason_; }

 private:
  RejectReason reason_;
};

// Which camera of an MRPT pair is the rig's reference when the TCamera names do not say (rawlogs
// we did not write).
enum class PairReference { kLeft, kRight };

// Rebuilds a RigFrame from a stereo pair and the extra cameras 2, 3, ... in camera order: the
// calibration from the cameras' intrinsics, distortion and poses (or the rectifier's calibration
// file), the images loaded (externally stored ones from `images_directory`) and rectified unless
// they are already (then B = the pair's baseline, so the first secondary comes back at bx = +-1).
// Throws ObservationRejected if they lack a calibration, cannot be rectified (saying why) or do
// not match it.
RigFrame fromRigObservations(const mrpt::obs::CObservationStereoImages& pair,
                             const std::vector<mrpt::obs::CObservationImage::Ptr>& extra_cameras,
                             const std::string& images_directory, PairReference unnamed_reference,
                             FrameRectifier& rectifier);

// The same for one capture recorded as one CObservationImage per camera (rawlog-grabber with
// several cameras, rosbag2rawlog), reference first: intrinsics from each cameraParams, the
// cameras' relative poses from their cameraPose on the robot.
RigFrame fromCameraImages(const std::vector<mrpt::obs::CObservationImage::Ptr>& cameras,
                          const std::string& images_directory, FrameRectifier& rectifier);

}  // namespace stereonav
