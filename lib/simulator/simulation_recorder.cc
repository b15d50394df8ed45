#include "simulator/simulation_recorder.h"

#include <mrpt/core/Clock.h>

#include <iomanip>

#include "common/atomic_file.h"
#include "observations/rig_frame.h"

namespace stereonav {
namespace {

constexpr double kRunEpoch = 946684800.0;  // 2000-01-01T00:00:00Z, seconds since 1970

}  // namespace

SimulationRecorder::SimulationRecorder(const std::string& rawlog_path, const RawlogWriterOptions& options,
                                       const CameraRig& rig)
    : writer_(rawlog_path, options), rig_(rig), ground_truth_path_(groundTruthPath(rawlog_path)) {
  ground_truth_ << std::setprecision(9);
}

void SimulationRecorder::record(const SimulatedFrame& frame) {
  RigFrame rig_frame;
  rig_frame.timestamp = mrpt::Clock::fromDouble(kRunEpoch + frame.time_s);
  rig_frame.reference = frame.images.reference;
  rig_frame.secondaries.assign(frame.images.secondaries.begin(), frame.images.secondaries.end());
  rig_frame.rig = rig_;
  rig_frame.odometry = frame.odometry;
  writer_.write(rig_frame);
  ground_truth_ << frame.time_s << " " << frame.true_pose.x() << " " << frame.true_pose.y() << " "
                << frame.true_pose.phi() << "\n";
}

void SimulationRecorder::finish() {
  writeStringAtomically(ground_truth_path_, ground_truth_.str());
  writer_.finish();
}

std::string SimulationRecorder::groundTruthPath(const std::string& rawlog_path) {
  const std::string extension = ".rawlog";
  const bool has_extension = rawlog_path.size() > extension.size() &&
                             rawlog_path.compare(rawlog_path.size() - extension.size(), extension.size(), extension) == 0;
  return (has_extension ? rawlog_path.substr(0, rawlog_path.size() - extension.size()) : rawlog_path) + ".gt.txt";
}

}  // namespace stereonav
