#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace cv {
class Mat;
}
namespace mrpt::serialization {
class CArchive;
}

namespace stereonav {

// Every output file goes through one of these. The data goes to a temporary file beside `path`
// (same filesystem, so the rename is atomic), every write is checked, the file is flushed to
// disk (fsync) and closed, and only then renamed over `path`. Any failure (a full disk, a
// read-only folder) throws std::runtime_error naming `path` and the cause, removes the
// temporary and leaves the previous `path` intact: readers never see a half-written output.

// The bytes of `contents`.
void writeStringAtomically(const std::string& path, std::string_view contents);

// `image` encoded by cv::imencode in the format of `path`'s extension (.png, .pgm, ...).
void writeImageAtomically(const std::string& path, const cv::Mat& image, const std::vector<int>& encoder_params = {});

// What `write` puts into an MRPT archive, gzip-compressed as mrpt::io::CFileGZOutputStream
// writes it (.gridmap, .rawlog, .3Dscene files).
void writeGzArchiveAtomically(const std::string& path,
                              const std::function<void(mrpt::serialization::CArchive&)>& write);

// For writers that can only write to a path themselves: `write_to` receives the temporary path
// and must create the file there, throwing if it cannot; the file is then flushed and renamed.
// Such writers should check their own writes; prefer the functions above, which check every byte.
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& temporary_path)>& write_to);

// Writes several outputs so that one that cannot be written does not cost the others: each
// write() runs even after another failed; throwIfFailed() then throws one std::runtime_error whose
// one-line message is the first failure, followed by the count of the others.
class OutputBatch {
 public:
  void write(const std::function<void()>& write_one);
  bool failed() const { return !errors_.empty(); }
  const std::vector<std::string>& errors() const { return errors_; }
  void throwIfFailed() const;

 private:
  std::vector<std::string> errors_;
};

// The temporary path writeFileAtomically uses for `path`: same folder, ".tmp<pid>" before the
// extension (writers that choose a format by extension still work).
std::string temporaryPathFor(const std::string& path);

}  // namespace stereonav
