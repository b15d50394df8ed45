#pragma once

#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <string>
#include <vector>

#include "mapping/stage_times.h"
#include "observations/rawlog_reader.h"

namespace stereonav {

// What a rawlog replay did, for the user (summary line) and for scripts (PREFIX.stats.json).
struct MappingReport {
  std::string rawlog_path;
  size_t frames_mapped = 0;
  size_t frames_without_odometry = 0;  // mapped at the previous frame's pose
  // With localized poses: frames whose scan match corrected odometry (the others kept it).
  size_t frames_localized = 0;
  size_t frames_floor_measured = 0;  // frames whose step was measured on the floor (floor_motion)
  std::vector<mrpt::poses::CPose2D> path;  // the pose each frame was mapped at
  SkippedFrames skipped;
  std::optional<RawlogDamage> damage;  // where reading stopped, if the rawlog is damaged
  bool interrupted = false;            // stopped by request (Ctrl-C) after a whole frame
  std::vector<std::string> calibration_warnings;
  std::vector<std::string> output_errors;  // outputs that could not be written (the others were)
  // Fractions of all pixels of all mapped frames: with a stereo match, and kept by spike removal.
  double matched_pixel_fraction = 0.0;
  double kept_pixel_fraction = 0.0;
  StageTimes times;             // the per-frame pipeline only
  double wall_seconds = 0.0;    // the whole replay: decoding, pipeline, panels

  bool complete() const { return !damage && !interrupted; }
  // Frames per second of the pipeline alone (0 before any frame).
  double pipelineFramesPerSecond() const;
  // E.g. "mapped 60 frames (41.2 frames/s; pipeline 3.9 ms/frame); stopped at damage: ...".
  std::string summary() const;
  std::string toJson() const;
};

}  // namespace stereonav
