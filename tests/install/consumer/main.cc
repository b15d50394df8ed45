// Declares the stereo grid in an MRPT map definition, inserts one disparity scan and checks the
// cell the sensor model must have marked occupied; exits non-zero with a message otherwise.
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/poses/CPose3D.h>

#include <iostream>

#include "occupancy_grid/observation_disparity_scan.h"
#include "occupancy_grid/stereo_occupancy_grid_map.h"

int main() {
  mrpt::config::CConfigFileMemory config;
  config.write("map", "stereoOccupancyGrid_count", 1);
  mrpt::maps::TSetOfMetricMapInitializers initializers;
  initializers.loadFromConfigFile(config, "map");
  mrpt::maps::CMultiMetricMap maps(initializers);
  const auto grid = maps.mapByClass<stereonav::CStereoOccupancyGridMap>();
  if (!grid) {
    std::cerr << "consumer: stereoOccupancyGrid was not created from the map definition\n";
    return 1;
  }

  // One column straight ahead: f = 1 px, fB = 4 m px, d = 1.5 puts the obstacle between
  // 4 / 2 = 2 m and 4 / 1 = 4 m ahead (paper equation 1), so the cell 3 m ahead is OCC.
  stereonav::CObservationDisparityScan observation;
  observation.scan.column_disparity = {1.5f};
  observation.camera.focal_px = 1.0;
  observation.camera.cx = 0.0;
  observation.camera.baseline_m = 4.0;
  observation.camera.pose_on_robot =
      stereonav::CameraRig::opticalPoseOnRobot(0.0, 0.0, 0.5, 0.0, 0.0);
  maps.insertObservation(observation, mrpt::poses::CPose3D());

  int col = 0, row = 0;
  if (!grid->grid().cellAt(3.0, 0.0, col, row) ||
      grid->grid().occupancy(col, row) <= grid->grid().scale().unknown()) {
    std::cerr << "consumer: the cell 3 m ahead is not occupied after the insertion\n";
    return 1;
  }
  std::cout << "consumer: stereoOccupancyGrid from the installed package marked (3, 0) occupied\n";
  return 0;
}
