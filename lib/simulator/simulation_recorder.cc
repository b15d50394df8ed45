#include "simulator/simulation_recorder.h"

#include <iomanip>

#include "common/atomic_file.h"
#include "common/ini_section.h"
#include "observations/rig_observations.h"

namespace stereonav {

SimulationRecorder::SimulationRecorder(const std::string& rawlog_path, const RawlogWriterOptions& options,
                                       const CameraRig& rig)
    : writer_(rawlog_path, options), rig_(rig), ground_truth_path_(groundTruthPath(rawlog_path)) {
  ground_truth_ << std::setprecision(9);
}

void SimulationRecorder::record(const SimulatedFrame& frame) {
  writer_.write(rigFrameOf(frame, rig_));
  ground_truth_ << frame.time_s << " " << frame.true_pose.x() << " " << frame.true_pose.y() << " "
                << frame.true_pose.phi() << "\n";
}

void SimulationRecorder::finish() {
  writeStringAtomically(ground_truth_path_, ground_truth_.str());
  writer_.finish();
}

void SimulationRecorder::checkRecordable(const CameraRig& rig, const std::string& config_path) {
  if (formsStereoPair(rig)) return;
  throw ConfigError(config_path +
                    ": [rig] secondary_cameras: the first camera must sit beside the reference "
                    "(by = 0, bx != 0) for the frames to be recorded as MRPT stereo pairs");
}

std::string SimulationRecorder::groundTruthPath(const std::string& rawlog_path) {
  const std::string extension = ".rawlog";
  const bool has_extension = rawlog_path.size() > extension.size() &&
                             rawlog_path.compare(rawlog_path.size() - extension.size(), extension.size(), extension) == 0;
  return (has_extension ? rawlog_path.substr(0, rawlog_path.size() - extension.size()) : rawlog_path) + ".gt.txt";
}

}  // namespace stereonav
