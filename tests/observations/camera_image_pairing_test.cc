#include "observations/camera_image_pairing.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>

#include "observations/rawlog_reader.h"
#include "observations/rig_observations.h"
#include "sample_frames.h"

namespace stereonav {
namespace {

mrpt::obs::CObservationImage::Ptr image(const std::string& label, double t) {
  auto observation = mrpt::obs::CObservationImage::Create();
  observation->sensorLabel = label;
  observation->timestamp = mrpt::Clock::fromDouble(1.7e9 + t);
  return observation;
}

double time(const mrpt::obs::CObservationImage::Ptr& observation) {
  return mrpt::Clock::toDouble(observation->timestamp) - 1.7e9;
}

// Feeds images, then finishes; returns the captures as "t_ref/t_partner..." or "skip".
std::vector<std::string> pairAll(const ImagePairingOptions& options,
                                 const std::vector<mrpt::obs::CObservationImage::Ptr>& images) {
  CameraImagePairer pairer(options);
  std::vector<std::string> captures;
  const auto drain = [&] {
    while (auto capture = pairer.next()) {
      if (!capture->missing.empty()) {
        EXPECT_TRUE(capture->images.empty());
        captures.push_back("skip");
        continue;
      }
      std::string text;
      for (const auto& observation : capture->images) {
        char number[16];
        std::snprintf(number, sizeof number, "%.3f", time(observation));
        text += (text.empty() ? "" : "/") + std::string(number);
      }
      captures.push_back(text);
    }
  };
  for (const auto& observation : images) {
    pairer.add(observation);
    drain();
  }
  pairer.finish();
  drain();
  return captures;
}

const ImagePairingOptions kStereo{{"LEFT", "RIGHT"}, 0.005};

TEST(CameraImagePairingTest, PairsImagesWithinTheToleranceOnly) {
  EXPECT_EQ(pairAll(kStereo, {image("LEFT", 0.0), image("RIGHT", 0.0), image("LEFT", 0.1),
                              image("RIGHT", 0.104), image("RIGHT", 0.196), image("LEFT", 0.2)}),
            (std::vector<std::string>{"0.000/0.000", "0.100/0.104", "0.200/0.196"}));
  // 6 ms apart is a missing partner for each side: the left frame and the right image.
  EXPECT_EQ(pairAll(kStereo, {image("LEFT", 0.0), image("RIGHT", 0.006), image("LEFT", 0.1),
                              image("RIGHT", 0.1)}),
            (std::vector<std::string>{"skip", "skip", "0.100/0.100"}));
}

TEST(CameraImagePairingTest, MissingPartnerIsSkippedAndCountedNeverStalls) {
  // The right camera drops frame 0.1; the left one drops frame 0.3.
  EXPECT_EQ(pairAll(kStereo, {image("LEFT", 0.0), image("RIGHT", 0.0), image("LEFT", 0.1),
                              image("LEFT", 0.2), image("RIGHT", 0.2), image("RIGHT", 0.3),
                              image("LEFT", 0.4), image("RIGHT", 0.4)}),
            (std::vector<std::string>{"0.000/0.000", "skip", "0.200/0.200", "skip",
                                      "0.400/0.400"}));
  // Only one camera at all, and the partner's last image alone at the end.
  EXPECT_EQ(pairAll(kStereo, {image("LEFT", 0.0), image("LEFT", 0.1)}),
            (std::vector<std::string>{"skip", "skip"}));
  EXPECT_EQ(pairAll(kStereo, {image("RIGHT", 0.0)}), (std::vector<std::string>{"skip"}));
  EXPECT_TRUE(pairAll(kStereo, {}).empty());
}

TEST(CameraImagePairingTest, ThreeCamerasOutOfOrderAndOtherLabelsIgnored) {
  const ImagePairingOptions triclops{{"RIGHT", "LEFT", "TOP"}, 0.002};
  EXPECT_EQ(pairAll(triclops, {image("TOP", 0.001), image("IMU", 0.0), image("LEFT", 0.0),
                               image("RIGHT", 0.0), image("LEFT", 0.05), image("RIGHT", 0.0499),
                               image("TOP", 0.0502)}),
            (std::vector<std::string>{"0.000/0.000/0.001", "0.050/0.050/0.050"}));
  // The top camera's image closest in time wins.
  EXPECT_EQ(pairAll(triclops, {image("RIGHT", 0.0), image("LEFT", 0.0), image("TOP", -0.0015),
                               image("TOP", 0.0004), image("RIGHT", 0.1), image("LEFT", 0.1),
                               image("TOP", 0.1)}),
            (std::vector<std::string>{"skip", "0.000/0.000/0.000", "0.100/0.100/0.100"}));
}

TEST(CameraImagePairingTest, ACaptureOfOneInstantIsDecidedWhenItsLastCameraArrives) {
  CameraImagePairer pairer({{"LEFT", "RIGHT", "TOP"}, 0.005});
  pairer.add(image("RIGHT", 0.0));
  pairer.add(image("LEFT", 0.0));
  EXPECT_FALSE(pairer.next());  // TOP may still come
  pairer.add(image("TOP", 0.002));
  EXPECT_FALSE(pairer.next());  // a TOP image closer to 0.0 may still come
  pairer.add(image("TOP", 0.0));
  const auto capture = pairer.next();
  ASSERT_TRUE(capture);
  ASSERT_EQ(capture->images.size(), 3u);
  EXPECT_DOUBLE_EQ(time(capture->images[2]), 0.0);
}

TEST(CameraImagePairingTest, IniKeys) {
  mrpt::config::CConfigFileMemory config;
  config.write("rawlog", "camera_labels", "LEFT RIGHT TOP");
  config.write("rawlog", "pairing_tolerance_s", "0.01");
  IniSection section(config, "rawlog");
  const ImagePairingOptions options = loadImagePairingOptions(section);
  EXPECT_EQ(options.labels, (std::vector<std::string>{"LEFT", "RIGHT", "TOP"}));
  EXPECT_DOUBLE_EQ(options.max_time_difference_s, 0.01);
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"camera_labels", "LEFT"}, {"camera_labels", "LEFT LEFT"},
           {"pairing_tolerance_s", "0"}}) {
    mrpt::config::CConfigFileMemory bad;
    bad.write("rawlog", key, value);
    IniSection bad_section(bad, "rawlog");
    EXPECT_THROW(loadImagePairingOptions(bad_section), ConfigError) << key << " = " << value;
  }
}

TEST(CameraImagePairingTest, RawlogOfSeparateImagesReadsAsFrames) {
  // A binocular head recorded as rawlog-grabber does with two cameras: one CObservationImage
  // each, the right one 2 ms late and missing frame 2, odometry before every frame.
  test_support::ScratchDirectory scratch;
  const std::string path = scratch.file("separate.rawlog");
  const CameraRig rig = binocularRig();
  const std::vector<RigFrame> frames = sampleFrames(rig, 5);
  {
    mrpt::io::CFileGZOutputStream out(path);
    auto archive = mrpt::serialization::archiveFrom(out);
    for (size_t i = 0; i < frames.size(); ++i) {
      const RigObservations observations = toRigObservations(frames[i], "HEAD");
      if (frames[i].odometry) {
        mrpt::obs::CObservationOdometry odometry;
        odometry.timestamp = frames[i].timestamp;
        odometry.odometry = *frames[i].odometry;
        archive << odometry;
      }
      mrpt::obs::CObservationImage left, right;
      left.sensorLabel = "LEFT";
      right.sensorLabel = "RIGHT";
      left.timestamp = frames[i].timestamp;
      right.timestamp = frames[i].timestamp + std::chrono::milliseconds(2);
      left.cameraParams = observations.pair->leftCamera;
      right.cameraParams = observations.pair->rightCamera;
      left.cameraPose = mrpt::poses::CPose3D(observations.pair->cameraPose);
      right.cameraPose = left.cameraPose + mrpt::poses::CPose3D(observations.pair->rightCameraPose);
      left.image = observations.pair->imageLeft;
      right.image = observations.pair->imageRight;
      archive << left;
      if (i != 2) archive << right;
    }
  }
  RawlogReaderOptions options;
  options.pairing = {{"LEFT", "RIGHT"}, 0.005};
  RawlogReader reader(path, options);
  std::vector<RigFrame> read;
  while (auto frame = reader.next()) read.push_back(std::move(*frame));
  ASSERT_EQ(read.size(), 4u);
  expectSameFrame(frames[0], read[0]);
  expectSameFrame(frames[4], read[3]);
  EXPECT_EQ(reader.skipped().count[static_cast<size_t>(RejectReason::kMissingPartner)], 1u);
  EXPECT_NE(reader.skipped().summary().find("no RIGHT image within"), std::string::npos)
      << reader.skipped().summary();
}

}  // namespace
}  // namespace stereonav
