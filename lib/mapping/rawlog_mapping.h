#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <mrpt/maps/CMetricMap.h>
#include <mrpt/poses/CPose2D.h>

#include "mapping/mapping_options.h"
#include "mapping/mapping_report.h"
#include "observations/rawlog_reader.h"

namespace stereonav {

// Where the poses a run is mapped with come from:
//   odometry      the rawlog's odometry, dead reckoning as in the paper (section 5)
//   localized     odometry corrected by matching each frame's stereo scan against the map built
//                 from the frames before it (localization/scan_localizer.h, [localization])
//   ground_truth  a pose list, one pose per frame (e.g. the simulator's OUT.gt.txt)
enum class MapPoseSource { kOdometry, kLocalized, kGroundTruth };

// "odometry" | "localized" | "ground_truth"; throws std::invalid_argument for anything else.
MapPoseSource parseMapPoseSource(const std::string& name);

// One replay of a recorded run through the mapping pipeline.
struct MappingJob {
  std::string rawlog_path;
  // Outputs <prefix>.gridmap, .png, .yaml + .pgm, .3Dscene (map_outputs.h), .stats.json and
  // .traj.tum (the poses mapped with, one per frame, TUM format: localization/tum_trajectory.h).
  std::string output_prefix;
  std::string debug_panel_directory;  // "" = no panels; else one PNG per frame (must exist)
  size_t debug_panel_every = 1;       // with a directory: a panel of every N-th frame (from the first)
  std::string virtual_scan_rawlog;    // "" = none; else virtual_scan_recorder.h's rawlog
  MapPoseSource pose_source = MapPoseSource::kOdometry;
  // For MapPoseSource::kGroundTruth: one pose per frame in rawlog order (loadPoseList). The recorded
  // odometry still goes into the virtual scan rawlog.
  std::vector<mrpt::poses::CPose2D> ground_truth_poses;
};

// The poses of a trajectory file, one per frame: `stereonav simulate`'s OUT.gt.txt ("t x y phi":
// seconds, metres, radians) or TUM text (loadTrajectory). Throws std::runtime_error naming the
// file and line on malformed text.
std::vector<mrpt::poses::CPose2D> loadPoseList(const std::string& path);

// How the caller follows and steers the replay; every member may be left empty.
struct MappingCallbacks {
  // After every mapped frame, with the number mapped so far and the map as it stands.
  std::function<void(size_t frames_mapped, const mrpt::maps::CMetricMap& map)> on_frame;
  // Asked after every frame; true stops the replay there (e.g. Ctrl-C), outputs are still saved.
  std::function<bool()> stop_requested;
};

// Replays `job.rawlog_path` frame by frame through a StereoMapper, robot poses from
// job.pose_source, and writes all outputs, also when the rawlog is damaged (mapped up to the damage) or
// the replay is stopped. The rig is the [rig] section merged with the first frame's calibration
// (the ini wins; disagreements are reported). Throws std::runtime_error if the rawlog cannot be
// opened or an output cannot be written, std::invalid_argument if ground_truth_poses has fewer
// poses than the rawlog has frames (or none, for MapPoseSource::kGroundTruth).
MappingReport mapRawlog(const MappingOptions& options, const MappingJob& job,
                        const MappingCallbacks& callbacks = {});

// How the reader is set up for `options` (which pair to follow, the rig to expect).
RawlogReaderOptions rawlogReaderOptions(const MappingOptions& options);

// The number of usable frames in a rawlog (reads it once; stops at damage), for progress bars.
size_t countRawlogFrames(const std::string& rawlog_path, const MappingOptions& options);

}  // namespace stereonav
