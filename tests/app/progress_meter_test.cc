#include "progress_meter.h"

#include <gtest/gtest.h>

#include <csignal>
#include <sstream>

#include "sigint_stop.h"

namespace stereonav {
namespace {

TEST(ProgressMeterTest, FinalLineShowsCountPercentageAndEndsTheLine) {
  std::ostringstream out;
  ProgressMeter meter(out, "exploring", 60);
  meter.finish(30);
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("\rexploring [", 0), 0u) << text;  // redrawn in place, the work named
  EXPECT_NE(text.find("30/60"), std::string::npos) << text;
  EXPECT_NE(text.find(" 50%"), std::string::npos) << text;
  EXPECT_NE(text.find("[############............]"), std::string::npos) << text;
  EXPECT_NE(text.find("ETA"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
}

TEST(ProgressMeterTest, WithoutATotalShowsCountAndRateOnly) {
  std::ostringstream out;
  ProgressMeter meter(out, "mapping", std::nullopt);
  meter.finish(12);
  EXPECT_NE(out.str().find("12 frames"), std::string::npos) << out.str();
  EXPECT_EQ(out.str().find("ETA"), std::string::npos) << out.str();
}

TEST(ProgressMeterTest, UpdatesAreThrottled) {
  std::ostringstream out;
  ProgressMeter meter(out, "mapping", 1000);
  for (size_t i = 0; i < 1000; ++i) meter.update(i);  // well within 100 ms
  EXPECT_EQ(out.str(), "");
}

TEST(SigintStopRequestTest, FirstSigintOnlyRaisesTheFlag) {
  SigintStopRequest stop;
  EXPECT_FALSE(stop.requested());
  std::raise(SIGINT);  // would end the test binary without the handler
  EXPECT_TRUE(stop.requested());
}

TEST(SigintStopRequestTest, SigtermIsHandledLikeSigint) {
  SigintStopRequest stop;
  std::raise(SIGTERM);  // what service managers and ROS send; would end the test binary too
  EXPECT_TRUE(stop.requested());
}

}  // namespace
}  // namespace stereonav
