#include "framework/core/stats.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "framework/core/error.h"

namespace lpvlab {
namespace {

// Expected values follow numpy: np.percentile(x, [25, 50, 75]) (linear interpolation).
TEST(Summarize, OddCount) {
  const Summary s = summarize({5, 1, 4, 2, 3});
  EXPECT_EQ(s.count, 5);
  EXPECT_DOUBLE_EQ(s.min, 1);
  EXPECT_DOUBLE_EQ(s.max, 5);
  EXPECT_DOUBLE_EQ(s.median, 3);
  EXPECT_DOUBLE_EQ(s.q1, 2);
  EXPECT_DOUBLE_EQ(s.q3, 4);
  EXPECT_DOUBLE_EQ(s.mad, 1);  // deviations 2,1,0,1,2 -> median 1
}

TEST(Summarize, EvenCount) {
  const Summary s = summarize({4, 1, 3, 2});
  EXPECT_EQ(s.count, 4);
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.q1, 1.75);
  EXPECT_DOUBLE_EQ(s.q3, 3.25);
  EXPECT_DOUBLE_EQ(s.mad, 1);  // deviations 1.5,0.5,0.5,1.5 -> median 1
}

TEST(Summarize, MadIgnoresOutlier) {
  const Summary s = summarize({10, 11, 12, 13, 1000});
  EXPECT_DOUBLE_EQ(s.median, 12);
  EXPECT_DOUBLE_EQ(s.mad, 1);  // deviations 2,1,0,1,988 -> median 1
  EXPECT_DOUBLE_EQ(s.max, 1000);
}

TEST(Summarize, SingleSample) {
  const Summary s = summarize({7.5});
  EXPECT_EQ(s.count, 1);
  EXPECT_DOUBLE_EQ(s.median, 7.5);
  EXPECT_DOUBLE_EQ(s.min, 7.5);
  EXPECT_DOUBLE_EQ(s.max, 7.5);
  EXPECT_DOUBLE_EQ(s.q1, 7.5);
  EXPECT_DOUBLE_EQ(s.q3, 7.5);
  EXPECT_DOUBLE_EQ(s.mad, 0);
}

TEST(Summarize, EmptyIsAnError) { EXPECT_THROW(summarize({}), Error); }

TEST(Summarize, NaNIsAnErrorNamingIt) {
  try {
    summarize({1.0, std::nan(""), 3.0});
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("NaN"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("sample 1"), std::string::npos) << e.what();
  }
}

TEST(Summarize, InfinityIsAnError) {
  EXPECT_THROW(summarize({1.0, std::numeric_limits<double>::infinity()}), Error);
}

TEST(Summarize, JsonHasEveryField) {
  const nlohmann::json j = summarize({1, 2, 3, 4}).toJson();
  EXPECT_EQ(j.at("count"), 4);
  EXPECT_DOUBLE_EQ(j.at("median").get<double>(), 2.5);
  EXPECT_DOUBLE_EQ(j.at("min").get<double>(), 1);
  EXPECT_DOUBLE_EQ(j.at("max").get<double>(), 4);
  EXPECT_DOUBLE_EQ(j.at("q1").get<double>(), 1.75);
  EXPECT_DOUBLE_EQ(j.at("q3").get<double>(), 3.25);
  EXPECT_DOUBLE_EQ(j.at("mad").get<double>(), 1);
  EXPECT_EQ(j.size(), 7u);
}

}  // namespace
}  // namespace lpvlab
