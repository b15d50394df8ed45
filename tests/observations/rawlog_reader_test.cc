#include "observations/rawlog_reader.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "common/atomic_file.h"
#include "observations/rawlog_writer.h"
#include "sample_frames.h"

namespace stereonav {
namespace {

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Where each top-level observation starts in an uncompressed observations-only rawlog, found from
// MRPT's object header (one byte 0x80 | length, then the class name) rather than from our reader.
struct ObjectStart {
  size_t offset;
  std::string class_name;
};
std::vector<ObjectStart> topLevelObjects(const std::string& bytes) {
  std::vector<ObjectStart> objects;
  for (const std::string name : {"mrpt::obs::CObservationOdometry", "mrpt::obs::CObservationImage",
                                 "mrpt::obs::CObservationStereoImages"}) {
    for (size_t at = bytes.find(name); at != std::string::npos; at = bytes.find(name, at + 1)) {
      if (at > 0 && static_cast<unsigned char>(bytes[at - 1]) == (0x80 | name.size())) {
        objects.push_back({at - 1, name});
      }
    }
  }
  std::sort(objects.begin(), objects.end(),
            [](const ObjectStart& a, const ObjectStart& b) { return a.offset < b.offset; });
  return objects;
}

// The n-th (from 0) top-level object of class `name`.
size_t indexOfNth(const std::vector<ObjectStart>& objects, const std::string& name, size_t n) {
  for (size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].class_name == name && n-- == 0) return i;
  }
  ADD_FAILURE() << "no such object";
  return 0;
}

const std::string kPair = "mrpt::obs::CObservationStereoImages";
const std::string kImage = "mrpt::obs::CObservationImage";

struct ReadResult {
  std::vector<RigFrame> frames;
  std::optional<RawlogDamage> damage;
  SkippedFrames skipped;
};

ReadResult readAll(const std::string& path, RawlogReaderOptions options = {}) {
  RawlogReader reader(path, std::move(options));
  ReadResult result;
  while (auto frame = reader.next()) result.frames.push_back(std::move(*frame));
  EXPECT_FALSE(reader.next().has_value()) << "frames after the end";
  result.damage = reader.damage();
  result.skipped = reader.skipped();
  return result;
}

void expectFramesArePrefix(const std::vector<RigFrame>& written, const std::vector<RigFrame>& read,
                           size_t count) {
  ASSERT_EQ(read.size(), count);
  for (size_t i = 0; i < count; ++i) {
    SCOPED_TRACE("frame " + std::to_string(i));
    expectSameFrame(written[i], read[i]);
  }
}

class DamagedRawlogTest : public ::testing::Test {
 protected:
  // Six Triclops frames, plain (uncompressed) and gzip, observations only: per frame an
  // odometry observation (not in frames 2 and 5), the top camera, the pair.
  void SetUp() override {
    frames_ = sampleFrames(triclopsRig(), 6);
    for (const int level : {0, 1}) {
      RawlogWriter writer(
          path(level), {RawlogLayout::kObservations, ImageStorage::kEmbedded, level, "TRICLOPS"});
      for (const auto& frame : frames_) writer.write(frame);
    }
    bytes_ = readBytes(path(0));
    objects_ = topLevelObjects(bytes_);
    ASSERT_EQ(objects_.size(), 16u);  // 4 odometry + 6 top camera + 6 pairs
  }

  std::string path(int compression_level) const {
    return scratch_.file(compression_level ? "run.rawlog" : "plain.rawlog");
  }
  void rewritePlain(const std::string& bytes) const { writeStringAtomically(path(0), bytes); }

  test_support::ScratchDirectory scratch_;
  std::vector<RigFrame> frames_;
  std::string bytes_;
  std::vector<ObjectStart> objects_;
};

TEST_F(DamagedRawlogTest, IntactRawlogReadsToTheEndWithoutDamage) {
  const auto result = readAll(path(0));
  expectFramesArePrefix(frames_, result.frames, 6);
  EXPECT_FALSE(result.damage.has_value());
}

TEST_F(DamagedRawlogTest, TruncatedInsideAPairKeepsEveryEarlierFrame) {
  const size_t damaged = indexOfNth(objects_, kPair, 3);
  rewritePlain(bytes_.substr(0, objects_[damaged].offset + 100));
  const auto result = readAll(path(0));
  expectFramesArePrefix(frames_, result.frames, 3);
  ASSERT_TRUE(result.damage.has_value());
  EXPECT_EQ(result.damage->object_index, damaged);
  EXPECT_EQ(result.damage->byte_offset, objects_[damaged].offset);
  const std::string description = result.damage->describe(path(0));
  EXPECT_NE(description.find(path(0)), std::string::npos) << description;
  EXPECT_NE(description.find("object #" + std::to_string(damaged)), std::string::npos);
}

TEST_F(DamagedRawlogTest, TruncatedInsideAnExtraCameraDropsThatUnfinishedFrame) {
  const size_t damaged = indexOfNth(objects_, kImage, 4);
  rewritePlain(bytes_.substr(0, objects_[damaged].offset + 100));
  const auto result = readAll(path(0));
  expectFramesArePrefix(frames_, result.frames, 4);
  ASSERT_TRUE(result.damage.has_value());
  EXPECT_EQ(result.damage->object_index, damaged);
  EXPECT_EQ(result.damage->byte_offset, objects_[damaged].offset);
}

TEST_F(DamagedRawlogTest, CutAtAnObjectBoundaryIsAShorterRawlog) {
  rewritePlain(bytes_.substr(0, objects_[indexOfNth(objects_, kPair, 2) + 1].offset));
  const auto result = readAll(path(0));
  expectFramesArePrefix(frames_, result.frames, 3);
  EXPECT_FALSE(result.damage.has_value());
}

TEST_F(DamagedRawlogTest, TruncatedGzipStopsAtAnObjectStartAndKeepsTheFramesBeforeIt) {
  const std::string compressed = readBytes(path(1));
  writeStringAtomically(path(1), compressed.substr(0, compressed.size() * 6 / 10));
  const auto result = readAll(path(1));
  ASSERT_TRUE(result.damage.has_value());
  // The uncompressed stream is the plain rawlog, so the damage must be reported at one of its
  // object starts, after exactly the pairs returned.
  ASSERT_LT(result.damage->object_index, objects_.size());
  EXPECT_EQ(result.damage->byte_offset, objects_[result.damage->object_index].offset);
  size_t pairs_before = 0;
  for (size_t i = 0; i < result.damage->object_index; ++i)
    pairs_before += objects_[i].class_name == kPair;
  EXPECT_GT(pairs_before, 0u);
  EXPECT_LT(pairs_before, 6u);
  expectFramesArePrefix(frames_, result.frames, pairs_before);
}

TEST_F(DamagedRawlogTest, CorruptedObjectHeaderInTheMiddleStopsThere) {
  const size_t damaged = indexOfNth(objects_, kPair, 2);
  std::string bytes = bytes_;
  bytes.replace(objects_[damaged].offset, 20, std::string(20, 'X'));
  rewritePlain(bytes);
  const auto result = readAll(path(0));
  expectFramesArePrefix(frames_, result.frames, 2);
  ASSERT_TRUE(result.damage.has_value());
  EXPECT_EQ(result.damage->object_index, damaged);
  EXPECT_EQ(result.damage->byte_offset, objects_[damaged].offset);
}

TEST_F(DamagedRawlogTest, CorruptedNestedObjectStopsAtTheObservationHoldingIt) {
  // Overwrite the class name of the image inside frame 1's top-camera observation.
  const size_t damaged = indexOfNth(objects_, kImage, 1);
  const size_t image_header = bytes_.find("mrpt::img::CImage", objects_[damaged].offset);
  ASSERT_LT(image_header, objects_[damaged + 1].offset);
  std::string bytes = bytes_;
  bytes.replace(image_header, 10, "garbage!!!");
  rewritePlain(bytes);
  const auto result = readAll(path(0));
  expectFramesArePrefix(frames_, result.frames, 1);
  ASSERT_TRUE(result.damage.has_value());
  EXPECT_EQ(result.damage->object_index, damaged);
  EXPECT_EQ(result.damage->byte_offset, objects_[damaged].offset);
}

TEST(RawlogReaderTest, NotARawlogIsDamageAtTheFirstObject) {
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("notes.rawlog");
  writeStringAtomically(path, "these are not the observations you are looking for\n");
  const auto result = readAll(path);
  EXPECT_TRUE(result.frames.empty());
  ASSERT_TRUE(result.damage.has_value());
  EXPECT_EQ(result.damage->object_index, 0u);
  EXPECT_EQ(result.damage->byte_offset, 0u);
}

TEST(RawlogReaderTest, MissingFileIsReportedByName) {
  try {
    RawlogReader reader("/nonexistent/run.rawlog", {});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/run.rawlog"), std::string::npos);
  }
}

TEST(RawlogReaderTest, UnusableFramesAreSkippedAndCounted) {
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("mixed.rawlog");
  const auto frames = sampleFrames(binocularRig(), 5);
  {
    mrpt::io::CFileGZOutputStream out(path);
    auto archive = mrpt::serialization::archiveFrom(out);
    for (size_t i = 0; i < frames.size(); ++i) {
      auto pair = toRigObservations(frames[i], "TRICLOPS").pair;
      if (i == 1) pair->leftCamera.intrinsicParams.setZero();             // no calibration
      if (i == 2) pair->leftCamera.ncols = pair->rightCamera.ncols = 80;  // images not 80 wide
      if (i == 3) pair->rightCamera.setDistortionKannalaBrandt(0.1, 0, 0, 0);  // fisheye lens
      archive << *pair;
    }
  }
  const auto result = readAll(path);
  ASSERT_EQ(result.frames.size(), 2u);
  expectSameFrame(
      [&] {
        RigFrame f = frames[0];
        f.odometry.reset();
        return f;
      }(),
      result.frames[0]);
  EXPECT_EQ(result.frames[1].timestamp, frames[4].timestamp);
  EXPECT_FALSE(result.damage.has_value());
  EXPECT_EQ(result.skipped.total(), 3u);
  EXPECT_EQ(result.skipped.count[static_cast<size_t>(RejectReason::kMissingCalibration)], 1u);
  EXPECT_EQ(result.skipped.count[static_cast<size_t>(RejectReason::kWrongImageFormat)], 1u);
  EXPECT_EQ(result.skipped.count[static_cast<size_t>(RejectReason::kNotRectified)], 1u);
  const std::string summary = result.skipped.summary();
  EXPECT_NE(summary.find("skipped 3 "), std::string::npos) << summary;
  EXPECT_NE(summary.find("1 without calibration"), std::string::npos) << summary;
  EXPECT_NE(summary.find("image is 64x48, its calibration is for 80x48"), std::string::npos)
      << summary;
  EXPECT_NE(summary.find("fisheye"), std::string::npos) << summary;
}

TEST(RawlogReaderTest, FramesNotMatchingTheExpectedRigAreSkipped) {
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("binocular.rawlog");
  {
    RawlogWriter writer(path, {});
    for (const auto& frame : sampleFrames(binocularRig(), 2)) writer.write(frame);
  }
  RawlogReaderOptions options;
  options.expected_rig = triclopsRig();
  const auto wrong_count = readAll(path, options);
  EXPECT_TRUE(wrong_count.frames.empty());
  EXPECT_EQ(wrong_count.skipped.count[static_cast<size_t>(RejectReason::kWrongCameraCount)], 2u);

  options.expected_rig = binocularRig();
  options.expected_rig->reference.width = 320;
  const auto wrong_size = readAll(path, options);
  EXPECT_TRUE(wrong_size.frames.empty());
  EXPECT_EQ(wrong_size.skipped.count[static_cast<size_t>(RejectReason::kWrongImageFormat)], 2u);
  EXPECT_NE(wrong_size.skipped.summary().find("expected 320x48"), std::string::npos);
}

TEST(RawlogReaderTest, FirstFrameSetsTheExpectationWhenNoRigIsGiven) {
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("changing.rawlog");
  const auto triclops = sampleFrames(triclopsRig(), 2);
  const auto binocular = sampleFrames(binocularRig(), 1);
  {
    RawlogWriter writer(path, {});
    writer.write(triclops[0]);
    writer.write(binocular[0]);  // the top camera went missing
    writer.write(triclops[1]);
  }
  const auto result = readAll(path);
  ASSERT_EQ(result.frames.size(), 2u);
  EXPECT_EQ(result.frames[1].timestamp, triclops[1].timestamp);
  EXPECT_EQ(result.skipped.count[static_cast<size_t>(RejectReason::kWrongCameraCount)], 1u);
}

TEST(RawlogReaderTest, ForeignPairTakesItsReferenceSideFromTheExpectedRig) {
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("foreign.rawlog");
  const auto frames = sampleFrames(sampleRig({{-1.0, 0.0}}), 1);
  {
    mrpt::io::CFileGZOutputStream out(path);
    auto archive = mrpt::serialization::archiveFrom(out);
    auto pair = toRigObservations(frames[0], "BB").pair;
    pair->leftCamera.cameraName = "left";  // as other recorders name them
    pair->rightCamera.cameraName = "right";
    archive << *pair;
  }
  EXPECT_DOUBLE_EQ(readAll(path).frames.at(0).rig.secondaries[0].bx, 1.0);
  RawlogReaderOptions options;
  options.expected_rig = sampleRig({{-1.0, 0.0}});
  const auto read = readAll(path, options).frames;
  ASSERT_EQ(read.size(), 1u);
  RigFrame expected = frames[0];
  expected.odometry.reset();
  expectSameFrame(expected, read[0]);
}

}  // namespace
}  // namespace stereonav
