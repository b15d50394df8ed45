#include "observations/deserialization_budget.h"

#include <unistd.h>
#include <zlib.h>

#include <fstream>
#include <vector>

namespace stereonav {
namespace {

// Images of a record (JPEG/PNG-compressed in some rawlogs) can decode to this many times their
// stored size; the constant part covers the decoders' own buffers.
constexpr uint64_t kDecodedPerStoredByte = 64;
constexpr uint64_t kFixedBudget = 256ull << 20;

uint64_t addressSpaceInUse() {
  std::ifstream statm("/proc/self/statm");
  uint64_t pages = 0;
  statm >> pages;
  return pages * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
}

}  // namespace

DeserializationBudget::DeserializationBudget(uint64_t budget_bytes) {
  const uint64_t in_use = addressSpaceInUse();
  if (in_use == 0 || ::getrlimit(RLIMIT_AS, &previous_) != 0) return;
  rlimit limited = previous_;
  const uint64_t wanted = in_use + budget_bytes;
  // Never raise a limit someone else set, nor go beyond the hard limit.
  if (previous_.rlim_cur != RLIM_INFINITY && wanted >= previous_.rlim_cur) return;
  limited.rlim_cur = static_cast<rlim_t>(wanted);
  active_ = ::setrlimit(RLIMIT_AS, &limited) == 0;
}

DeserializationBudget::~DeserializationBudget() {
  if (active_) ::setrlimit(RLIMIT_AS, &previous_);
}

uint64_t DeserializationBudget::forRemainingBytes(uint64_t remaining_bytes) {
  return kFixedBudget + kDecodedPerStoredByte * remaining_bytes;
}

uint64_t uncompressedSize(const std::string& path) {
  gzFile file = gzopen(path.c_str(), "rb");  // reads plain files as they are
  if (file == nullptr) return 0;
  std::vector<char> buffer(1 << 20);
  uint64_t total = 0;
  while (true) {
    const int read = gzread(file, buffer.data(), static_cast<unsigned>(buffer.size()));
    if (read <= 0) break;
    total += static_cast<uint64_t>(read);
  }
  gzclose(file);
  return total;
}

}  // namespace stereonav
