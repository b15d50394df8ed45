#pragma once

#include <functional>
#include <string>

#include "observations/kitti_sequence.h"
#include "observations/rawlog_writer.h"

namespace stereonav {

// Public stereo datasets as rawlogs of this project's layout (rig_observations.h), so that
// `stereonav map` and MRPT's tools read them. Each returns the number of frames written and
// throws std::runtime_error naming the file that is missing or malformed. `on_frame` (optional)
// is told the frames written so far.

// EuRoC MAV (ASL folder layout: cam0/, cam1/ with data.csv, data/<ns>.png and sensor.yaml): the
// raw, unrectified pair as CObservationStereoImages carrying each camera's intrinsics and
// radial-tangential distortion and the right camera's pose from T_BS, so readers rectify it.
// EuRoC has no wheel odometry; the head is mounted level, 1 m up, looking along the robot's x.
// Only the data.csv entries whose two images exist are converted.
size_t convertEuroc(const std::string& dataset, RawlogWriter& writer,
                    const std::function<void(size_t)>& on_frame = {});

// A KITTI odometry sequence (kitti_sequence.h): the rectified pair at 10 Hz; its true poses,
// when it has them, become the robot's odometry with `error` added (none by default).
size_t convertKitti(const KittiSequence& sequence, const OdometryError& error, RawlogWriter& writer,
                    const std::function<void(size_t)>& on_frame = {});

}  // namespace stereonav
