#include "common/csv_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace stereonav {
namespace {

TEST(CsvWriterTest, HeaderThenRowsOfNumbersAndText) {
  CsvWriter csv({"t", "phase", "frontiers", "target_x"});
  csv.add(0.2).add("driving").add(size_t{3}).add(1.23456789).endRow();
  csv.add(0.4).add("looking_around").add(0).add(NAN).endRow();
  EXPECT_EQ(csv.str(),
            "t,phase,frontiers,target_x\n"
            "0.2,driving,3,1.23457\n"
            "0.4,looking_around,0,nan\n");
}

TEST(CsvWriterTest, QuotesTextThatHoldsASeparatorOrAQuote) {
  CsvWriter csv({"reason"});
  csv.add("boxed in, no \"exit\"").endRow();
  EXPECT_EQ(csv.str(), "reason\n\"boxed in, no \"\"exit\"\"\"\n");
}

TEST(CsvWriterTest, ARowMustHaveOneFieldPerColumn) {
  CsvWriter csv({"a", "b"});
  csv.add(1.0);
  EXPECT_THROW(csv.endRow(), std::logic_error);
}

}  // namespace
}  // namespace stereonav
