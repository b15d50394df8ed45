#pragma once

#include <array>
#include <chrono>
#include <cstddef>

namespace stereonav {

// The steps of the per-frame pipeline, in order.
enum class PipelineStage { kGrey, kStereo, kSpikeRemoval, kProjection, kVirtualScan, kGridUpdate };
constexpr size_t kPipelineStageCount = 6;

// "grey", "stereo", "spike_removal", "projection", "virtual_scan", "grid_update".
const char* stageName(PipelineStage stage);

// Wall time spent in each stage, summed over frames.
class StageTimes {
 public:
  void add(PipelineStage stage, std::chrono::steady_clock::duration duration) {
    total_[static_cast<size_t>(stage)] += duration;
  }
  void countFrame() { ++frames_; }

  size_t frames() const { return frames_; }
  double totalMs(PipelineStage stage) const;
  double meanMs(PipelineStage stage) const;  // per frame; 0 before the first frame
  double meanFrameMs() const;                // all stages
  void clear() { *this = StageTimes(); }

 private:
  std::array<std::chrono::steady_clock::duration, kPipelineStageCount> total_{};
  size_t frames_ = 0;
};

// Adds the time from construction to destruction to one stage.
class ScopedStageTimer {
 public:
  ScopedStageTimer(StageTimes& times, PipelineStage stage)
      : times_(times), stage_(stage), start_(std::chrono::steady_clock::now()) {}
  ~ScopedStageTimer() { times_.add(stage_, std::chrono::steady_clock::now() - start_); }

  ScopedStageTimer(const ScopedStageTimer&) = delete;
  ScopedStageTimer& operator=(const ScopedStageTimer&) = delete;

 private:
  StageTimes& times_;
  PipelineStage stage_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace stereonav
