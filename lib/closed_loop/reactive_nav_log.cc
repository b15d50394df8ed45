#include "closed_loop/reactive_nav_log.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <stdexcept>

#include "common/atomic_file.h"

namespace stereonav {

void ReactiveNavLog::append(const mrpt::nav::CLogFileRecord& record) {
  auto archive = mrpt::serialization::archiveFrom(serialized_);
  archive << record;
  ++records_;
}

void ReactiveNavLog::save(const std::string& path) const {
  writeFileAtomically(path, [&](const std::string& temporary) {
    mrpt::io::CFileGZOutputStream file;
    if (!file.open(temporary)) throw std::runtime_error(path + ": cannot create the file");
    const auto bytes = static_cast<size_t>(serialized_.getTotalBytesCount());
    if (bytes > 0 && file.Write(serialized_.getRawBufferData(), bytes) != bytes) {
      throw std::runtime_error(path + ": cannot write");
    }
    file.close();
  });
}

}  // namespace stereonav
