#include "observations/external_images.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "sample_frames.h"

namespace stereonav {
namespace {

TEST(ExternalImagesTest, FolderIsNamedAfterTheRawlogStem) {
  EXPECT_EQ(externalImagesDirectoryFor("/data/run3.rawlog"), "/data/run3_Images");
  EXPECT_EQ(externalImagesDirectoryFor("run3.rawlog"), "run3_Images");
}

TEST(ExternalImagesTest, FindsTheSpellingThatExists) {
  test_support::ScratchDirectory scratch;
  const std::string rawlog = scratch.file("old.rawlog");
  EXPECT_EQ(findExternalImagesDirectory(rawlog), scratch.file("old_Images"));
  std::filesystem::create_directory(scratch.file("old_images"));
  EXPECT_EQ(findExternalImagesDirectory(rawlog), scratch.file("old_images"));
}

TEST(ExternalImagesTest, StoredImageIsAReferenceThatLoadsTheSamePixels) {
  test_support::ScratchDirectory scratch;
  const cv::Mat pixels = sampleFrames(binocularRig(), 1, CV_8UC3)[0].reference;
  mrpt::img::CImage image(pixels.clone(), mrpt::img::SHALLOW_COPY);
  storeImageExternally(image, scratch.file(""), "cam.png");
  EXPECT_TRUE(image.isExternallyStored());
  EXPECT_EQ(image.getExternalStorageFile(), "cam.png");
  EXPECT_TRUE(samePixels(imagePixels(image, scratch.file("")), pixels));
  EXPECT_TRUE(imagePixels(image, scratch.file("elsewhere")).empty());
}

}  // namespace
}  // namespace stereonav
