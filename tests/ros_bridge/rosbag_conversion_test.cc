#include "ros_bridge/rosbag_conversion.h"

#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "mapping/rawlog_mapping.h"
#include "support/scratch_directory.h"

namespace stereonav {
namespace {

const std::string kSource = STEREONAV_SOURCE_DIR;

std::string readFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

class RosbagConversionTest : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return scratch_.file(name); }

  test_support::ScratchDirectory scratch_;
};

// The office run through a bag and back maps to the very same grid: the bag carries every pixel,
// the calibration and the odometry of every frame.
TEST_F(RosbagConversionTest, OfficeRunThroughABagAndBackMapsTheSameGrid) {
  const MappingOptions options = loadMappingOptionsFile(kSource + "/ini/office_run.ini");
  const std::string rawlog = kSource + "/rawlogs/office_run.rawlog";
  EXPECT_EQ(writeRosbagFromRawlog(rawlog, rawlogReaderOptions(options), path("office.bag")), 76u);

  rosbag::Bag bag(path("office.bag"), rosbag::bagmode::Read);
  size_t images = 0, odometry = 0;
  for (const rosbag::MessageInstance& message : rosbag::View(bag)) {
    images += message.getTopic() == "/stereo/top/image_rect";
    odometry += message.getTopic() == "/odom";
  }
  EXPECT_EQ(images, 76u);
  EXPECT_EQ(odometry, 76u);

  RawlogWriterOptions writer_options;
  {
    RawlogWriter writer(path("back.rawlog"), writer_options);
    const RosbagConversionReport report =
        convertRosbagToRawlog(path("office.bag"), rosHeadOptions(options), writer);
    writer.finish();
    EXPECT_EQ(report.frames, 76u);
    EXPECT_EQ(report.odometry_messages, 76u);
    EXPECT_EQ(report.skipped.total(), 0u);
    EXPECT_EQ(report.image_topics, "/stereo/left/image_rect /stereo/right/image_rect /stereo/top/image_rect");
  }
  for (const auto& [input, prefix] : {std::pair{rawlog, path("direct")}, std::pair{path("back.rawlog"), path("back")}}) {
    MappingJob job;
    job.rawlog_path = input;
    job.output_prefix = prefix;
    EXPECT_EQ(mapRawlog(options, job).frames_mapped, 76u);
  }
  const std::string direct = readFile(path("direct.pgm"));
  EXPECT_GT(direct.size(), 1000u);
  EXPECT_EQ(direct, readFile(path("back.pgm")));
  EXPECT_EQ(readFile(path("direct.traj.tum")), readFile(path("back.traj.tum")));
}

TEST_F(RosbagConversionTest, ABagWithoutTheHeadsTopicsIsNamed) {
  {
    rosbag::Bag bag(path("empty.bag"), rosbag::bagmode::Write);
    bag.write("/chatter", ros::Time(1, 0), std_msgs::Header());
  }
  RawlogWriter writer(path("out.rawlog"), RawlogWriterOptions{});
  try {
    convertRosbagToRawlog(path("empty.bag"), RosHeadOptions{}, writer);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path("empty.bag") + ": no left/image_rect"), std::string::npos)
        << e.what();
  }
  try {
    convertRosbagToRawlog(path("missing.bag"), RosHeadOptions{}, writer);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path("missing.bag")), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace stereonav
