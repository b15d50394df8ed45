#pragma once

#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <vector>

#include "closed_loop/exploration_config.h"
#include "evaluation/scan_accuracy.h"
#include "simulator/world.h"

namespace stereonav {

// The stereo scans a robot takes at `poses` (one per frame, at the configuration's frame rate) in
// `world`, each against the scan of the renderer's exact disparity: every `every`-th frame is
// rendered afresh (the same views as the run's, with fresh sensor noise), matched and projected
// as the mapping pipeline does, and compared (compareScans), truth beyond the configured stereo
// max_disparity counted as too near. Moving obstacles stand where they start. Throws
// std::invalid_argument if `every` is 0.
ScanAccuracy scanAccuracyAlongPath(const ExplorationConfig& config, const World& world,
                                   const std::vector<mrpt::poses::CPose2D>& poses, size_t every,
                                   const ScanAccuracyOptions& options);

}  // namespace stereonav
