#pragma once

#include <mrpt/obs/CObservationImage.h>

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "common/ini_section.h"

namespace stereonav {

// Cameras recorded as one CObservationImage each (rawlog-grabber with several cameras,
// rosbag2rawlog): which labels make up the head and how far apart in time their images of one
// capture may be.
struct ImagePairingOptions {
  std::vector<std::string> labels;  // reference first, then the secondaries in rig order
  double max_time_difference_s = 0.005;
};

// [rawlog] keys: camera_labels = "LEFT RIGHT [TOP]" (empty: the head is recorded as
// CObservationStereoImages), pairing_tolerance_s (> 0, default 0.005). Throws ConfigError.
ImagePairingOptions loadImagePairingOptions(IniSection& section);

// One capture: an image per label, in label order, or, when a partner is missing, why not.
struct PairedCapture {
  std::vector<mrpt::obs::CObservationImage::Ptr> images;
  std::string missing;  // "" for a complete capture
};

// Groups separately recorded camera images into captures. Each reference image takes, from every
// partner label, the image closest to it in time within the tolerance, decided once every partner
// has an image past that window or one of the very same instant (or at the end); without a match
// it is skipped (a capture with `missing` set). A partner image no reference image took is
// reported the same way. Images arriving slightly out of order are sorted by time; images of other labels are
// ignored.
class CameraImagePairer {
 public:
  explicit CameraImagePairer(ImagePairingOptions options);

  // Returns false (and keeps nothing) if `image` is not one of the head's cameras.
  bool add(const mrpt::obs::CObservationImage::Ptr& image);
  // No more images: decides every pending one.
  void finish();
  // The next decided capture, oldest first.
  std::optional<PairedCapture> next();

 private:
  void decide(bool at_end);
  void dropUnused(size_t label, mrpt::system::TTimeStamp before);

  ImagePairingOptions options_;
  std::vector<std::deque<mrpt::obs::CObservationImage::Ptr>> pending_;  // per label, by time
  std::deque<PairedCapture> decided_;
};

}  // namespace stereonav
