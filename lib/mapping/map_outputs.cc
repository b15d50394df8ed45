#include "mapping/map_outputs.h"

#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/stock_objects.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <stdexcept>

#include "common/atomic_file.h"
#include "occupancy_grid/grid_io.h"
#include "occupancy_grid/stereo_occupancy_grid_map.h"

namespace stereonav {
namespace {

DisparityTaggedGrid fromMrptOccupancyGrid(const mrpt::maps::COccupancyGridMap2D& mrpt_grid,
                                          const OccupancyScale& scale) {
  const int width = static_cast<int>(mrpt_grid.getSizeX());
  const int height = static_cast<int>(mrpt_grid.getSizeY());
  std::vector<uint8_t> occupancy(static_cast<size_t>(width) * height);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const double p_occupied = 1.0 - mrpt_grid.getCell(col, row);
      occupancy[static_cast<size_t>(row) * width + col] =
          static_cast<uint8_t>(std::lround(255.0 * p_occupied));
    }
  }
  const GridFrame frame{mrpt_grid.getXMin(), mrpt_grid.getYMin(), mrpt_grid.getResolution()};
  std::vector<float> tags(occupancy.size(), DisparityTaggedGrid::kNoTag);
  std::vector<uint8_t> close_free(occupancy.size(), 0);
  DisparityTaggedGrid grid(GridLimits{}, scale);
  grid.assign(frame, width, height, std::move(occupancy), std::move(tags), std::move(close_free));
  return grid;
}

void saveScene(const mrpt::maps::CMetricMap& map, const std::vector<mrpt::poses::CPose2D>& path,
               const std::string& scene_path) {
  mrpt::opengl::COpenGLScene scene;
  auto map_objects = mrpt::opengl::CSetOfObjects::Create();
  map.getVisualizationInto(*map_objects);
  scene.insert(map_objects);
  scene.insert(mrpt::opengl::stock_objects::CornerXYZSimple(0.5f, 2.0f));

  // Drawn a little above the grid so that the floor does not hide it.
  constexpr float kPathHeight = 0.02f;
  const auto point = [&](const mrpt::poses::CPose2D& pose) {
    return mrpt::math::TPoint3D(pose.x(), pose.y(), kPathHeight);
  };
  if (path.size() >= 2) {
    // Made and destroyed by MRPT's own code (CreateObject), not by the inline Create(): the
    // packaged headers declare a 32-byte alignment that MRPT's allocations do not give, which
    // UBSan reports in any destructor compiled here.
    auto line = std::dynamic_pointer_cast<mrpt::opengl::CSetOfLines>(
        mrpt::opengl::CSetOfLines::CreateObject());
    line->setColor(1.0f, 0.0f, 0.0f);
    line->setLineWidth(2.0f);
    line->appendLine(point(path[0]), point(path[1]));
    for (size_t i = 2; i < path.size(); ++i) line->appendLineStrip(point(path[i]));
    scene.insert(line);
  }
  if (!path.empty()) {
    auto robot = mrpt::opengl::stock_objects::RobotPioneer();
    robot->setPose(mrpt::poses::CPose3D(path.back()));
    scene.insert(robot);
  }
  // As COpenGLScene::saveToFile writes it, with every write checked.
  writeGzArchiveAtomically(scene_path, [&](mrpt::serialization::CArchive& archive) { archive << scene; });
}

}  // namespace

const DisparityTaggedGrid* ownGridOf(const mrpt::maps::CMetricMap& map) {
  const auto* stereo = dynamic_cast<const CStereoOccupancyGridMap*>(&map);
  return stereo != nullptr ? &stereo->grid() : nullptr;
}

DisparityTaggedGrid gridOfMap(const mrpt::maps::CMetricMap& map, const OccupancyScale& scale) {
  if (const DisparityTaggedGrid* own = ownGridOf(map)) return *own;
  if (const auto* mrpt_grid = dynamic_cast<const mrpt::maps::COccupancyGridMap2D*>(&map)) {
    return fromMrptOccupancyGrid(*mrpt_grid, scale);
  }
  throw std::invalid_argument("cannot save a map of type " +
                              std::string(map.GetRuntimeClass()->className));
}

void saveMapOutputs(const mrpt::maps::CMetricMap& map, const OccupancyScale& scale,
                    const std::vector<mrpt::poses::CPose2D>& robot_path, const std::string& prefix) {
  const DisparityTaggedGrid grid = gridOfMap(map, scale);
  OutputBatch outputs;
  outputs.write([&] { saveMrptGridmap(grid, prefix + ".gridmap"); });
  outputs.write([&] { saveGridImage(grid, prefix + ".png"); });
  outputs.write([&] { saveRosMapServer(grid, prefix + ".yaml"); });
  outputs.write([&] { saveScene(map, robot_path, prefix + ".3Dscene"); });
  outputs.throwIfFailed();
}

}  // namespace stereonav
