#include "closed_loop/exploration_report.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "common/json_writer.h"

namespace stereonav {

double ExplorationReport::speedUp() const { return wall_time_s > 0.0 ? sim_time_s / wall_time_s : 0.0; }

double ExplorationReport::speedUpWithoutRendering() const {
  const double robot_s = wall_time_s - render_wall_s;
  return robot_s > 0.0 ? sim_time_s / robot_s : 0.0;
}

std::string ExplorationReport::summary() const {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << "explored " << coverage.free_area_m2 << " m2 free ("
       << 100.0 * coverage.coverage << "% of the reachable free space; " << 100.0 * coverage.seen_coverage
       << "% seen), drove " << distance_m << " m in " << sim_time_s << " s simulated (" << wall_time_s
       << " s wall, " << render_wall_s << " s of it rendering), " << collisions << " collision(s), pose error RMS "
       << std::setprecision(3) << trajectory_error.rms_m << " m (max " << trajectory_error.max_m << " m); stopped: " << stop_reason;
  return text.str();
}

std::string ExplorationReport::toJson() const {
  JsonWriter json;
  json.beginObject()
      .key("explored_area_m2").value(coverage.known_area_m2)
      .key("free_area_m2").value(coverage.free_area_m2)
      .key("reachable_free_m2").value(coverage.reachable_free_m2)
      .key("covered_reachable_free_m2").value(coverage.covered_m2)
      .key("coverage").value(coverage.coverage)
      .key("seen_reachable_free_m2").value(coverage.seen_m2)
      .key("seen_coverage").value(coverage.seen_coverage)
      .key("distance_m").value(distance_m)
      .key("sim_time_s").value(sim_time_s)
      .key("wall_time_s").value(wall_time_s)
      .key("render_wall_s").value(render_wall_s)
      .key("collisions").value(collisions)
      .key("collision_events").beginArray();
  for (const CollisionEvent& event : collision_events) {
    json.beginObject()
        .key("t").value(event.time_s)
        .key("x").value(event.x)
        .key("y").value(event.y)
        .key("speed").value(event.speed_mps)
        .key("with").value(event.with)
        .endObject();
  }
  json.endArray()
      .key("blocked_reversals").value(blocked_reversals)
      .key("top_speed_mps").value(top_speed_mps)
      .key("frames").value(frames)
      .key("frame_rate_hz").value(frame_rate_hz)
      .key("pipeline_ms_per_frame").value(pipeline_ms_per_frame)
      .key("trajectory_error").beginObject()
      .key("rms_m").value(trajectory_error.rms_m)
      .key("max_m").value(trajectory_error.max_m)
      .key("final_m").value(trajectory_error.final_m)
      .key("rms_heading_deg").value(trajectory_error.rms_heading_deg)
      .key("max_heading_deg").value(trajectory_error.max_heading_deg)
      .endObject()
      .key("frames_localized").value(frames_localized)
      .key("frames_floor_measured").value(frames_floor_measured)
      .key("start_pose").beginArray().value(start_x).value(start_y).value(start_phi).endArray()
      .key("stop_reason").value(stop_reason)
      .key("time_to_coverage_s").beginObject();
  for (size_t i = 0; i < kCoverageMilestones.size(); ++i) {
    json.key(std::to_string(static_cast<int>(std::lround(100.0 * kCoverageMilestones[i]))));
    if (time_to_coverage_s[i]) {
      json.value(*time_to_coverage_s[i]);
    } else {
      json.null();
    }
  }
  json.endObject().endObject();
  return json.str();
}

}  // namespace stereonav
