#pragma once

#include <sys/resource.h>

#include <cstdint>
#include <string>

namespace stereonav {

// MRPT's deserializer trusts the sizes a record declares: a damaged string or vector length
// (e.g. pixel bytes read as a camera name's length) makes it allocate and zero-fill gigabytes
// before it finds the stream too short. While an instance lives, the process's address space may
// grow by at most `budget_bytes`, so such an allocation fails at once with std::bad_alloc, which
// the reader reports as damage. Set only around the deserialization of one record, on the
// reading thread; the previous limit is restored on destruction.
class DeserializationBudget {
 public:
  explicit DeserializationBudget(uint64_t budget_bytes);
  ~DeserializationBudget();

  DeserializationBudget(const DeserializationBudget&) = delete;
  DeserializationBudget& operator=(const DeserializationBudget&) = delete;

  // The budget for a record with `remaining_bytes` of the (uncompressed) stream left: nothing it
  // declares can be larger than that, except images that decode to more than they store.
  static uint64_t forRemainingBytes(uint64_t remaining_bytes);

 private:
  rlimit previous_{};
  bool active_ = false;
};

// The uncompressed size of a gzip-compressed (or plain) file, up to where its compressed data is
// damaged; one pass of decompression.
uint64_t uncompressedSize(const std::string& path);

}  // namespace stereonav
