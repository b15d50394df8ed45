#include "common/atomic_file.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace stereonav {

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& temporary_path)>& write_to) {
  // Keep the temporary beside the target so rename() stays within one filesystem (atomic); keep
  // its extension so writers that choose a format by extension (cv::imwrite) still work.
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  const bool has_extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  const std::string stem = has_extension ? path.substr(0, dot) : path;
  const std::string extension = has_extension ? path.substr(dot) : "";
  const std::string temporary = stem + ".tmp" + std::to_string(::getpid()) + extension;
  try {
    write_to(temporary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error(path + ": cannot write (rename of the temporary file failed)");
  }
}

void writeStringAtomically(const std::string& path, const std::string& contents) {
  writeFileAtomically(path, [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.close();
    if (!out) throw std::runtime_error(path + ": cannot write");
  });
}

}  // namespace stereonav
