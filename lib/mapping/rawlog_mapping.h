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

// One replay of a recorded run through the mapping pipeline.
struct MappingJob {
  std::string rawlog_path;
  // Outputs <prefix>.gridmap, .png, .yaml + .pgm, .3Dscene (map_outputs.h) and .stats.json.
  std::string output_prefix;
  std::string debug_panel_directory;  // "" = no panels; else one PNG per frame (must exist)
  size_t debug_panel_every = 1;       // with a directory: a panel of every N-th frame (from the first)
  std::string virtual_scan_rawlog;    // "" = none; else virtual_scan_recorder.h's rawlog
  // Poses to map with instead of odometry, one per frame in rawlog order (loadPoseList); empty
  // = odometry. The recorded odometry still goes into the virtual scan rawlog.
  std::vector<mrpt::poses::CPose2D> ground_truth_poses;
};

// A pose list as `stereonav simulate` writes it (OUT.gt.txt): one line per frame,
// "t x y phi" (seconds, metres, radians); '#' starts a comment. Throws std::runtime_error naming
// the file and line on malformed text.
std::vector<mrpt::poses::CPose2D> loadPoseList(const std::string& path);

// How the caller follows and steers the replay; every member may be left empty.
struct MappingCallbacks {
  // After every mapped frame, with the number mapped so far and the map as it stands.
  std::function<void(size_t frames_mapped, const mrpt::maps::CMetricMap& map)> on_frame;
  // Asked after every frame; true stops the replay there (e.g. Ctrl-C), outputs are still saved.
  std::function<bool()> stop_requested;
};

// Replays `job.rawlog_path` frame by frame through a StereoMapper, robot poses from the rawlog's
// odometry, and writes all outputs, also when the rawlog is damaged (mapped up to the damage) or
// the replay is stopped. The rig is the [rig] section merged with the first frame's calibration
// (the ini wins; disagreements are reported). Throws std::runtime_error if the rawlog cannot be
// opened or an output cannot be written, std::invalid_argument if ground_truth_poses has fewer
// poses than the rawlog has frames.
MappingReport mapRawlog(const MappingOptions& options, const MappingJob& job,
                        const MappingCallbacks& callbacks = {});

// How the reader is set up for `options` (which pair to follow, the rig to expect).
RawlogReaderOptions rawlogReaderOptions(const MappingOptions& options);

// The number of usable frames in a rawlog (reads it once; stops at damage), for progress bars.
size_t countRawlogFrames(const std::string& rawlog_path, const MappingOptions& options);

}  // namespace stereonav
