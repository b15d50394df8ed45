#include "observations/deserialization_budget.h"

#include <gtest/gtest.h>

#include <memory>
#include <new>
#include <string>

namespace stereonav {
namespace {

TEST(DeserializationBudgetTest, AllocationBeyondTheBudgetFailsOnlyWhileItLives) {
#ifdef __SANITIZE_ADDRESS__
  // AddressSanitizer's operator new aborts the process when the address space runs out instead of
  // throwing std::bad_alloc (allocator_may_return_null covers malloc only), so the refusal cannot
  // be observed here; the Release run checks it.
  GTEST_SKIP() << "AddressSanitizer aborts on out-of-memory instead of throwing std::bad_alloc";
#endif
  constexpr size_t kGigabyte = size_t{1} << 30;
  {
    DeserializationBudget budget(64u << 20);
    // What a damaged length field asks for: refused at once instead of zero-filled.
    EXPECT_THROW(std::make_unique<char[]>(4 * kGigabyte), std::bad_alloc);
    EXPECT_NO_THROW(std::make_unique<char[]>(1u << 20));
  }
  EXPECT_NO_THROW(std::unique_ptr<char[]>(new char[kGigabyte]));  // not touched: no memory used
}

TEST(DeserializationBudgetTest, GrowsWithWhatIsLeftOfTheFile) {
  EXPECT_LT(DeserializationBudget::forRemainingBytes(0), DeserializationBudget::forRemainingBytes(1 << 20));
  EXPECT_GE(DeserializationBudget::forRemainingBytes(1 << 20), uint64_t{1} << 20);
}

TEST(UncompressedSizeTest, CountsTheDecompressedBytes) {
  // gzip's trailer of this file records 176058 bytes (`file` prints it).
  EXPECT_EQ(uncompressedSize(std::string(STEREONAV_TEST_DATA_DIR) + "/repro/office3.rawlog"), 176058u);
  EXPECT_EQ(uncompressedSize("/nonexistent.rawlog"), 0u);
}

}  // namespace
}  // namespace stereonav
