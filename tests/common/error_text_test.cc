#include "common/error_text.h"

#include <gtest/gtest.h>

namespace stereonav {
namespace {

TEST(OneLineMessageTest, KeepsOurOneLineMessages) {
  EXPECT_EQ(oneLineMessage("a.ini: [grid] resolution: expected [0.001, 100], got '0'"),
            "a.ini: [grid] resolution: expected [0.001, 100], got '0'");
}

// The shape of MRPT 2.5's report for a truncated rawlog (abridged backtraces).
constexpr const char* kNestedMrptReport =
    "==== MRPT exception ====\n"
    "Message:  Exception while parsing typed object 'mrpt::obs::CObservationImage' from "
    "mrpt::io::CFileGZInputStream for file 'x.rawlog'\n"
    "Original exception:\n"
    "==== MRPT exception ====\n"
    "Message:  (EOF?) Cannot read requested number of bytes from stream\n"
    "Location: ./libs/serialization/src/CArchive.cpp:34: [size_t mrpt::serialization::CArchive::ReadBuffer]\n"
    "Call stack backtrace:\n"
    "[0 ] (unknown file) mrpt::ExceptionWithCallBack<std::logic_error>::ExceptionWithCallBack\n"
    "\n"
    "Location: ./libs/serialization/src/CArchive.cpp:475: [void internal_ReadObject]\n"
    "Call stack backtrace:\n"
    "[0 ] (unknown file) mrpt::serialization::CArchive::ReadObject\n";

TEST(OneLineMessageTest, NamesTheObjectAndTheInnermostCauseOfAnMrptReport) {
  EXPECT_EQ(oneLineMessage(kNestedMrptReport),
            "reading mrpt::obs::CObservationImage: (EOF?) Cannot read requested number of bytes from stream");
}

TEST(OneLineMessageTest, SingleMrptReportGivesItsMessage) {
  EXPECT_EQ(oneLineMessage("==== MRPT exception ====\nMessage:  Wrong file\nLocation: a.cpp:1: [f]\n"
                           "Call stack backtrace:\n[0 ] f\n"),
            "Wrong file");
}

TEST(OneLineMessageTest, MrptIniParserReportWithoutAMessageLineGivesItsReason) {
  // What MRPT 2.5's ini parser throws for "$eval{" left open (found by fuzz_ini_options).
  EXPECT_EQ(oneLineMessage("==== MRPT exception ====\nLine 139: Expected closing `}` near: `$eval{x = 8`\n"
                           "Call stack backtrace:\n[0 ]     0x7f5e10dedb28\n"),
            "Line 139: Expected closing `}` near: `$eval{x = 8`");
}

TEST(OneLineMessageTest, OtherMultiLineTextGivesItsFirstLine) {
  EXPECT_EQ(oneLineMessage("\nfirst\nsecond\n"), "first");
}

}  // namespace
}  // namespace stereonav
