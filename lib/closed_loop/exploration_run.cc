#include "closed_loop/exploration_run.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <random>

#include "closed_loop/navigation_trace.h"
#include "closed_loop/simulated_robot_interface.h"
#include "column_projection/range_top_points.h"
#include "common/atomic_file.h"
#include "common/image_file.h"
#include "evaluation/trajectory_error.h"
#include "explorer/frontier_explorer.h"
#include "mapping/frame_localizer.h"
#include "mapping/map_outputs.h"
#include "mapping/stereo_mapper.h"
#include "simulator/ground_truth_map.h"
#include "simulator/simulation.h"
#include "simulator/simulation_recorder.h"

namespace stereonav {
namespace {

constexpr double kStartJitterM = 0.5;
// The robot's sensed obstacles (for the explorer's guard) are the stereo scan's within this range.
constexpr double kSensedRangeM = 4.0;

// A start pose near the world's for this seed: a body's disc (plus 0.1 m) of true free floor.
mrpt::poses::CPose2D seededStart(const World& world, const GroundTruthMap& truth, double radius, int seed) {
  std::mt19937 random(static_cast<std::mt19937::result_type>(seed));
  std::uniform_real_distribution<double> offset(-kStartJitterM, kStartJitterM), heading(-M_PI, M_PI);
  const auto free_disc = [&](double x, double y) {
    const double reach = radius + 0.1;
    for (double dy = -reach; dy <= reach; dy += truth.resolution() * 0.5) {
      for (double dx = -reach; dx <= reach; dx += truth.resolution() * 0.5) {
        if (dx * dx + dy * dy > reach * reach) continue;
        const int ix = static_cast<int>(std::floor((x + dx - truth.xMin()) / truth.resolution()));
        const int iy = static_cast<int>(std::floor((y + dy - truth.yMin()) / truth.resolution()));
        if (ix < 0 || iy < 0 || ix >= truth.width() || iy >= truth.height()) return false;
        if (truth.cell(ix, iy) != GroundTruthMap::kFree) return false;
      }
    }
    return true;
  };
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const double x = world.start_pose[0] + offset(random), y = world.start_pose[1] + offset(random);
    const double phi = heading(random);
    if (free_disc(x, y)) return mrpt::poses::CPose2D(x, y, phi);
  }
  return mrpt::poses::CPose2D(world.start_pose[0], world.start_pose[1], heading(random));
}

// The map (white free, black occupied, grey unknown, top row = max y) with the path it was built along.
void savePathImage(const DisparityTaggedGrid& grid, const std::vector<mrpt::poses::CPose2D>& path,
                   const std::string& file) {
  cv::Mat1b grey(grid.height(), grid.width());
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      grey(grid.height() - 1 - row, col) = static_cast<uint8_t>(255 - grid.occupancy(col, row));
    }
  }
  constexpr int kScale = 4;  // pixels per cell, so the path line is thinner than a cell
  cv::Mat3b image;
  cv::cvtColor(grey, image, cv::COLOR_GRAY2BGR);
  cv::resize(image, image, cv::Size(), kScale, kScale, cv::INTER_NEAREST);
  const auto pixel = [&](const mrpt::poses::CPose2D& pose) {
    return cv::Point(static_cast<int>((pose.x() - grid.minX()) / grid.resolution() * kScale),
                     static_cast<int>((grid.maxY() - pose.y()) / grid.resolution() * kScale));
  };
  for (size_t i = 1; i < path.size(); ++i) {
    cv::line(image, pixel(path[i - 1]), pixel(path[i]), cv::Scalar(0, 0, 255), 1, cv::LINE_AA);
  }
  if (!path.empty()) {
    cv::circle(image, pixel(path.front()), 2 * kScale, cv::Scalar(0, 160, 0), -1);
    cv::circle(image, pixel(path.back()), 2 * kScale, cv::Scalar(255, 0, 0), -1);
  }
  writeImageFile(file, image);
}

// The mapping options of the loop: a localized run matches each frame's virtual scan.
MappingOptions closedLoopMappingOptions(const ExplorationConfig& config) {
  MappingOptions options = config.mapping;
  if (config.pose_source == MapPoseSource::kLocalized) options.mapper.virtual_scans = true;
  return options;
}

// The mapping side of the loop: every frame goes through the stereo pipeline into the map, and
// the newest scan and map go to the robot's sensor and the explorer. A localized run first
// matches the frame's scan against the map so far, as `stereonav map --poses localized` does,
// so a recorded run replays to the same map and trajectory.
class ClosedLoopMapper {
 public:
  ClosedLoopMapper(const ExplorationConfig& config, CSimulatedRobotInterface& robot_interface,
                   FrontierExplorer& explorer)
      : config_(config),
        mapper_(closedLoopMappingOptions(config), config.simulator.rig),
        robot_interface_(robot_interface),
        explorer_(explorer) {
    if (config.pose_source == MapPoseSource::kLocalized) {
      localizer_ = std::make_unique<FrameLocalizer>(config.mapping.localization, config.simulator.rig);
    }
  }

  // Maps `frame` at the pose the navigator has (after localizing it); returns that pose.
  mrpt::poses::CPose2D process(const SimulatedFrame& frame) {
    const RigFrame rig_frame = rigFrameOf(frame, config_.simulator.rig);
    mapper_.observe(rig_frame);
    if (localizer_) {
      const ScanMatch& match = localizer_->update(frame.odometry, mapper_, grid());
      if (match.corrected) ++frames_localized_;
      robot_interface_.setLocalizedPose(match.pose, frame.odometry);
    }
    const mrpt::poses::CPose2D map_pose = robot_interface_.pose();
    mapper_.insertLastObservation(map_pose);
    const DisparityScan& scan = mapper_.disparityScan().scan;
    robot_interface_.setSensedScan(scan, config_.simulator.rig, config_.explorer.robot_radius_m, kSensedRangeM,
                                   rig_frame.timestamp, map_pose);
    std::vector<mrpt::math::TPoint2D> range_top = rangeTopPoints(scan, config_.simulator.rig);
    for (mrpt::math::TPoint2D& point : range_top) map_pose.composePoint(mrpt::math::TPoint2D(point), point);
    explorer_.rememberObstacles(range_top);
    explorer_.updateMap(grid(), map_pose);
    return map_pose;
  }

  // The map as a disparity-tagged grid: the stereo map's own, not a copy of it each frame.
  const DisparityTaggedGrid& grid() const {
    if (const DisparityTaggedGrid* own = ownGridOf(mapper_.map())) return *own;
    return converted_.emplace(gridOfMap(mapper_.map(), config_.mapping.grid.stereo.update.scale));
  }
  const StereoMapper& mapper() const { return mapper_; }
  size_t framesLocalized() const { return frames_localized_; }
  size_t framesFloorMeasured() const { return localizer_ ? localizer_->floorMeasuredSteps() : 0; }

 private:
  const ExplorationConfig& config_;
  StereoMapper mapper_;
  CSimulatedRobotInterface& robot_interface_;
  FrontierExplorer& explorer_;
  std::unique_ptr<FrameLocalizer> localizer_;  // localized runs only
  size_t frames_localized_ = 0;
  mutable std::optional<DisparityTaggedGrid> converted_;  // grid() of a map of another type
};

void fillFromSimulation(ExplorationReport& report, const Simulation& simulation, const mrpt::poses::CPose2D& start,
                        double frame_rate_hz) {
  report.start_x = start.x();
  report.start_y = start.y();
  report.start_phi = start.phi();
  report.frame_rate_hz = frame_rate_hz;
  report.frames = simulation.frames();
  report.distance_m = simulation.distance();
  report.top_speed_mps = simulation.topSpeed();
  report.collision_events = simulation.collisionEvents();
  report.sim_time_s = simulation.time();
  report.collisions = simulation.robot().collisionCount();
}

// Times the milestones `coverage` reaches first at `time_s`.
void recordMilestones(ExplorationReport& report, const ExplorationCoverage& coverage, double time_s) {
  for (size_t i = 0; i < ExplorationReport::kCoverageMilestones.size(); ++i) {
    if (!report.time_to_coverage_s[i] && coverage.coverage >= ExplorationReport::kCoverageMilestones[i]) {
      report.time_to_coverage_s[i] = time_s;
    }
  }
}

// <prefix>.path.png: the map with the path; <prefix>.plan.png: the explorer's last plan, if any.
void savePathAndPlanImages(const DisparityTaggedGrid& grid, const std::vector<mrpt::poses::CPose2D>& map_path,
                           const FrontierExplorer& explorer, const std::string& prefix) {
  savePathImage(grid, map_path, prefix + ".path.png");
  const cv::Mat3b plan = explorer.planImage();
  if (!plan.empty()) writeImageFile(prefix + ".plan.png", plan);
}

}  // namespace

ExplorationReport runExploration(const World& world, const ExplorationConfig& config, const ExplorationJob& job,
                                 const ExplorationCallbacks& callbacks) {
  const auto wall_start = std::chrono::steady_clock::now();
  SensorOptions sensor = config.simulator.sensor;
  DifferentialDriveOptions robot_options = config.simulator.robot;
  const GroundTruthMap truth(world, config.simulator.ground_truth);
  mrpt::poses::CPose2D start(world.start_pose[0], world.start_pose[1], world.start_pose[2]);
  if (job.seed) {
    sensor.seed = *job.seed;
    robot_options.seed = *job.seed;
    start = seededStart(world, truth, robot_options.radius_m, *job.seed);
  }
  const double max_time = job.max_time_s.value_or(config.simulator.simulation.max_duration_s);
  const size_t frame_limit =
      static_cast<size_t>(std::floor(max_time * config.simulator.simulation.frame_rate_hz)) + 1;

  Simulation simulation(world, config.simulator.rig, sensor, robot_options, config.simulator.simulation, start);
  FrontierExplorer explorer(config.explorer);
  CSimulatedRobotInterface robot_interface(simulation, config.pose_source);
  ClosedLoopMapper mapper(config, robot_interface, explorer);
  std::optional<SimulationRecorder> recorder;
  if (!job.record_rawlog.empty()) recorder.emplace(job.record_rawlog, config.simulator.rawlog, config.simulator.rig);
  std::vector<mrpt::poses::CPose2D> map_path, true_path;
  NavigationTrace trace;
  const ReachableFloor reachable(truth, robot_options.radius_m, start.x(), start.y());

  ExplorationReport report;
  double next_coverage_sample_s = job.coverage_sample_period_s;
  while (true) {
    if (simulation.frameDue()) {
      const auto render_start = std::chrono::steady_clock::now();
      const SimulatedFrame frame = simulation.renderFrame();
      report.render_wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - render_start).count();
      if (recorder) recorder->record(frame);
      map_path.push_back(mapper.process(frame));
      true_path.push_back(frame.true_pose);
      trace.append(frame, map_path.back(), simulation.robot(), robot_interface, explorer.status(),
                   robot_options.radius_m);
      if (callbacks.on_frame) callbacks.on_frame(map_path.size(), frame_limit);
      if (job.coverage_sample_period_s > 0.0 && simulation.time() >= next_coverage_sample_s) {
        recordMilestones(report, reachable.measure(mapper.grid()), simulation.time());
        next_coverage_sample_s += job.coverage_sample_period_s;
      }
    }
    if (callbacks.stop_requested && callbacks.stop_requested()) {
      report.stop_reason = "interrupted";
      report.interrupted = true;
      break;
    }
    if (simulation.timeUp(max_time)) {
      report.stop_reason = "time limit of " + std::to_string(static_cast<int>(max_time)) + " s reached";
      break;
    }
    if (!explorer.controlStep(robot_interface)) {
      report.stop_reason = explorer.stopReason();
      break;
    }
    simulation.step(robot_interface.commandedSpeed(), robot_interface.commandedTurnRate());
  }
  if (recorder) recorder->finish();

  fillFromSimulation(report, simulation, start, config.simulator.simulation.frame_rate_hz);
  report.pipeline_ms_per_frame = mapper.mapper().times().meanFrameMs();
  report.frames_localized = mapper.framesLocalized();
  report.frames_floor_measured = mapper.framesFloorMeasured();
  if (!map_path.empty()) report.trajectory_error = trajectoryError(map_path, true_path);
  const DisparityTaggedGrid grid = mapper.grid();
  report.coverage = reachable.measure(grid);
  recordMilestones(report, report.coverage, simulation.time());
  saveMapOutputs(mapper.mapper().map(), config.mapping.grid.stereo.update.scale, map_path, job.output_prefix);
  trace.save(job.output_prefix);
  savePathAndPlanImages(grid, map_path, explorer, job.output_prefix);
  report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  writeStringAtomically(job.output_prefix + ".stats.json", report.toJson());
  return report;
}

}  // namespace stereonav
