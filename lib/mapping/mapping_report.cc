#include "mapping/mapping_report.h"

#include <cstdio>
#include <sstream>

namespace stereonav {
namespace {

std::string jsonString(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': quoted += "\\\""; break;
      case '\\': quoted += "\\\\"; break;
      case '\n': quoted += "\\n"; break;
      case '\t': quoted += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
          quoted += escaped;
        } else {
          quoted += c;
        }
    }
  }
  return quoted + "\"";
}

// JSON has no infinities or NaNs; rates are finite by construction, this keeps it that way.
std::string jsonNumber(double value) {
  if (!(value == value) || value > 1e300 || value < -1e300) return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

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
  if (damage) text << "; stopped at damage: " << damage->describe(rawlog_path);
  if (interrupted) text << "; interrupted (Ctrl-C), map saved so far";
  return text.str();
}

std::string MappingReport::toJson() const {
  std::ostringstream json;
  json << "{\n"
       << "  \"rawlog\": " << jsonString(rawlog_path) << ",\n"
       << "  \"complete\": " << (complete() ? "true" : "false") << ",\n"
       << "  \"frames\": " << frames_mapped << ",\n"
       << "  \"frames_without_odometry\": " << frames_without_odometry << ",\n"
       << "  \"skipped_frames\": {\n    \"total\": " << skipped.total();
  for (size_t reason = 0; reason < kRejectReasonCount; ++reason) {
    json << ",\n    " << jsonString(kRejectReasonKeys[reason]) << ": " << skipped.count[reason];
  }
  json << ",\n    \"summary\": " << jsonString(skipped.summary()) << "\n  },\n";
  if (damage) {
    json << "  \"damage\": {\"object_index\": " << damage->object_index
         << ", \"byte_offset\": " << damage->byte_offset
         << ", \"error\": " << jsonString(damage->error)
         << ", \"description\": " << jsonString(damage->describe(rawlog_path)) << "},\n";
  } else {
    json << "  \"damage\": null,\n";
  }
  json << "  \"interrupted\": " << (interrupted ? "true" : "false") << ",\n"
       << "  \"calibration_warnings\": [";
  for (size_t i = 0; i < calibration_warnings.size(); ++i) {
    json << (i ? ", " : "") << jsonString(calibration_warnings[i]);
  }
  json << "],\n"
       << "  \"matched_pixel_fraction\": " << jsonNumber(matched_pixel_fraction) << ",\n"
       << "  \"valid_pixel_fraction\": " << jsonNumber(kept_pixel_fraction) << ",\n"
       << "  \"time_per_stage_ms\": {";
  for (size_t stage = 0; stage < kPipelineStageCount; ++stage) {
    const auto which = static_cast<PipelineStage>(stage);
    json << (stage ? ", " : "") << jsonString(stageName(which)) << ": "
         << jsonNumber(times.meanMs(which));
  }
  json << ", \"total\": " << jsonNumber(times.meanFrameMs()) << "},\n"
       << "  \"pipeline_frames_per_second\": " << jsonNumber(pipelineFramesPerSecond()) << ",\n"
       << "  \"wall_seconds\": " << jsonNumber(wall_seconds) << ",\n"
       << "  \"frames_per_second\": "
       << jsonNumber(wall_seconds > 0.0 ? frames_mapped / wall_seconds : 0.0) << "\n"
       << "}\n";
  return json.str();
}

}  // namespace stereonav
