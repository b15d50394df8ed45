#include "explorer/exploration_run.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/core/Clock.h>
#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/math/wrap2pi.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <random>
#include <sstream>

#include "column_projection/virtual_range_scan.h"
#include "common/atomic_file.h"
#include "explorer/frontier_explorer.h"
#include "explorer/reactive_nav_log.h"
#include "explorer/simulated_robot_interface.h"
#include "mapping/map_outputs.h"
#include "mapping/stereo_mapper.h"
#include "observations/rig_frame.h"
#include "simulator/footprint_overlap.h"
#include "simulator/moving_traffic.h"
#include "simulator/simulation_recorder.h"

namespace stereonav {
namespace {

constexpr double kRunEpoch = 946684800.0;  // as SimulationRecorder stamps frames
constexpr double kTimeSlack = 1e-9;
constexpr double kStartJitterM = 0.5;
// The robot's sensed obstacles (for the explorer's guard) are the stereo scan's within this range.
constexpr double kSensedRangeM = 4.0;
// A moving obstacle this close to the body at a contact is what the robot touched.
constexpr double kContactSlackM = 0.01;

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

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    out += c;
  }
  return out + "\"";
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
  writeFileAtomically(file, [&](const std::string& temp) {
    if (!cv::imwrite(temp, image)) throw std::runtime_error(file + ": cannot write the image");
  });
}

// One frame of the run as MRPT's reactive navigators log it (reactive_nav_log.h).
mrpt::nav::CLogFileRecord navigationRecord(mrpt::system::TTimeStamp stamp, const mrpt::poses::CPose2D& map_pose,
                                           const DifferentialDriveRobot& robot,
                                           CSimulatedRobotInterface& robot_interface, const ExplorerStatus& status,
                                           double robot_radius_m) {
  mrpt::nav::CLogFileRecord record;
  record.timestamps["tim_start_iteration"] = stamp;
  record.robotPoseLocalization = map_pose.asTPose();
  record.robotPoseOdometry = robot.odometry().asTPose();
  mrpt::system::TTimeStamp sensed_stamp;
  robot_interface.senseObstacles(record.WS_Obstacles, sensed_stamp);
  record.WS_Obstacles_original = record.WS_Obstacles;
  if (status.has_target) {
    const mrpt::math::TPoint2D target = map_pose.inverseComposePoint(mrpt::math::TPoint2D(status.target_x, status.target_y));
    record.WS_targets_relative.emplace_back(target.x, target.y, 0.0);
  }
  auto command = std::make_shared<mrpt::kinematics::CVehicleVelCmd_DiffDriven>();
  command->lin_vel = status.speed_command;
  command->ang_vel = status.turn_rate_command;
  record.cmd_vel = command;
  record.cur_vel_local = mrpt::math::TTwist2D(robot.speed(), 0.0, robot.turnRate());
  record.cur_vel = record.cur_vel_local;
  record.cur_vel.rotate(map_pose.phi());
  record.robotShape_radius = robot_radius_m;
  record.values["frontiers"] = static_cast<double>(status.frontiers);
  record.values["cost_to_go_m"] = status.cost_to_go;
  record.values["free_travel_m"] = status.free_travel_m;
  record.values["collisions"] = robot.collisionCount();
  record.additional_debug_msgs["phase"] = phaseName(status.phase);
  return record;
}

}  // namespace

ExplorationConfig loadExplorationConfig(const std::string& path) {
  if (!std::ifstream(path)) throw ConfigError(path + ": cannot open the configuration file");
  const mrpt::config::CConfigFile file(path);
  ExplorationConfig config;
  config.simulator = loadSimulatorConfig(file, path);
  config.explorer = loadIniSection(file, "explorer", [&](IniSection& section) {
    ExplorerOptions options = loadExplorerOptions(section);
    const std::string source = section.getString("pose_source", "odometry");
    if (source == "odometry") {
      config.pose_source = PoseSource::kOdometry;
    } else if (source == "ground_truth") {
      config.pose_source = PoseSource::kGroundTruth;
    } else {
      throw ConfigError("[explorer] pose_source: '" + source + "' is neither odometry nor ground_truth");
    }
    return options;
  }, path);
  try {
    config.mapping = loadMappingOptions(file);
  } catch (const ConfigError& error) {
    throw ConfigError(path + ": " + error.what());
  }
  if (config.explorer.robot_radius_m < config.simulator.robot.radius_m) {
    throw ConfigError(path + ": [explorer] robot_radius_m: smaller than the robot's ([sim_robot] radius_m)");
  }
  return config;
}

std::string ExplorationReport::summary() const {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << "explored " << coverage.free_area_m2 << " m2 free ("
       << 100.0 * coverage.coverage << "% of the reachable free space; " << 100.0 * coverage.seen_coverage
       << "% seen), drove " << distance_m << " m in "
       << sim_time_s << " s simulated (" << wall_time_s << " s wall), " << collisions
       << " collision(s); stopped: " << stop_reason;
  return text.str();
}

std::string ExplorationReport::toJson() const {
  std::ostringstream json;
  json << std::setprecision(6) << "{\n"
       << "  \"explored_area_m2\": " << coverage.known_area_m2 << ",\n"
       << "  \"free_area_m2\": " << coverage.free_area_m2 << ",\n"
       << "  \"reachable_free_m2\": " << coverage.reachable_free_m2 << ",\n"
       << "  \"covered_reachable_free_m2\": " << coverage.covered_m2 << ",\n"
       << "  \"coverage\": " << coverage.coverage << ",\n"
       << "  \"seen_reachable_free_m2\": " << coverage.seen_m2 << ",\n"
       << "  \"seen_coverage\": " << coverage.seen_coverage << ",\n"
       << "  \"distance_m\": " << distance_m << ",\n"
       << "  \"sim_time_s\": " << sim_time_s << ",\n"
       << "  \"wall_time_s\": " << wall_time_s << ",\n"
       << "  \"collisions\": " << collisions << ",\n"
       << "  \"collision_events\": [";
  for (size_t i = 0; i < collision_events.size(); ++i) {
    const CollisionEvent& event = collision_events[i];
    json << (i == 0 ? "\n" : ",\n") << "    {\"t\": " << event.time_s << ", \"x\": " << event.x << ", \"y\": " << event.y
         << ", \"speed\": " << event.speed_mps << ", \"with\": " << jsonString(event.with) << "}";
  }
  json << (collision_events.empty() ? "],\n" : "\n  ],\n")
       << "  \"blocked_reversals\": " << blocked_reversals << ",\n"
       << "  \"top_speed_mps\": " << top_speed_mps << ",\n"
       << "  \"frames\": " << frames << ",\n"
       << "  \"frame_rate_hz\": " << frame_rate_hz << ",\n"
       << "  \"pipeline_ms_per_frame\": " << pipeline_ms_per_frame << ",\n"
       << "  \"start_pose\": [" << start_x << ", " << start_y << ", " << start_phi << "],\n"
       << "  \"stop_reason\": " << jsonString(stop_reason) << "\n"
       << "}\n";
  return json.str();
}

ExplorationReport runExploration(const World& world, const ExplorationConfig& config, const ExplorationJob& job) {
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

  DifferentialDriveRobot robot(world, robot_options, start);
  RigRenderer renderer(world, config.simulator.rig, sensor);
  MovingTraffic traffic(world);
  StereoMapper mapper(config.mapping, config.simulator.rig);
  FrontierExplorer explorer(config.explorer);
  double time = 0.0;
  CSimulatedRobotInterface robot_interface(robot, time, config.pose_source);
  std::optional<SimulationRecorder> recorder;
  if (!job.record_rawlog.empty()) recorder.emplace(job.record_rawlog, config.simulator.rawlog, config.simulator.rig);
  const OccupancyScale& scale = config.mapping.grid.stereo.update.scale;

  ExplorationReport report;
  report.start_x = start.x();
  report.start_y = start.y();
  report.start_phi = start.phi();
  report.frame_rate_hz = config.simulator.simulation.frame_rate_hz;
  std::vector<mrpt::poses::CPose2D> map_path;
  ReactiveNavLog reactive_navlog;
  std::ostringstream path_text, truth_text, navlog;
  path_text << std::setprecision(9);
  truth_text << std::setprecision(9);
  navlog << std::setprecision(6)
         << "t,odometry_x,odometry_y,odometry_phi,true_x,true_y,true_phi,speed,turn_rate,phase,frontiers,"
            "target_x,target_y,cost_to_go,speed_command,turn_rate_command,free_travel,collisions\n";

  const double dt = 1.0 / config.simulator.simulation.control_rate_hz;
  size_t step = 0;
  while (true) {
    if (time >= static_cast<double>(report.frames) / config.simulator.simulation.frame_rate_hz - kTimeSlack) {
      SimulatedFrame frame;
      frame.time_s = time;
      frame.images = renderer.render(robot.pose(), time, traffic.solids());
      frame.true_pose = robot.pose();
      frame.odometry = robot.odometry();
      frame.collisions = robot.collisionCount();
      if (recorder) recorder->record(frame);
      RigFrame rig_frame;
      rig_frame.timestamp = mrpt::Clock::fromDouble(kRunEpoch + time);
      rig_frame.reference = frame.images.reference;
      rig_frame.secondaries.assign(frame.images.secondaries.begin(), frame.images.secondaries.end());
      rig_frame.rig = config.simulator.rig;
      rig_frame.odometry = frame.odometry;
      const mrpt::poses::CPose2D map_pose = robot_interface.pose();
      mapper.process(rig_frame, map_pose);
      mrpt::obs::CObservation2DRangeScan sensed =
          makeVirtualRangeScan(mapper.disparityScan().scan, config.simulator.rig, kSensedRangeM);
      sensed.timestamp = rig_frame.timestamp;
      robot_interface.setSensedObstacles(sensed, map_pose);
      explorer.updateMap(gridOfMap(mapper.map(), scale), map_pose);
      ++report.frames;
      map_path.push_back(map_pose);
      path_text << time << " " << map_pose.x() << " " << map_pose.y() << " " << map_pose.phi() << "\n";
      truth_text << time << " " << frame.true_pose.x() << " " << frame.true_pose.y() << " " << frame.true_pose.phi()
                 << "\n";
      const ExplorerStatus& status = explorer.status();
      reactive_navlog.append(navigationRecord(rig_frame.timestamp, map_pose, robot, robot_interface, status,
                                              robot_options.radius_m));
      navlog << time << "," << frame.odometry.x() << "," << frame.odometry.y() << "," << frame.odometry.phi() << ","
             << frame.true_pose.x() << "," << frame.true_pose.y() << "," << frame.true_pose.phi() << ","
             << robot.speed() << "," << robot.turnRate() << "," << phaseName(status.phase) << ","
             << status.frontiers << "," << (status.has_target ? status.target_x : NAN) << ","
             << (status.has_target ? status.target_y : NAN) << "," << status.cost_to_go << ","
             << status.speed_command << "," << status.turn_rate_command << "," << status.free_travel_m << ","
             << robot.collisionCount() << "\n";
    }
    if (time >= max_time - kTimeSlack) {
      report.stop_reason = "time limit of " + std::to_string(static_cast<int>(max_time)) + " s reached";
      break;
    }
    if (!explorer.controlStep(robot_interface)) {
      report.stop_reason = explorer.stopReason();
      break;
    }
    const mrpt::poses::CPose2D before = robot.pose();
    const double speed_before = robot.speed();
    const int collisions_before = robot.collisionCount();
    traffic.advance(dt, robot.pose(), robot.speed(), robot_options.radius_m);
    robot.step(robot_interface.commandedSpeed(), robot_interface.commandedTurnRate(), dt, traffic.solids());
    if (robot.collisionCount() > collisions_before) {
      CollisionEvent event{time + dt, robot.pose().x(), robot.pose().y(), speed_before, "static"};
      for (size_t i = 0; i < traffic.solids().size(); ++i) {
        if (solidOverlapsDisc(traffic.solids()[i], robot.pose().x(), robot.pose().y(), robot_options.radius_m + kContactSlackM)) {
          event.with = world.moving_obstacles[i].name;
        }
      }
      report.collision_events.push_back(event);
    }
    report.distance_m += std::hypot(robot.pose().x() - before.x(), robot.pose().y() - before.y());
    report.top_speed_mps = std::max(report.top_speed_mps, std::abs(robot.speed()));
    time = static_cast<double>(++step) * dt;
  }
  if (recorder) recorder->finish();

  report.sim_time_s = time;
  report.collisions = robot.collisionCount();
  report.blocked_reversals = robot_interface.apparentCollisions();
  report.pipeline_ms_per_frame = mapper.times().meanFrameMs();
  const DisparityTaggedGrid grid = gridOfMap(mapper.map(), scale);
  report.coverage = measureCoverage(truth, grid, robot_options.radius_m, start.x(), start.y());
  saveMapOutputs(mapper.map(), scale, map_path, job.output_prefix);
  writeStringAtomically(job.output_prefix + ".path.txt", path_text.str());
  writeStringAtomically(job.output_prefix + ".truth.txt", truth_text.str());
  writeStringAtomically(job.output_prefix + ".navlog.csv", navlog.str());
  reactive_navlog.save(job.output_prefix + ".reactivenavlog");
  savePathImage(grid, map_path, job.output_prefix + ".path.png");
  const cv::Mat3b plan = explorer.planImage();
  if (!plan.empty()) {
    writeFileAtomically(job.output_prefix + ".plan.png", [&](const std::string& temporary) {
      if (!cv::imwrite(temporary, plan)) throw std::runtime_error(job.output_prefix + ".plan.png: cannot write the image");
    });
  }
  report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  writeStringAtomically(job.output_prefix + ".stats.json", report.toJson());
  return report;
}

}  // namespace stereonav
