#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

namespace stereonav::fuzz {

// The readers under test take paths: each input is written to a file of this process's own,
// named with `extension` (readers that choose a format by extension see the right one).
class FuzzInputFile {
 public:
  FuzzInputFile(const uint8_t* data, size_t size, const std::string& extension)
      : path_("/tmp/stereonav_fuzz_" + std::to_string(::getpid()) + extension) {
    std::ofstream(path_, std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  ~FuzzInputFile() { std::remove(path_.c_str()); }
  FuzzInputFile(const FuzzInputFile&) = delete;
  FuzzInputFile& operator=(const FuzzInputFile&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace stereonav::fuzz
