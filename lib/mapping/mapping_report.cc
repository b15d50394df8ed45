#include "mapping/mapping_report.h"

#include <sstream>

#include "common/json_writer.h"

namespace stereonav {
namespace {

constexpr const char* kRejectReasonKeys[kRejectReasonCount] = {
    "missing_calibration", "wrong_image_format", "not_rectified", "missing_image",
    "wrong_camera_count", "missing_partner"};

}  // namespace

double MappingReport::pipelineFramesPerSecond() const {
  const double ms = times.meanFrameMs();
  return ms > 0.0 ? 1000.0 / ms : 0.0;
}

std::string MappingReport::summary() const {
  std::ostringstream text;
  char numbers[160];
  std::snprintf(numbers, sizeof numbers,
                "mapped %zu frames in %.1f s (%.1f frames/s overall; pipeline %.2f ms/frame = "
                "%.0f frames/s)",
                frames_mapped, wall_seconds, wall_seconds > 0.0 ? frames_mapped / wall_seconds : 0.0,
                times.meanFrameMs(), pipelineFramesPerSecond());
  text << numbers;
  if (skipped.total() > 0) text << "; " << skipped.summary();
  if (frames_without_odometry > 0) {
    text << "; " << frames_without_odometry << " frames without odometry (mapped at the previous pose)";
  }
  if (frames_localized > 0) text << "; " << frames_localized << " frames corrected by scan matching";
  if (frames_floor_measured > 0) text << "; " << frames_floor_measured << " steps measured on the floor";
  if (damage) text << "; stopped at damage: " << damage->describe(rawlog_path);
  if (interrupted) text << "; interrupted (Ctrl-C), map saved so far";
  return text.str();
}

std::string MappingReport::toJson() const {
  JsonWriter json;
  json.beginObject()
      .key("rawlog").value(rawlog_path)
      .key("complete").value(complete())
      .key("frames").value(frames_mapped)
      .key("frames_without_odometry").value(frames_without_odometry)
      .key("frames_localized").value(frames_localized)
      .key("frames_floor_measured").value(frames_floor_measured)
      .key("skipped_frames").beginObject().key("total").value(skipped.total());
  for (size_t reason = 0; reason < kRejectReasonCount; ++reason) {
    json.key(kRejectReasonKeys[reason]).value(skipped.count[reason]);
  }
  json.key("summary").value(skipped.summary()).endObject().key("damage");
  if (damage) {
    json.beginObject()
        .key("object_index").value(damage->object_index)
        .key("byte_offset").value(damage->byte_offset)
        .key("error").value(damage->error)
        .key("description").value(damage->describe(rawlog_path))
        .endObject();
  } else {
    json.null();
  }
  json.key("interrupted").value(interrupted).key("calibration_warnings").beginArray();
  for (const std::string& warning : calibration_warnings) json.value(warning);
  json.endArray().key("output_errors").beginArray();
  for (const std::string& error : output_errors) json.value(error);
  json.endArray()
      .key("matched_pixel_fraction").value(matched_pixel_fraction)
      .key("valid_pixel_fraction").value(kept_pixel_fraction)
      .key("time_per_stage_ms").beginObject();
  for (size_t stage = 0; stage < kPipelineStageCount; ++stage) {
    const auto which = static_cast<PipelineStage>(stage);
    json.key(stageName(which)).value(times.meanMs(which));
  }
  json.key("total").value(times.meanFrameMs()).endObject()
      .key("pipeline_frames_per_second").value(pipelineFramesPerSecond())
      .key("wall_seconds").value(wall_seconds)
      .key("frames_per_second").value(wall_seconds > 0.0 ? frames_mapped / wall_seconds : 0.0)
      .endObject();
  return json.str();
}

}  // namespace stereonav
