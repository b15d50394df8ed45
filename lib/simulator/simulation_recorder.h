#pragma once

#include <sstream>
#include <string>

#include "observations/rawlog_writer.h"
#include "rig/camera_rig.h"
#include "simulator/simulation.h"

namespace stereonav {

// Records a simulated run the way the real robot's would be: a rawlog of rig frames with the
// robot's (drifting) odometry, readable by the pipeline and by MRPT tools; plus the ground truth
// the real robot never has, the true pose of every frame, in "<rawlog stem>.gt.txt": one line
// "t x y phi" per frame and nothing else (t: seconds since the start of the run, x y in metres,
// phi in radians).
// Frame timestamps in the rawlog are 2000-01-01T00:00:00Z plus t, so runs are reproducible.
class SimulationRecorder {
 public:
  SimulationRecorder(const std::string& rawlog_path, const RawlogWriterOptions& options,
                     const CameraRig& rig);

  void record(const SimulatedFrame& frame);

  // Writes the ground-truth file (atomically) and finishes the rawlog.
  void finish();

  // "OUT.rawlog" -> "OUT.gt.txt".
  static std::string groundTruthPath(const std::string& rawlog_path);

  // Throws ConfigError "<config_path>: [rig] secondary_cameras: ..." when frames of `rig` cannot
  // be recorded (formsStereoPair): checked before a run, so that it fails before the work.
  static void checkRecordable(const CameraRig& rig, const std::string& config_path);

 private:
  RawlogWriter writer_;
  CameraRig rig_;
  std::string ground_truth_path_;
  std::ostringstream ground_truth_;
};

}  // namespace stereonav
