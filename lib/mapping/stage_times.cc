#include "mapping/stage_times.h"

namespace stereonav {

const char* stageName(PipelineStage stage) {
  switch (stage) {
    case PipelineStage::kGrey: return "grey";
    case PipelineStage::kStereo: return "stereo";
    case PipelineStage::kSpikeRemoval: return "spike_removal";
    case PipelineStage::kProjection: return "projection";
    case PipelineStage::kVirtualScan: return "virtual_scan";
    case PipelineStage::kGridUpdate: return "grid_update";
  }
  return "?";
}

double StageTimes::totalMs(PipelineStage stage) const {
  return std::chrono::duration<double, std::milli>(total_[static_cast<size_t>(stage)]).count();
}

double StageTimes::meanMs(PipelineStage stage) const {
  return frames_ == 0 ? 0.0 : totalMs(stage) / static_cast<double>(frames_);
}

double StageTimes::meanFrameMs() const {
  double sum = 0.0;
  for (size_t stage = 0; stage < kPipelineStageCount; ++stage) {
    sum += meanMs(static_cast<PipelineStage>(stage));
  }
  return sum;
}

}  // namespace stereonav
