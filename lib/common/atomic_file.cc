#include "common/atomic_file.h"

#include <fcntl.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <vector>

namespace stereonav {
namespace {

[[noreturn]] void failWith(const std::string& path, const std::string& what, int error) {
  throw std::runtime_error(path + ": cannot write (" + what + ": " + std::strerror(error) + ")");
}

// Flushes an existing file's data to the disk; delayed write errors surface here.
void syncFile(const std::string& temporary, const std::string& path) {
  const int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) failWith(path, "reopening the temporary file", errno);
  const bool synced = ::fsync(fd) == 0;
  const int sync_error = errno;
  ::close(fd);
  if (!synced) failWith(path, "flushing to disk", sync_error);
}

void renameOver(const std::string& temporary, const std::string& path) {
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    std::remove(temporary.c_str());
    failWith(path, "renaming the temporary file", error);
  }
}

void writeBytes(const std::string& path, const void* data, size_t size) {
  const std::string temporary = temporaryPathFor(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) failWith(path, "creating the temporary file", errno);
  const auto fail = [&](const char* what) {
    const int error = errno;
    ::close(fd);
    std::remove(temporary.c_str());
    failWith(path, what, error);
  };
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      fail("writing");
    }
    bytes += written;
    size -= static_cast<size_t>(written);
  }
  if (::fsync(fd) != 0) fail("flushing to disk");
  if (::close(fd) != 0) {
    const int error = errno;
    std::remove(temporary.c_str());
    failWith(path, "closing", error);
  }
  renameOver(temporary, path);
}

std::string extensionOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  const bool has_extension = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return has_extension ? path.substr(dot) : "";
}

}  // namespace

void OutputBatch::write(const std::function<void()>& write_one) {
  try {
    write_one();
  } catch (const std::exception& error) {
    errors_.push_back(error.what());
  }
}

void OutputBatch::throwIfFailed() const {
  if (errors_.empty()) return;
  std::string message = errors_.front();
  if (errors_.size() > 1) {
    message += " (and " + std::to_string(errors_.size() - 1) + " more output" + (errors_.size() > 2 ? "s" : "") +
               " not written: ";
    for (size_t i = 1; i < errors_.size(); ++i) {
      const std::string& error = errors_[i];
      message += (i > 1 ? ", " : "") + error.substr(0, error.find(": "));
    }
    message += ")";
  }
  throw std::runtime_error(message);
}

std::string temporaryPathFor(const std::string& path) {
  const std::string extension = extensionOf(path);
  return path.substr(0, path.size() - extension.size()) + ".tmp" + std::to_string(::getpid()) + extension;
}

void writeStringAtomically(const std::string& path, std::string_view contents) {
  writeBytes(path, contents.data(), contents.size());
}

void writeImageAtomically(const std::string& path, const cv::Mat& image, const std::vector<int>& encoder_params) {
  std::vector<uchar> encoded;
  bool ok = false;
  try {
    ok = cv::imencode(extensionOf(path), image, encoded, encoder_params);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok) throw std::runtime_error(path + ": cannot encode the image in this format");
  writeBytes(path, encoded.data(), encoded.size());
}

void writeGzArchiveAtomically(const std::string& path,
                              const std::function<void(mrpt::serialization::CArchive&)>& write) {
  mrpt::io::CMemoryStream memory;
  {
    auto archive = mrpt::serialization::archiveFrom(memory);
    write(archive);
  }
  // gzip framing (window bits 15 + 16) at level 1, as CFileGZOutputStream writes by default.
  z_stream stream{};
  if (deflateInit2(&stream, 1, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
    throw std::runtime_error(path + ": cannot write (gzip initialisation failed)");
  }
  const uLong size = static_cast<uLong>(memory.getTotalBytesCount());
  std::vector<uint8_t> compressed(deflateBound(&stream, size));
  stream.next_in = static_cast<Bytef*>(memory.getRawBufferData());
  stream.avail_in = static_cast<uInt>(size);
  stream.next_out = compressed.data();
  stream.avail_out = static_cast<uInt>(compressed.size());
  const int result = deflate(&stream, Z_FINISH);
  const size_t compressed_size = stream.total_out;
  deflateEnd(&stream);
  if (result != Z_STREAM_END) throw std::runtime_error(path + ": cannot write (gzip compression failed)");
  writeBytes(path, compressed.data(), compressed_size);
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& temporary_path)>& write_to) {
  const std::string temporary = temporaryPathFor(path);
  try {
    write_to(temporary);
    syncFile(temporary, path);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  renameOver(temporary, path);
}

}  // namespace stereonav
