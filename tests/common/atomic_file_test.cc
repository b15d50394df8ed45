#include "common/atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace stereonav {
namespace {

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

TEST(AtomicFileTest, ReplacesContentsAndLeavesNoTemporary) {
  const auto directory = std::filesystem::temp_directory_path() / "stereonav_atomic_test";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  const std::string path = (directory / "out.txt").string();
  writeStringAtomically(path, "first");
  writeStringAtomically(path, "second");
  EXPECT_EQ(readAll(path), "second");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(directory), {}), 1);
  std::filesystem::remove_all(directory);
}

TEST(AtomicFileTest, FailedWriterKeepsThePreviousFile) {
  const auto directory = std::filesystem::temp_directory_path() / "stereonav_atomic_fail";
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
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
  std::filesystem::remove_all(directory);
}

TEST(AtomicFileTest, UnwritableDirectoryNamesThePath) {
  try {
    writeStringAtomically("/nonexistent-dir/out.txt", "x");
    FAIL();
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent-dir/out.txt"), std::string::npos);
  }
}

}  // namespace
}  // namespace stereonav
