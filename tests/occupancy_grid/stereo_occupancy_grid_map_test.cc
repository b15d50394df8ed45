#include "occupancy_grid/stereo_occupancy_grid_map.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/serialization/CArchive.h>

#include "test_scans.h"

namespace stereonav {
namespace {

using testing::occupancyAt;

CObservationDisparityScan::Ptr unitObservation(float disparity) {
  auto observation = CObservationDisparityScan::Create();
  observation->scan = testing::scanOf({disparity});
  observation->camera = testing::unitCamera();
  return observation;
}

StereoGridMapOptions unitOptions() {
  StereoGridMapOptions options;
  options.limits = testing::unitLimits();
  return options;
}

mrpt::poses::CPose3D pose3D(const mrpt::poses::CPose2D& pose) { return mrpt::poses::CPose3D(pose); }

TEST(CStereoOccupancyGridMapTest, IsRegisteredWithMrptByName) {
  const mrpt::rtti::TRuntimeClassId* found =
      mrpt::rtti::findRegisteredClass("stereonav::CStereoOccupancyGridMap");
  ASSERT_NE(found, nullptr);
  EXPECT_TRUE(found->derivedFrom(CLASS_ID(mrpt::maps::CMetricMap)));
}

TEST(CStereoOccupancyGridMapTest, InsertsDisparityScansAndRefusesOtherObservations) {
  CStereoOccupancyGridMap map(unitOptions());
  EXPECT_TRUE(map.isEmpty());
  mrpt::obs::CObservationStereoImages stereo;
  EXPECT_FALSE(map.insertObservation(stereo, pose3D(testing::robotAt(0, 0))));
  EXPECT_TRUE(map.isEmpty());
  EXPECT_TRUE(map.insertObservation(*unitObservation(1.5f), pose3D(testing::robotAt(0, 0))));
  EXPECT_FALSE(map.isEmpty());
  EXPECT_EQ(occupancyAt(map.grid(), 3, 1), 148);
  EXPECT_EQ(occupancyAt(map.grid(), 1, 0), 108);
  map.clear();
  EXPECT_TRUE(map.isEmpty());
  EXPECT_EQ(occupancyAt(map.grid(), 3, 1), 128);
}

// Stands in for the full pipeline (matching + spike removal + column projection), which will
// turn stereo images into a disparity scan through this extension point.
class FixedStereoSource : public DisparityScanSource {
 public:
  CObservationDisparityScan::Ptr toDisparityScan(
      const mrpt::obs::CObservation& observation) const override {
    if (!IS_CLASS(observation, mrpt::obs::CObservationStereoImages)) return nullptr;
    return unitObservation(1.5f);
  }
};

TEST(CStereoOccupancyGridMapTest, DisparityScanSourcesLetOtherObservationsIn) {
  CStereoOccupancyGridMap map(unitOptions());
  map.addDisparityScanSource(std::make_shared<FixedStereoSource>());
  mrpt::obs::CObservationStereoImages stereo;
  EXPECT_TRUE(map.insertObservation(stereo, pose3D(testing::robotAt(0, 0))));
  EXPECT_EQ(occupancyAt(map.grid(), 2, -1), 148);
  mrpt::obs::CObservation2DRangeScan laser;
  EXPECT_FALSE(map.insertObservation(laser, pose3D(testing::robotAt(0, 0))));
}

TEST(CStereoOccupancyGridMapTest, SerialisesWithItsOptionsAndAllLayers) {
  StereoGridMapOptions options = unitOptions();
  options.update.update_step = 30;
  options.update.free_preservation_range_m = 1.5;
  options.sensor_model.max_range_m = 7.5;
  options.sensor_model.disparity_uncertainty_px = 0.3;
  options.sensor_model.keep_obstacle_borders = true;
  CStereoOccupancyGridMap map(options);
  map.insertObservation(*unitObservation(1.5f), pose3D(testing::robotAt(0, 0)));

  mrpt::io::CMemoryStream buffer;
  mrpt::serialization::archiveFrom(buffer).WriteObject(&map);
  buffer.Seek(0);
  const auto copy = std::dynamic_pointer_cast<CStereoOccupancyGridMap>(
      mrpt::serialization::archiveFrom(buffer).ReadObject());
  ASSERT_TRUE(copy);
  EXPECT_FALSE(copy->isEmpty());
  EXPECT_EQ(copy->options().update.update_step, 30);
  EXPECT_EQ(copy->options().sensor_model.max_range_m, 7.5);
  EXPECT_EQ(copy->options().sensor_model.disparity_uncertainty_px, 0.3);
  EXPECT_TRUE(copy->options().sensor_model.keep_obstacle_borders);
  EXPECT_EQ(copy->options().update.free_preservation_range_m, 1.5);
  EXPECT_EQ(copy->grid().occupancyLayer(), map.grid().occupancyLayer());
  EXPECT_EQ(copy->grid().tagLayer(), map.grid().tagLayer());
  EXPECT_EQ(copy->grid().closeFreeLayer(), map.grid().closeFreeLayer());
  // CLEAR within 1.5 m of the camera: X = 0, 1 on the reading's axis.
  int col = 0, row = 0;
  ASSERT_TRUE(copy->grid().cellAt(1.5, 0.5, col, row));
  EXPECT_TRUE(copy->grid().closeFree(col, row));
  EXPECT_EQ(copy->grid().minX(), map.grid().minX());
  // The copy keeps mapping with the same rule: K = 30 on top of 128 + 30.
  copy->insertObservation(*unitObservation(1.5f), pose3D(testing::robotAt(0, 0)));
  EXPECT_EQ(occupancyAt(copy->grid(), 3, 0), 188);
}

// A CMultiMetricMap defined in an ini file, with MRPT's own grid next to ours.
const char* const kMultiMapIni = R"ini(
[map]
occupancyGrid_count = 1
stereoOccupancyGrid_count = 1

[map_occupancyGrid_00_creationOpts]
min_x = -5
max_x = 5
min_y = -5
max_y = 5
resolution = 0.1

[map_stereoOccupancyGrid_00_creationOpts]
min_x = -3
max_x = 3
min_y = -2
max_y = 2
resolution = 0.5
enableSaveAs3DObject = true

[map_stereoOccupancyGrid_00_insertOpts]
update_step = 25
occupied_above = 170
accuracy_preservation = false
max_range_m = 12
)ini";

TEST(CStereoOccupancyGridMapTest, IsDeclaredInACMultiMetricMapIniNextToMrptMaps) {
  mrpt::config::CConfigFileMemory ini(kMultiMapIni);
  mrpt::maps::TSetOfMetricMapInitializers initializers;
  initializers.loadFromConfigFile(ini, "map");
  mrpt::maps::CMultiMetricMap maps(initializers);
  ASSERT_EQ(maps.maps.size(), 2u);
  const auto ours = maps.mapByClass<CStereoOccupancyGridMap>();
  ASSERT_TRUE(ours);
  ASSERT_TRUE(maps.mapByClass<mrpt::maps::COccupancyGridMap2D>());
  EXPECT_EQ(ours->grid().resolution(), 0.5);
  EXPECT_EQ(ours->grid().width(), 12);
  EXPECT_EQ(ours->grid().height(), 8);
  EXPECT_EQ(ours->options().update.update_step, 25);
  EXPECT_EQ(ours->options().update.scale.occupied_above, 170);
  EXPECT_FALSE(ours->options().update.accuracy_preservation);
  EXPECT_EQ(ours->options().sensor_model.max_range_m, 12.0);

  // The multi-map hands the disparity scan to every map; only ours takes it.
  EXPECT_TRUE(maps.insertObservation(*unitObservation(1.5f), mrpt::poses::CPose3D()));
  int col = 0, row = 0;
  ASSERT_TRUE(ours->grid().cellAt(2.9, 0.1, col, row));  // depth in [2, 4): OCC
  EXPECT_EQ(ours->grid().occupancy(col, row), 153);
  EXPECT_TRUE(maps.mapByClass<mrpt::maps::COccupancyGridMap2D>()->isEmpty());
}

TEST(CStereoOccupancyGridMapTest, UnknownInsertionKeyInTheMapDefinitionIsRejected) {
  mrpt::config::CConfigFileMemory ini(std::string(kMultiMapIni) + "update_stpe = 3\n");
  mrpt::maps::TSetOfMetricMapInitializers initializers;
  try {
    initializers.loadFromConfigFile(ini, "map");
    FAIL() << "typo accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("update_stpe"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace stereonav
