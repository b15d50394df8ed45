#include "closed_loop/reactive_nav_log.h"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

namespace stereonav {
namespace {

std::string outputPath(const std::string& name) {
  const std::string directory = std::string(STEREONAV_BINARY_DIR) + "/test_outputs/closed_loop/navlog";
  std::filesystem::create_directories(directory);
  return directory + "/" + name;
}

mrpt::nav::CLogFileRecord record(double x, double speed) {
  mrpt::nav::CLogFileRecord record;
  record.robotPoseLocalization = {x, 2.0, 0.5};
  record.WS_Obstacles.insertPoint(1.0f, 0.25f, 0.0f);
  auto command = std::make_shared<mrpt::kinematics::CVehicleVelCmd_DiffDriven>();
  command->lin_vel = speed;
  record.cmd_vel = command;
  record.values["cost_to_go"] = 3.0 * x;
  record.additional_debug_msgs["phase"] = "driving";
  return record;
}

// What navlog-viewer does: read CSerializable objects from the gzip stream until its end.
std::vector<mrpt::nav::CLogFileRecord::Ptr> readBack(const std::string& path) {
  mrpt::io::CFileGZInputStream file(path);
  auto archive = mrpt::serialization::archiveFrom(file);
  std::vector<mrpt::nav::CLogFileRecord::Ptr> records;
  while (true) {
    try {
      records.push_back(std::dynamic_pointer_cast<mrpt::nav::CLogFileRecord>(archive.ReadObject()));
    } catch (const mrpt::serialization::CExceptionEOF&) {
      break;
    }
  }
  return records;
}

TEST(ReactiveNavLog, WritesRecordsNavlogViewerReadsBackInOrder) {
  ReactiveNavLog log;
  log.append(record(1.0, 0.5));
  log.append(record(1.5, 0.75));
  EXPECT_EQ(log.size(), 2u);
  const std::string path = outputPath("two.reactivenavlog");
  log.save(path);

  const auto records = readBack(path);
  ASSERT_EQ(records.size(), 2u);
  ASSERT_TRUE(records[0] && records[1]);
  EXPECT_DOUBLE_EQ(records[0]->robotPoseLocalization.x, 1.0);
  EXPECT_DOUBLE_EQ(records[1]->robotPoseLocalization.x, 1.5);
  EXPECT_DOUBLE_EQ(records[1]->robotPoseLocalization.phi, 0.5);
  ASSERT_EQ(records[1]->WS_Obstacles.size(), 1u);
  EXPECT_FLOAT_EQ(records[1]->WS_Obstacles.getPointsBufferRef_y()[0], 0.25f);
  const auto command = std::dynamic_pointer_cast<mrpt::kinematics::CVehicleVelCmd_DiffDriven>(records[1]->cmd_vel);
  ASSERT_TRUE(command);
  EXPECT_DOUBLE_EQ(command->lin_vel, 0.75);
  EXPECT_DOUBLE_EQ(records[1]->values.at("cost_to_go"), 4.5);
  EXPECT_EQ(records[0]->additional_debug_msgs.at("phase"), "driving");
}

TEST(ReactiveNavLog, AnUnwritablePathIsAnErrorNamingIt) {
  ReactiveNavLog log;
  log.append(record(1.0, 0.5));
  const std::string path = outputPath("no_such_folder/run.reactivenavlog");
  try {
    log.save(path);
    FAIL() << "saved into a missing folder";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace stereonav
