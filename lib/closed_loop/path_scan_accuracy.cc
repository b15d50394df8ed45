#include "closed_loop/path_scan_accuracy.h"

#include <algorithm>
#include <stdexcept>

#include "column_projection/column_projector.h"
#include "mapping/disparity_scanner.h"
#include "mapping/stage_times.h"
#include "simulator/moving_traffic.h"
#include "simulator/rig_renderer.h"

namespace stereonav {

ScanAccuracy scanAccuracyAlongPath(const ExplorationConfig& config, const World& world,
                                   const std::vector<mrpt::poses::CPose2D>& poses, size_t every,
                                   const ScanAccuracyOptions& options) {
  if (every == 0) throw std::invalid_argument("scan accuracy: every frame count must be at least 1");
  const CameraRig& rig = config.simulator.rig;
  RigRenderer renderer(world, rig, config.simulator.sensor);
  const MovingTraffic traffic(world);
  const MappingOptions& mapping = config.mapping;
  DisparityScanner scanner(rig, mapping.stereo, mapping.spike_removal, mapping.projection);
  const ColumnProjector truth_projector(rig, mapping.projection);
  ScanAccuracyOptions searched = options;
  searched.max_disparity = std::min(options.max_disparity, static_cast<double>(mapping.stereo.max_disparity));
  StageTimes times;
  ScanAccuracy accuracy;
  for (size_t frame = 0; frame < poses.size(); frame += every) {
    const double time_s = static_cast<double>(frame) / config.simulator.simulation.frame_rate_hz;
    const RigImages images = renderer.render(poses[frame], time_s, traffic.solids());
    RigFrame rig_frame;
    rig_frame.reference = images.reference;
    rig_frame.rig = rig;
    rig_frame.secondaries.assign(images.secondaries.begin(), images.secondaries.end());
    const DisparityScan& measured = scanner.scan(rig_frame, times);
    accuracy += compareScans(measured, truth_projector.project(images.true_disparity), rig, searched);
  }
  return accuracy;
}

}  // namespace stereonav
