// MRPT's own rawlog-edit must read every kind of rawlog we write.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <tuple>

#include "observations/rawlog_writer.h"
#include "sample_frames.h"

namespace stereonav {
namespace {

constexpr const char* kRawlogEdit = "/usr/bin/rawlog-edit";

std::string outputOf(const std::string& command) {
  std::string output;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return output;
  std::array<char, 4096> buffer;
  while (const size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) {
    output.append(buffer.data(), n);
  }
  ::pclose(pipe);
  return output;
}

size_t occurrences(const std::string& text, const std::string& what) {
  size_t count = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++count;
  return count;
}

class RawlogEditTest
    : public ::testing::TestWithParam<std::tuple<RawlogLayout, ImageStorage, bool>> {};

TEST_P(RawlogEditTest, ListsOurStereoAndImageObservations) {
  if (!std::filesystem::exists(kRawlogEdit)) GTEST_SKIP() << kRawlogEdit << " is not installed";
  const auto [layout, storage, trinocular] = GetParam();
  test_support::ScratchDirectory scratch;
  const auto frames = sampleFrames(trinocular ? triclopsRig() : binocularRig(), 3);
  {
    RawlogWriter writer(scratch.file("run.rawlog"), {layout, storage, 1, "TRICLOPS"});
    for (const auto& frame : frames) writer.write(frame);
  }
  // Run from the rawlog's folder: MRPT 2.5's CRawlog::detectImagesDirectory drops the '/' before
  // "<stem>_Images" when the rawlog path has a folder in it.
  const std::string command = "cd '" + scratch.file("") + "' && " + kRawlogEdit + " -i run.rawlog";

  const std::string info = outputOf(command + " --info");
  SCOPED_TRACE(info);
  const size_t odometry = layout == RawlogLayout::kObservations ? 2 : 0;  // frames 0 and 1
  const size_t objects = layout == RawlogLayout::kObservations ? odometry + 3 * (trinocular ? 2 : 1)
                                                               : 2 * 3;  // actions + frame
  EXPECT_NE(info.find("Overall number of objects         : " + std::to_string(objects)),
            std::string::npos);
  EXPECT_NE(info.find("TRICLOPS /      3"), std::string::npos);
  EXPECT_EQ(info.find("TRICLOPS_CAM2 /      3") != std::string::npos, trinocular);

  // --describe loads every image, so it also proves MRPT finds our external image files.
  const std::string described = outputOf(command + " --describe");
  EXPECT_EQ(occurrences(described, "ClassName: mrpt::obs::CObservationStereoImages"), 3u);
  EXPECT_EQ(occurrences(described, "ClassName: mrpt::obs::CObservationImage\n"),
            trinocular ? 3u : 0u);
  // Once per pair and once per top-camera image.
  EXPECT_EQ(occurrences(described, "Image size: 64x48 pixels"), trinocular ? 6u : 3u);
  EXPECT_EQ(occurrences(described, "MRPT exception"), 0u) << described;
}

// Every layout with every image storage, each head in both layouts and both storages (rawlog-edit
// takes a third of a second to start, so not the full product).
INSTANTIATE_TEST_SUITE_P(
    EveryKindWeWrite, RawlogEditTest,
    ::testing::Values(std::make_tuple(RawlogLayout::kObservations, ImageStorage::kEmbedded, true),
                      std::make_tuple(RawlogLayout::kObservations, ImageStorage::kExternal, false),
                      std::make_tuple(RawlogLayout::kSensoryFrames, ImageStorage::kEmbedded, false),
                      std::make_tuple(RawlogLayout::kSensoryFrames, ImageStorage::kExternal,
                                      true)));

}  // namespace
}  // namespace stereonav
