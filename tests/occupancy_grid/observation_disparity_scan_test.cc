#include "occupancy_grid/observation_disparity_scan.h"

#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>

#include "test_scans.h"

namespace stereonav {
namespace {

TEST(CObservationDisparityScanTest, IsRegisteredWithMrptByName) {
  const mrpt::rtti::TRuntimeClassId* found =
      mrpt::rtti::findRegisteredClass("stereonav::CObservationDisparityScan");
  ASSERT_NE(found, nullptr);
  EXPECT_TRUE(found->derivedFrom(CLASS_ID(mrpt::obs::CObservation)));
  EXPECT_NE(dynamic_cast<CObservationDisparityScan*>(found->createObject().get()), nullptr);
}

TEST(CObservationDisparityScanTest, SerialisesAndComesBackAsAnObservation) {
  CObservationDisparityScan original;
  original.timestamp = mrpt::Clock::fromDouble(1234.5);
  original.sensorLabel = "TRICLOPS";
  original.scan = testing::scanOf({3.0f, kInvalidDisparity, 0.0f});
  original.scan.column_row = {17, -1, 40};
  original.scan.column_clear_end = {6.5f, kInvalidDisparity, kInvalidDisparity};
  original.scan.column_clear_end_row = {90, -1, -1};
  original.scan.range_top = 47.0f;
  original.camera.focal_px = 190.0;
  original.camera.cx = 80.25;
  original.camera.cy = 61.75;
  original.camera.baseline_m = 0.12;
  original.setSensorPose(CameraRig::opticalPoseOnRobot(0.1, -0.05, 0.6, 0.2, 0.1));

  mrpt::io::CMemoryStream buffer;
  mrpt::serialization::archiveFrom(buffer).WriteObject(&original);
  buffer.Seek(0);
  const mrpt::serialization::CSerializable::Ptr object =
      mrpt::serialization::archiveFrom(buffer).ReadObject();
  const auto copy = std::dynamic_pointer_cast<CObservationDisparityScan>(object);
  ASSERT_TRUE(copy);
  EXPECT_EQ(copy->timestamp, original.timestamp);
  EXPECT_EQ(copy->sensorLabel, "TRICLOPS");
  EXPECT_EQ(copy->scan.column_disparity, original.scan.column_disparity);
  EXPECT_EQ(copy->scan.column_row, original.scan.column_row);
  EXPECT_EQ(copy->scan.column_clear_end, original.scan.column_clear_end);
  EXPECT_EQ(copy->scan.column_clear_end_row, original.scan.column_clear_end_row);
  EXPECT_EQ(copy->scan.range_top, 47.0f);
  EXPECT_EQ(copy->camera.focal_px, 190.0);
  EXPECT_EQ(copy->camera.cx, 80.25);
  EXPECT_EQ(copy->camera.cy, 61.75);
  EXPECT_EQ(copy->camera.baseline_m, 0.12);
  mrpt::poses::CPose3D pose;
  copy->getSensorPose(pose);
  EXPECT_NEAR((pose - original.camera.pose_on_robot).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace stereonav
