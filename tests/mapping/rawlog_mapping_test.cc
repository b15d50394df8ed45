#include "mapping/rawlog_mapping.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/serialization/CArchive.h>
#include <sys/wait.h>

#include <cstdlib>
#include <set>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "mapping/map_outputs.h"
#include "observations/rawlog_writer.h"
#include "synthetic_scene.h"

namespace stereonav {
namespace {

namespace fs = std::filesystem;
using testing::SyntheticScene;
using testing::Wall;

constexpr size_t kFrames = 8;
constexpr size_t kFramesBeforeDamage = 5;
constexpr double kWallX = 2.0;
constexpr double kStepM = 0.05;  // the robot drives towards the wall by this much per frame

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

mrpt::poses::CPose2D poseOfFrame(size_t i) { return {kStepM * i, 0.0, 0.0}; }

void writeRawlog(const std::string& path, const std::vector<RigFrame>& frames, size_t count) {
  RawlogWriterOptions options;
  options.compression_level = 0;  // so that byte offsets in the file are offsets in the stream
  RawlogWriter writer(path, options);
  for (size_t i = 0; i < count; ++i) writer.write(frames[i]);
  writer.finish();
}

// A run towards a textured wall, recorded in full and as its first kFramesBeforeDamage frames:
// the short file's size is where the full file's next frame starts.
class RawlogMappingTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    directory_ = new fs::path(fs::temp_directory_path() / ("mapping_test_" + std::to_string(getpid())));
    fs::create_directories(*directory_);
    const SyntheticScene scene({Wall{kWallX, -3.0, kWallX, 3.0}});
    std::vector<RigFrame> frames;
    for (size_t i = 0; i < kFrames; ++i) {
      frames.push_back(scene.renderFrame(testing::testRig(), poseOfFrame(i),
                                         mrpt::Clock::fromDouble(1000.0 + 0.2 * i)));
    }
    writeRawlog(path("full.rawlog"), frames, kFrames);
    writeRawlog(path("prefix.rawlog"), frames, kFramesBeforeDamage);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*directory_);
    delete directory_;
  }
  static std::string path(const std::string& name) { return (*directory_ / name).string(); }

  static MappingJob jobFor(const std::string& rawlog, const std::string& prefix) {
    MappingJob job;
    job.rawlog_path = rawlog;
    job.output_prefix = path(prefix);
    return job;
  }

  static void expectOutputs(const std::string& prefix) {
    for (const char* extension : {".gridmap", ".png", ".yaml", ".pgm", ".3Dscene", ".stats.json"}) {
      EXPECT_TRUE(fs::exists(path(prefix) + extension)) << prefix << extension;
    }
  }

  // The saved .gridmap as MRPT's own class reads it.
  static mrpt::maps::COccupancyGridMap2D loadGridmap(const std::string& prefix) {
    mrpt::io::CFileGZInputStream file(path(prefix) + ".gridmap");
    mrpt::maps::COccupancyGridMap2D grid;
    mrpt::serialization::archiveFrom(file) >> grid;
    return grid;
  }

  static std::string damagedCopy(const std::string& name, const std::function<void(std::string&)>& damage) {
    std::string bytes = readBytes(path("full.rawlog"));
    damage(bytes);
    writeBytes(path(name), bytes);
    return path(name);
  }

  static size_t prefixSize() { return fs::file_size(path("prefix.rawlog")); }

  static fs::path* directory_;
};
fs::path* RawlogMappingTest::directory_ = nullptr;

TEST_F(RawlogMappingTest, CompleteRawlogIsMappedAndEveryOutputWritten) {
  const MappingReport report = mapRawlog(MappingOptions{}, jobFor(path("full.rawlog"), "full"));
  EXPECT_TRUE(report.complete());
  EXPECT_EQ(report.frames_mapped, kFrames);
  EXPECT_EQ(report.skipped.total(), 0u);
  EXPECT_GT(report.kept_pixel_fraction, 0.1);
  expectOutputs("full");
  const std::string stats = readBytes(path("full.stats.json"));
  EXPECT_NE(stats.find("\"frames\": 8,"), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"complete\": true"), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"damage\": null"), std::string::npos) << stats;

  const mrpt::maps::COccupancyGridMap2D grid = loadGridmap("full");
  float nearest_wall_p_free = 1.0f;
  for (double x = kWallX - 0.1; x <= kWallX + 0.1; x += 0.01) {
    nearest_wall_p_free = std::min(nearest_wall_p_free, grid.getPos(static_cast<float>(x), 0.0f));
  }
  EXPECT_LT(nearest_wall_p_free, 0.4f);  // G > 150: occupied
  EXPECT_GT(grid.getPos(1.2f, 0.0f), 0.8f);  // G < 50: free
  EXPECT_NEAR(grid.getPos(3.0f, 0.0f), 0.5f, 0.01f);  // behind the wall: unknown

  mrpt::opengl::COpenGLScene scene;
  ASSERT_TRUE(scene.loadFromFile(path("full.3Dscene")));
  EXPECT_GE(scene.getViewport()->size(), 3u);  // map, axes, path, robot
}

TEST_F(RawlogMappingTest, TruncatedRawlogIsMappedUpToTheCut) {
  const std::string rawlog =
      damagedCopy("truncated.rawlog", [](std::string& bytes) { bytes.resize(prefixSize() + 100); });
  const MappingReport report = mapRawlog(MappingOptions{}, jobFor(rawlog, "truncated"));
  EXPECT_FALSE(report.complete());
  ASSERT_TRUE(report.damage.has_value());
  EXPECT_EQ(report.frames_mapped, kFramesBeforeDamage);
  EXPECT_NE(report.summary().find("truncated.rawlog: damaged"), std::string::npos) << report.summary();
  expectOutputs("truncated");
  const std::string stats = readBytes(path("truncated.stats.json"));
  EXPECT_NE(stats.find("\"frames\": 5,"), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"complete\": false"), std::string::npos) << stats;
  loadGridmap("truncated");
}

TEST_F(RawlogMappingTest, CorruptedObjectInTheMiddleStopsMappingThere) {
  // Overwrite the header of the first object after the fifth frame (the sixth frame's odometry).
  const std::string rawlog = damagedCopy("corrupted.rawlog", [](std::string& bytes) {
    for (size_t i = 0; i < 16; ++i) bytes[prefixSize() + i] = '\xff';
  });
  const MappingReport report = mapRawlog(MappingOptions{}, jobFor(rawlog, "corrupted"));
  ASSERT_TRUE(report.damage.has_value());
  EXPECT_EQ(report.damage->byte_offset, prefixSize());
  EXPECT_EQ(report.frames_mapped, kFramesBeforeDamage);
  expectOutputs("corrupted");
  const std::string stats = readBytes(path("corrupted.stats.json"));
  EXPECT_NE(stats.find("\"frames\": 5,"), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"byte_offset\": " + std::to_string(prefixSize())), std::string::npos) << stats;
  // The frames before the damage still map the wall.
  const mrpt::maps::COccupancyGridMap2D grid = loadGridmap("corrupted");
  EXPECT_GT(grid.getPos(1.2f, 0.0f), 0.8f);
}

TEST_F(RawlogMappingTest, StopRequestEndsAfterTheCurrentFrameAndSavesTheMap) {
  MappingCallbacks callbacks;
  size_t seen = 0;
  callbacks.on_frame = [&](size_t frames, const mrpt::maps::CMetricMap&) { seen = frames; };
  callbacks.stop_requested = [&] { return seen == 3; };
  const MappingReport report = mapRawlog(MappingOptions{}, jobFor(path("full.rawlog"), "stopped"), callbacks);
  EXPECT_TRUE(report.interrupted);
  EXPECT_FALSE(report.complete());
  EXPECT_EQ(report.frames_mapped, 3u);
  expectOutputs("stopped");
  EXPECT_NE(readBytes(path("stopped.stats.json")).find("\"interrupted\": true"), std::string::npos);
}

TEST_F(RawlogMappingTest, PanelsOfEveryNthFrameAndTheGrowingMapInTheCallback) {
  MappingJob job = jobFor(path("full.rawlog"), "every");
  job.debug_panel_directory = path("every_panels");
  job.debug_panel_every = 3;
  fs::create_directories(job.debug_panel_directory);
  MappingCallbacks callbacks;
  std::vector<size_t> known_cells;
  callbacks.on_frame = [&](size_t, const mrpt::maps::CMetricMap& map) {
    const DisparityTaggedGrid grid = gridOfMap(map, OccupancyScale{});
    size_t known = 0;
    for (int row = 0; row < grid.height(); ++row) {
      for (int col = 0; col < grid.width(); ++col) known += grid.occupancy(col, row) != OccupancyScale{}.unknown();
    }
    known_cells.push_back(known);
  };
  mapRawlog(MappingOptions{}, job, callbacks);
  std::set<std::string> panels;
  for (const auto& entry : fs::directory_iterator(job.debug_panel_directory)) panels.insert(entry.path().filename());
  // 8 frames, every third from the first: frames 0, 3 and 6.
  EXPECT_EQ(panels, (std::set<std::string>{"panel_000000.png", "panel_000003.png", "panel_000006.png"}));
  ASSERT_EQ(known_cells.size(), kFrames);
  EXPECT_GT(known_cells.front(), 0u);
  EXPECT_LT(known_cells.front(), known_cells.back()) << "the map is passed as it grows";
}

TEST_F(RawlogMappingTest, VirtualScanRawlogHoldsOdometryAndOneScanPerFrame) {
  MappingJob job = jobFor(path("full.rawlog"), "scans");
  job.virtual_scan_rawlog = path("scans.rawlog");
  mapRawlog(MappingOptions{}, job);
  mrpt::io::CFileGZInputStream file(job.virtual_scan_rawlog);
  auto archive = mrpt::serialization::archiveFrom(file);
  for (size_t i = 0; i < kFrames; ++i) {
    const auto odometry = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(archive.ReadObject());
    ASSERT_TRUE(odometry) << i;
    EXPECT_NEAR(odometry->odometry.x(), poseOfFrame(i).x(), 1e-9);
    const auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(archive.ReadObject());
    ASSERT_TRUE(scan) << i;
    EXPECT_EQ(scan->timestamp, odometry->timestamp);
    // Straight ahead the scan measures the wall from the camera (on the robot's centre).
    const size_t middle = scan->getScanSize() / 2;
    ASSERT_TRUE(scan->getScanRangeValidity(middle));
    EXPECT_NEAR(scan->getScanRange(middle), kWallX - poseOfFrame(i).x(), 0.15) << i;
  }
}

TEST_F(RawlogMappingTest, GroundTruthPosesReplaceOdometry) {
  // The same frames claimed to be taken 1 m further left: the wall moves with them.
  std::ofstream(path("poses.txt")) << "# t x y phi\n";
  for (size_t i = 0; i < kFrames; ++i) {
    std::ofstream(path("poses.txt"), std::ios::app) << 0.2 * i << " " << poseOfFrame(i).x() << " 1.0 0.0\n";
  }
  MappingJob job = jobFor(path("full.rawlog"), "shifted");
  job.pose_source = MapPoseSource::kGroundTruth;
  job.ground_truth_poses = loadPoseList(path("poses.txt"));
  ASSERT_EQ(job.ground_truth_poses.size(), kFrames);
  mapRawlog(MappingOptions{}, job);
  const mrpt::maps::COccupancyGridMap2D grid = loadGridmap("shifted");
  EXPECT_GT(grid.getPos(1.2f, 1.0f), 0.8f);
  EXPECT_NEAR(grid.getPos(1.2f, -0.5f), 0.5f, 0.01f);  // outside the field of view now

  job.ground_truth_poses.resize(kFrames - 1);
  EXPECT_THROW(mapRawlog(MappingOptions{}, job), std::invalid_argument);
  std::ofstream(path("bad_poses.txt")) << "0 1 2\n";
  EXPECT_THROW(loadPoseList(path("bad_poses.txt")), std::runtime_error);
}

// `stereonav map` itself: exit status and outputs.
int runMapCommand(const std::string& arguments) {
  const std::string command = std::string(STEREONAV_BINARY_DIR) + "/bin/stereonav map " + arguments;
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST_F(RawlogMappingTest, CommandExitsZeroWhenCompleteAndThreeWhenPartialWithOutputsEitherWay) {
  std::ofstream(path("map.ini")) << "[grid]\nmodel = linear\nresolution = 0.05\n";
  EXPECT_EQ(runMapCommand("--config " + path("map.ini") + " --rawlog " + path("full.rawlog") +
                          " --out " + path("app_full") + " 2>/dev/null"),
            0);
  expectOutputs("app_full");
  const std::string truncated =
      damagedCopy("app_truncated.rawlog", [](std::string& bytes) { bytes.resize(prefixSize() + 100); });
  EXPECT_EQ(runMapCommand("--config " + path("map.ini") + " --rawlog " + truncated + " --out " +
                          path("app_truncated") + " 2>" + path("app_truncated.err")),
            3);
  expectOutputs("app_truncated");
  const std::string messages = readBytes(path("app_truncated.err"));
  EXPECT_NE(messages.find("stopped at damage: " + truncated + ": damaged"), std::string::npos) << messages;
}

TEST_F(RawlogMappingTest, CommandNamesAnUnknownKeyAndTheFile) {
  std::ofstream(path("typo.ini")) << "[grid]\nresolutoin = 0.05\n";
  EXPECT_EQ(runMapCommand("--config " + path("typo.ini") + " --rawlog " + path("full.rawlog") +
                          " --out " + path("typo") + " 2>" + path("typo.err")),
            1);
  const std::string message = readBytes(path("typo.err"));
  EXPECT_NE(message.find("typo.ini"), std::string::npos) << message;
  EXPECT_NE(message.find("resolutoin"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(path("typo.gridmap")));
}

TEST_F(RawlogMappingTest, CommandFailsWhenEveryFrameIsSkippedAndSaysWhy) {
  std::ofstream(path("small_rig.ini")) << "[rig]\nwidth = 160\nheight = 120\nfocal_px = 80\ncx = 79.5\ncy = 59.5\n";
  EXPECT_EQ(runMapCommand("--config " + path("small_rig.ini") + " --rawlog " + path("full.rawlog") +
                          " --out " + path("skipped") + " 2>" + path("skipped.err")),
            1);
  const std::string message = readBytes(path("skipped.err"));
  EXPECT_NE(message.find("skipped 8 of the rawlog's stereo frames: 8 wrong image format"), std::string::npos)
      << message;
  EXPECT_NE(message.find("no frame of " + path("full.rawlog") + " could be mapped"), std::string::npos) << message;
  expectOutputs("skipped");
  EXPECT_NE(readBytes(path("skipped.stats.json")).find("\"wrong_image_format\": 8"), std::string::npos);
}

}  // namespace
}  // namespace stereonav
