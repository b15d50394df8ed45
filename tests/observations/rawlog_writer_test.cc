#include "observations/rawlog_writer.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <tuple>

#include "observations/rawlog_reader.h"
#include "observations/rig_observations.h"
#include "sample_frames.h"

namespace stereonav {
namespace {

enum class Head { kBinocular, kTriclops };

std::vector<RigFrame> readAll(const std::string& path, RawlogReaderOptions options = {}) {
  RawlogReader reader(path, std::move(options));
  std::vector<RigFrame> frames;
  while (auto frame = reader.next()) frames.push_back(std::move(*frame));
  EXPECT_FALSE(reader.damage().has_value()) << reader.damage()->describe(path);
  EXPECT_EQ(reader.skipped().total(), 0u) << reader.skipped().summary();
  return frames;
}

class RawlogRoundTripTest
    : public ::testing::TestWithParam<std::tuple<RawlogLayout, ImageStorage, Head, int>> {};

TEST_P(RawlogRoundTripTest, ReadsBackTheFramesWritten) {
  const auto [layout, storage, head, compression_level] = GetParam();
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("run.rawlog");
  const auto frames = sampleFrames(head == Head::kTriclops ? triclopsRig() : binocularRig(), 5);
  {
    RawlogWriter writer(path, {layout, storage, compression_level, "TRICLOPS"});
    for (const auto& frame : frames) writer.write(frame);
    EXPECT_EQ(writer.framesWritten(), frames.size());
    EXPECT_FALSE(std::filesystem::exists(path)) << "visible before finish()";
    writer.finish();
  }
  ASSERT_TRUE(std::filesystem::exists(path));

  // External images really live outside: the rawlog is much smaller than the pixels it refers to
  // (random pixels do not compress).
  const size_t pixel_bytes = frames.size() * (1 + frames[0].secondaries.size()) * 64 * 48;
  const bool rawlog_holds_pixels = std::filesystem::file_size(path) > pixel_bytes;
  EXPECT_EQ(rawlog_holds_pixels, storage == ImageStorage::kEmbedded);
  EXPECT_EQ(std::filesystem::exists(scratch.file("run_Images")),
            storage == ImageStorage::kExternal);

  const auto read = readAll(path);
  ASSERT_EQ(read.size(), frames.size());
  for (size_t i = 0; i < frames.size(); ++i) {
    SCOPED_TRACE("frame " + std::to_string(i));
    expectSameFrame(frames[i], read[i]);
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllChoices, RawlogRoundTripTest,
    ::testing::Combine(::testing::Values(RawlogLayout::kObservations, RawlogLayout::kSensoryFrames),
                       ::testing::Values(ImageStorage::kEmbedded, ImageStorage::kExternal),
                       ::testing::Values(Head::kBinocular, Head::kTriclops),
                       ::testing::Values(0, 1)));

TEST(RawlogRoundTripTest, ColourImagesKeepTheirChannels) {
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("colour.rawlog");
  const auto frames = sampleFrames(triclopsRig(), 2, CV_8UC3);
  for (const auto storage : {ImageStorage::kEmbedded, ImageStorage::kExternal}) {
    {
      RawlogWriter writer(path, {RawlogLayout::kObservations, storage, 1, "TRICLOPS"});
      for (const auto& frame : frames) writer.write(frame);
    }  // the destructor finishes
    const auto read = readAll(path);
    ASSERT_EQ(read.size(), frames.size());
    for (size_t i = 0; i < frames.size(); ++i) expectSameFrame(frames[i], read[i]);
  }
}

TEST(RawlogRoundTripTest, FirstSecondaryTwoUnitsAwayComesBackAsTheSameGeometryWithBFromThePair) {
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("wide.rawlog");
  auto frames = sampleFrames(sampleRig({{2.0, 0.0}, {0.0, -1.0}}), 1);
  {
    RawlogWriter writer(path, {});
    writer.write(frames[0]);
  }
  const auto read = readAll(path);
  ASSERT_EQ(read.size(), 1u);
  // The pair is 0.2 m wide, so B = 0.2 m and the top camera, 0.1 m up, is half a unit away.
  EXPECT_NEAR(read[0].rig.baseline_m, 0.2, 1e-9);
  ASSERT_EQ(read[0].rig.secondaries.size(), 2u);
  EXPECT_NEAR(read[0].rig.secondaries[0].bx, 1.0, 1e-9);
  EXPECT_NEAR(read[0].rig.secondaries[1].by, -0.5, 1e-9);
}

TEST(RawlogRoundTripTest, OnlyTheChosenPairIsRead) {
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("two_heads.rawlog");
  const auto front = sampleFrames(triclopsRig(), 2);
  const auto back = sampleFrames(binocularRig(), 2);
  {
    // Two heads interleaved in one observations-only rawlog, as rawlog-grabber records them.
    mrpt::io::CFileGZOutputStream out(path);
    auto archive = mrpt::serialization::archiveFrom(out);
    for (size_t i = 0; i < 2; ++i) {
      const auto front_observations = toRigObservations(front[i], "FRONT");
      archive << *front_observations.extra_cameras[0] << *front_observations.pair;
      archive << *toRigObservations(back[i], "BACK").pair;
    }
  }
  for (const std::string label : {"", "FRONT", "BACK"}) {
    SCOPED_TRACE("label '" + label + "'");
    RawlogReaderOptions options;
    options.sensor_label = label;
    const auto read = readAll(path, options);
    const auto& expected = label == "BACK" ? back : front;
    ASSERT_EQ(read.size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
      // No odometry was recorded in this rawlog.
      RigFrame without_odometry = expected[i];
      without_odometry.odometry.reset();
      expectSameFrame(without_odometry, read[i]);
    }
  }
}

TEST(RawlogWriterTest, RejectedFrameWritesNothing) {
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("bad.rawlog");
  auto frames = sampleFrames(binocularRig(), 2);
  frames[0].secondaries.clear();
  {
    RawlogWriter writer(path, {});
    EXPECT_THROW(writer.write(frames[0]), std::invalid_argument);
    writer.write(frames[1]);
    EXPECT_EQ(writer.framesWritten(), 1u);
  }
  const auto read = readAll(path);
  ASSERT_EQ(read.size(), 1u);
  expectSameFrame(frames[1], read[0]);
}

TEST(RawlogWriterTest, WriteAfterFinishIsAnError) {
  test_support::ScratchDirectory scratch;
  RawlogWriter writer(scratch.file("done.rawlog"), {});
  writer.finish();
  EXPECT_THROW(writer.write(sampleFrames(binocularRig(), 1)[0]), std::logic_error);
}

TEST(RawlogWriterTest, OptionsLoadFromIni) {
  mrpt::config::CConfigFileMemory config(
      "[rawlog]\nlayout = sensory_frames\nimages = external\ncompression_level = 0\n"
      "sensor_label = BUMBLEBEE\n[typo]\nlayout = sensoryframes\n[level]\ncompression_level = "
      "10\n");
  IniSection section(config, "rawlog");
  const RawlogWriterOptions options = loadRawlogWriterOptions(section);
  section.rejectUnknownKeys();
  EXPECT_EQ(options.layout, RawlogLayout::kSensoryFrames);
  EXPECT_EQ(options.image_storage, ImageStorage::kExternal);
  EXPECT_EQ(options.compression_level, 0);
  EXPECT_EQ(options.sensor_label, "BUMBLEBEE");
  for (const std::string bad : {"typo", "level"}) {
    IniSection bad_section(config, bad);
    EXPECT_THROW(loadRawlogWriterOptions(bad_section), ConfigError) << bad;
  }
}

TEST(RawlogWriterTest, UnwritablePathIsReportedByName) {
  try {
    RawlogWriter writer("/nonexistent-folder/x.rawlog", {});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-folder/x.rawlog"), std::string::npos);
  }
}

}  // namespace
}  // namespace stereonav
