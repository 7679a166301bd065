// Tests for render/stats: percentile against hand-worked values (numpy's
// default linear method) and the RollingStats ring window.
#include "render/stats.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace planet {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(Percentile, HandWorkedValues) {
    const std::vector<double> v{1, 2, 3, 4};
    EXPECT_DOUBLE_EQ(percentile(v, 50), 2.5);   // rank 1.5
    EXPECT_DOUBLE_EQ(percentile(v, 95), 3.85);  // rank 2.85 → 3 + 0.85
    EXPECT_DOUBLE_EQ(percentile(v, 25), 1.75);  // rank 0.75
    EXPECT_DOUBLE_EQ(percentile(v, 0), 1.0);
    EXPECT_DOUBLE_EQ(percentile(v, 100), 4.0);
}

TEST(Percentile, SortsUnsortedInput) {
    const std::vector<double> v{40, 10, 30, 20, 50};
    EXPECT_DOUBLE_EQ(percentile(v, 0), 10.0);
    EXPECT_DOUBLE_EQ(percentile(v, 50), 30.0);
    EXPECT_DOUBLE_EQ(percentile(v, 90), 46.0);  // rank 3.6 → 40 + 0.6 * 10
    EXPECT_DOUBLE_EQ(percentile(v, 100), 50.0);
}

TEST(Percentile, SingleValueAndEmpty) {
    EXPECT_DOUBLE_EQ(percentile({7.0}, 0), 7.0);
    EXPECT_DOUBLE_EQ(percentile({7.0}, 99), 7.0);
    EXPECT_TRUE(std::isnan(percentile({}, 50)));
}

TEST(Percentile, SkipsNaN) {
    EXPECT_DOUBLE_EQ(percentile({kNaN, 3, 1, kNaN, 2}, 50), 2.0);
    EXPECT_TRUE(std::isnan(percentile({kNaN}, 50)));
}

TEST(Percentile, RejectsPOutsideRange) {
    EXPECT_THROW(percentile({1, 2}, -1), std::invalid_argument);
    EXPECT_THROW(percentile({1, 2}, 100.5), std::invalid_argument);
    EXPECT_THROW(percentile({1, 2}, kNaN), std::invalid_argument);
}

TEST(RollingStats, EmptyIsNaN) {
    RollingStats s(4);
    EXPECT_EQ(s.size(), 0u);
    EXPECT_TRUE(std::isnan(s.min()));
    EXPECT_TRUE(std::isnan(s.median()));
    EXPECT_TRUE(std::isnan(s.max()));
    EXPECT_TRUE(std::isnan(s.mean()));
    EXPECT_TRUE(std::isnan(s.last()));
    EXPECT_TRUE(s.history().empty());
}

TEST(RollingStats, BeforeWrapping) {
    RollingStats s(5);
    for (double v : {4.0, 1.0, 3.0}) s.push(v);
    EXPECT_EQ(s.size(), 3u);
    EXPECT_EQ(s.history(), (std::vector<double>{4, 1, 3}));
    EXPECT_DOUBLE_EQ(s.min(), 1.0);
    EXPECT_DOUBLE_EQ(s.median(), 3.0);
    EXPECT_DOUBLE_EQ(s.max(), 4.0);
    EXPECT_DOUBLE_EQ(s.mean(), 8.0 / 3.0);
    EXPECT_DOUBLE_EQ(s.last(), 3.0);
}

TEST(RollingStats, WrapsAround) {
    RollingStats s(3);
    for (double v = 1; v <= 5; ++v) s.push(v);
    EXPECT_EQ(s.size(), 3u);
    EXPECT_EQ(s.history(), (std::vector<double>{3, 4, 5}));
    EXPECT_DOUBLE_EQ(s.median(), 4.0);
    EXPECT_DOUBLE_EQ(s.min(), 3.0);
    EXPECT_DOUBLE_EQ(s.max(), 5.0);
    EXPECT_DOUBLE_EQ(s.mean(), 4.0);
    EXPECT_DOUBLE_EQ(s.last(), 5.0);
}

TEST(RollingStats, EvenCountMedianAveragesMiddlePair) {
    RollingStats s(4);
    for (double v : {10.0, 1.0, 7.0, 3.0}) s.push(v);
    EXPECT_DOUBLE_EQ(s.median(), 5.0);  // (3 + 7) / 2
    s.push(2.0);                        // window now {1, 7, 3, 2}
    EXPECT_DOUBLE_EQ(s.median(), 2.5);
    EXPECT_DOUBLE_EQ(s.max(), 7.0);
}

TEST(RollingStats, MatchesPercentileOverLongRun) {
    RollingStats s(7);
    std::vector<double> all;
    for (int i = 0; i < 50; ++i) {
        const double v = std::fmod(i * 37.0, 11.0);
        s.push(v);
        all.push_back(v);
    }
    const std::vector<double> window(all.end() - 7, all.end());
    EXPECT_EQ(s.history(), window);
    EXPECT_DOUBLE_EQ(s.median(), percentile(window, 50));
}

TEST(RollingStats, IgnoresNaNAndClears) {
    RollingStats s(3);
    s.push(1.0);
    s.push(kNaN);
    EXPECT_EQ(s.size(), 1u);
    EXPECT_DOUBLE_EQ(s.last(), 1.0);
    s.clear();
    EXPECT_EQ(s.size(), 0u);
    EXPECT_TRUE(std::isnan(s.median()));
    s.push(9.0);
    EXPECT_EQ(s.history(), (std::vector<double>{9}));
}

TEST(RollingStats, ZeroCapacityThrows) { EXPECT_THROW(RollingStats(0), std::invalid_argument); }

}  // namespace
}  // namespace planet
