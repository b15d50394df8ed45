#include "common/atomic_file.h"

#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <sys/resource.h>

#include <csignal>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/scratch_directory.h"

namespace stereonav {
namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

TEST(AtomicFileTest, ReplacesContentsAndLeavesNoTemporary) {
  const test_support::ScratchDirectory scratch;
  const std::filesystem::path& directory = scratch.path();
  const std::string path = (directory / "out.txt").string();
  writeStringAtomically(path, "first");
  writeStringAtomically(path, "second");
  EXPECT_EQ(readAll(path), "second");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory), {}), 1);
}

TEST(AtomicFileTest, FailedWriterKeepsThePreviousFile) {
  const test_support::ScratchDirectory scratch;
  const std::filesystem::path& directory = scratch.path();
  const std::string path = (directory / "map.png").string();
  writeStringAtomically(path, "good map");
  EXPECT_THROW(writeFileAtomically(path,
                                   [](const std::string& temporary) {
                                     std::ofstream(temporary) << "half";
                                     throw std::runtime_error("interrupted");
                                   }),
               std::runtime_error);
  EXPECT_EQ(readAll(path), "good map");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory), {}), 1);
}

TEST(AtomicFileTest, UnwritableDirectoryNamesThePath) {
  try {
    writeStringAtomically("/nonexistent-dir/out.txt", "x");
    FAIL();
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent-dir/out.txt"), std::string::npos);
  }
}

// A full disk, injected: RLIMIT_FSIZE makes writes past the limit fail with EFBIG (SIGXFSZ
// ignored) exactly where a full filesystem fails them with ENOSPC.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    getrlimit(RLIMIT_FSIZE, &previous_);
    rlimit limited = previous_;
    limited.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &limited);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &previous_);
    std::signal(SIGXFSZ, previous_handler_);
  }

 private:
  rlimit previous_{};
  void (*previous_handler_)(int) = nullptr;
};

TEST(AtomicFileTest, FullDiskThrowsNamingTheFileAndKeepsThePrevious) {
  const test_support::ScratchDirectory scratch;
  const std::filesystem::path& directory = scratch.path();
  const std::string path = (directory / "map.gridmap").string();
  writeStringAtomically(path, "good map");
  {
    FileSizeLimit limit(4096);
    try {
      writeStringAtomically(path, std::string(100000, 'x'));
      FAIL() << "a write beyond the file size limit succeeded";
    } catch (const std::runtime_error& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind(path + ": cannot write", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos);
    }
    cv::Mat1b noise(300, 300);
    cv::randu(noise, 0, 255);
    EXPECT_THROW(writeImageAtomically((directory / "map.png").string(), noise), std::runtime_error);
  }
  EXPECT_EQ(readAll(path), "good map");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory), {}), 1);
}

TEST(AtomicFileTest, ImagesAndGzArchivesRoundTrip) {
  const test_support::ScratchDirectory scratch;
  const std::filesystem::path& directory = scratch.path();
  cv::Mat1b image(20, 30);
  cv::randu(image, 0, 255);
  const std::string png = (directory / "a.png").string(), pgm = (directory / "a.pgm").string();
  writeImageAtomically(png, image);
  writeImageAtomically(pgm, image);
  for (const auto& path : {png, pgm}) {
    const cv::Mat read = cv::imread(path, cv::IMREAD_UNCHANGED);
    ASSERT_EQ(read.size(), image.size()) << path;
    EXPECT_EQ(cv::norm(read, image, cv::NORM_INF), 0.0) << path;
  }
  const std::string archive_path = (directory / "values.gz").string();
  writeGzArchiveAtomically(archive_path, [](mrpt::serialization::CArchive& archive) {
    archive << std::string("stereo") << uint32_t{42};
  });
  mrpt::io::CFileGZInputStream in(archive_path);
  std::string text;
  uint32_t number = 0;
  auto archive = mrpt::serialization::archiveFrom(in);
  archive >> text >> number;
  EXPECT_EQ(text, "stereo");
  EXPECT_EQ(number, 42u);
  EXPECT_THROW(writeImageAtomically((directory / "a.unknown").string(), image), std::runtime_error);
}

TEST(OutputBatchTest, OneFailureDoesNotCostTheOthers) {
  OutputBatch outputs;
  int written = 0;
  outputs.write([&] { ++written; });
  outputs.write([] { throw std::runtime_error("a.gridmap: cannot write (disk full)"); });
  outputs.write([&] { ++written; });
  outputs.write([] { throw std::runtime_error("a.png: cannot write (disk full)"); });
  EXPECT_EQ(written, 2);
  try {
    outputs.throwIfFailed();
    FAIL();
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "a.gridmap: cannot write (disk full) (and 1 more output not written: a.png)");
  }
  EXPECT_NO_THROW(OutputBatch().throwIfFailed());
}

}  // namespace
}  // namespace stereonav
