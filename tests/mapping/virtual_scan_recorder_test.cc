#include "mapping/virtual_scan_recorder.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "mapping/rawlog_mapping.h"
#include "support/scratch_directory.h"

namespace stereonav {
namespace {

namespace fs = std::filesystem;

const std::string kSourceDir = std::string(STEREONAV_TEST_DATA_DIR) + "/../..";
constexpr const char* kIcpSlam = "/usr/bin/icp-slam";

TEST(VirtualScanRecorderTest, SavesOdometryAndScansInOrder) {
  VirtualScanRecorder recorder;
  for (int i = 0; i < 3; ++i) {
    mrpt::obs::CObservation2DRangeScan scan;
    scan.resizeScan(4);
    for (size_t ray = 0; ray < 4; ++ray) scan.setScanRange(ray, 1.0f + i);
    scan.timestamp = mrpt::Clock::fromDouble(10.0 + i);
    recorder.add(scan, mrpt::poses::CPose2D(i, 0.0, 0.0));
  }
  EXPECT_EQ(recorder.size(), 3u);
  const test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("virtual_scans.rawlog");
  recorder.save(path);
  mrpt::io::CFileGZInputStream file(path);
  auto archive = mrpt::serialization::archiveFrom(file);
  for (int i = 0; i < 3; ++i) {
    const auto odometry = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(archive.ReadObject());
    ASSERT_TRUE(odometry);
    EXPECT_EQ(odometry->sensorLabel, "ODOMETRY");
    EXPECT_EQ(odometry->odometry.x(), i);
    const auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(archive.ReadObject());
    ASSERT_TRUE(scan);
    EXPECT_EQ(scan->getScanRange(2), 1.0f + i);
    EXPECT_EQ(scan->timestamp, odometry->timestamp);
  }
}

// Stock icp-slam, with the shipped ini, on the virtual scans of the sample run: it must accept the
// scans, build a map of many of them, and end near the (exact) odometry of the closed loop.
TEST(VirtualScanRecorderTest, StockIcpSlamMapsTheSampleRunsVirtualScans) {
  if (!fs::exists(kIcpSlam)) GTEST_SKIP() << kIcpSlam << " is not installed";
  const fs::path directory = fs::temp_directory_path() / ("icp_slam_test_" + std::to_string(getpid()));
  fs::create_directories(directory);
  MappingJob job;
  job.rawlog_path = kSourceDir + "/rawlogs/sample_trinocular.rawlog";
  job.output_prefix = (directory / "sample").string();
  job.virtual_scan_rawlog = (directory / "scans.rawlog").string();
  const MappingReport report =
      mapRawlog(loadMappingOptionsFile(kSourceDir + "/ini/sample_trinocular.ini"), job);
  ASSERT_TRUE(report.complete());

  const std::string command = "cd " + directory.string() + " && " + kIcpSlam + " " + kSourceDir +
                              "/ini/icp_slam_virtual_scans.ini scans.rawlog </dev/null >icp.log 2>&1";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "see " << directory / "icp.log";
  const fs::path log = directory / "LOG_ICP-SLAM_STEREO";
  EXPECT_TRUE(fs::exists(log / "_finalmaps_.txt_mrpt__maps__COccupancyGridMap2D_00.png"));

  mrpt::maps::CSimpleMap keyframes;
  {
    mrpt::io::CFileGZInputStream file((log / "_finalmap_.simplemap").string());
    mrpt::serialization::archiveFrom(file) >> keyframes;
  }
  // Scans are inserted every 0.5 m or 20 degrees of a 13.8 m loop with four quarter turns, and
  // only when ICP accepted the scan: most of the ~27 opportunities must have been taken.
  EXPECT_GE(keyframes.size(), 15u);

  // The run closes its loop at the start pose; the odometry is exact, so ICP must not drift far.
  std::ifstream path_file(log / "log_estimated_path.txt");
  double step, x = 1e9, y = 1e9, phi = 0;
  while (path_file >> step >> x >> y >> phi) {}
  EXPECT_LT(std::hypot(x, y), 0.5) << "icp-slam ended at " << x << ", " << y;
  fs::remove_all(directory);
}

}  // namespace
}  // namespace stereonav
