// The One Euro filter (interaction/one_euro_filter.hpp) against the reference implementation's
// published data (tests/data/one_euro_filter: casiez/OneEuroFilter's groundTruth.csv, its first
// 300 rows): every output, not only the lag, on a number, on a point and on an orientation.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "interaction/one_euro_filter.hpp"
#include "test_paths.hpp"

namespace curvefold {
namespace {

// The parameters the reference made its data with.
constexpr OneEuroParameters kReferenceParameters{1.0, 0.1, 1.0};

struct ReferenceRow {
  double timestamp = 0.0, signal = 0.0, noisy = 0.0, filtered = 0.0;
};

// The rows of one of the reference's CSV files (tests/data/one_euro_filter), its header checked.
std::vector<std::vector<double>> readCsv(const std::string& name, const std::string& header) {
  std::ifstream in(std::string(CURVEFOLD_TEST_DATA) + "/one_euro_filter/" + name);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, header);
  const std::size_t columns = std::count(header.begin(), header.end(), ',') + 1;
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> values(columns);
    const char* at = line.data();
    const char* end = line.data() + line.size();
    for (double& value : values) {
      const auto [next, error] = std::from_chars(at, end, value);
      EXPECT_EQ(error, std::errc()) << line;
      at = next < end && *next == ',' ? next + 1 : next;
    }
    rows.push_back(std::move(values));
  }
  return rows;
}

std::vector<ReferenceRow> referenceRows() {
  std::vector<ReferenceRow> rows;
  for (const std::vector<double>& values :
       readCsv("ground_truth.csv", "timestamp,signal,noisy,filtered"))
    rows.push_back({values[0], values[1], values[2], values[3]});
  return rows;
}

// The reference filtered exact samples at exactly 120 Hz and printed six significant digits. So the
// clock here steps by exactly 1/120 s (the printed timestamps are that clock, rounded), and an
// output may differ by the rounding of the inputs (at most 5e-6 for those of 1 or more; the output
// is a weighted average of them, the weights summing to one) and of the output itself.
constexpr double kRate = 120.0;
constexpr double kPrinted = 1e-5;

double sampleTime(std::size_t row) {
  return static_cast<double>(row) / kRate;
}

TEST(OneEuroFilter, MatchesTheReferenceImplementationsPublishedOutputs) {
  const std::vector<ReferenceRow> rows = referenceRows();
  ASSERT_EQ(rows.size(), 300u);
  OneEuroFilter<double> filter(kReferenceParameters);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_NEAR(rows[i].timestamp, sampleTime(i), 5e-6);
    ASSERT_NEAR(filter.filter(rows[i].noisy, sampleTime(i)), rows[i].filtered, kPrinted)
        << "at t = " << rows[i].timestamp;
  }
}

// The published data has both cutoffs at 1 Hz; this is the reference run with a derivative cutoff
// of 3 Hz (tests/data/one_euro_filter/README.md), printed to full precision.
TEST(OneEuroFilter, MatchesTheReferenceWithADerivativeCutoffOfItsOwn) {
  const std::vector<std::vector<double>> rows =
      readCsv("derivative_cutoff_3.csv", "timestamp,noisy,filtered");
  ASSERT_EQ(rows.size(), 300u);
  OneEuroFilter<double> filter({1.0, 0.1, 3.0});
  for (const std::vector<double>& row : rows)
    ASSERT_NEAR(filter.filter(row[1], row[0]), row[2], 1e-12) << "at t = " << row[0];
}

TEST(OneEuroFilter, FiltersAPointAsTheReferenceDoesANumber) {
  // The signal along one direction: the speed is the vector's length, so the point moves along
  // that direction exactly as the number does.
  const glm::dvec3 along = glm::dvec3(1.0, 2.0, 2.0) / 3.0, origin(0.3, -1.2, 0.5);
  OneEuroFilter<glm::dvec3> filter(kReferenceParameters);
  const std::vector<ReferenceRow> rows = referenceRows();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const glm::dvec3 out = filter.filter(origin + rows[i].noisy * along, sampleTime(i));
    ASSERT_NEAR(glm::dot(out - origin, along), rows[i].filtered, kPrinted)
        << "at t = " << rows[i].timestamp;
    ASSERT_NEAR(glm::length(glm::cross(out - origin, along)), 0.0, 1e-12);
  }
}

TEST(OneEuroFilter, TurnsAnOrientationAsItFiltersItsAngle) {
  // While the reference's clean signal rises, a turn by that angle (radians) about one axis is
  // filtered as the angle is: the same speed (the angular velocity, along the axis) and the same
  // share of the way, by slerp. Every other sample comes with its sign flipped, as a
  // tracker may give it: q and -q are one orientation, so the filter turns just the same.
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.2, 1.0, -0.4));
  OneEuroFilter<double> angleFilter(kReferenceParameters);
  OneEuroFilter<glm::dquat> turnFilter(kReferenceParameters);
  const std::vector<ReferenceRow> rows = referenceRows();
  std::size_t compared = 0;
  for (std::size_t i = 0; i < rows.size() && (i == 0 || rows[i].signal > rows[i - 1].signal); ++i) {
    const glm::dquat expected =
        glm::angleAxis(angleFilter.filter(rows[i].signal, sampleTime(i)), axis);
    const glm::dquat sample = glm::angleAxis(rows[i].signal, axis);
    const glm::dquat turn = turnFilter.filter(i % 2 == 1 ? -sample : sample, sampleTime(i));
    const double sign = glm::dot(turn, expected) < 0.0 ? -1.0 : 1.0;
    for (int c = 0; c < 4; ++c)
      ASSERT_NEAR(sign * turn[c], expected[c], 1e-9) << "at t = " << rows[i].timestamp;
    ++compared;
  }
  EXPECT_GT(compared, 100u);
}

TEST(OneEuroFilter, JitterAtRestAveragesOutAsAPointsDoes) {
  // A hand held still: its orientation jitters by small turns about random axes. The filter's
  // speed estimate must average that jitter out as it does a point's (turns one way and back
  // cancel), so with a large beta the cutoff stays near its minimum and the jitter is smoothed
  // as much as the same jitter on a point. Filtering the angle alone (never negative) would add
  // the jitter up into a speed, raise the cutoff at rest and let the jitter through.
  const OneEuroParameters handParameters{1.0, 10.0, 1.0};
  OneEuroFilter<glm::dquat> turnFilter(handParameters);
  OneEuroFilter<glm::dvec3> pointFilter(handParameters);
  const glm::dquat rest = glm::angleAxis(0.7, glm::normalize(glm::dvec3(1.0, 2.0, -0.5)));
  std::mt19937_64 random(7);
  std::normal_distribution<double> jitter(0.0, 0.004);  // radians per axis
  double turnSquares = 0.0, pointSquares = 0.0, sampleSquares = 0.0;
  constexpr int kSamples = 600;
  for (int i = 0; i < kSamples; ++i) {
    const glm::dvec3 turn(jitter(random), jitter(random), jitter(random));
    const double angle = glm::length(turn);
    const glm::dquat sample = glm::angleAxis(angle, turn / angle) * rest;
    const glm::dquat turned = turnFilter.filter(sample, i / kRate);
    const glm::dvec3 moved = pointFilter.filter(turn, i / kRate);
    if (i < kSamples / 3) continue;  // the filters settle first
    const double off = 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(turned, rest))));
    turnSquares += off * off;
    pointSquares += glm::dot(moved, moved);
    sampleSquares += angle * angle;
  }
  EXPECT_LT(pointSquares, 0.25 * sampleSquares);  // the point's jitter is smoothed
  EXPECT_NEAR(std::sqrt(turnSquares / pointSquares), 1.0, 0.15);
}

TEST(OneEuroFilter, FirstSamplePassesAndARepeatedInstantChangesNothing) {
  OneEuroFilter<double> filter(kReferenceParameters), twin(kReferenceParameters);
  EXPECT_EQ(filter.filter(3.0, 1.0), 3.0);
  twin.filter(3.0, 1.0);
  const double moved = filter.filter(4.0, 1.01);
  EXPECT_EQ(twin.filter(4.0, 1.01), moved);
  EXPECT_EQ(filter.filter(100.0, 1.01), moved);  // the same instant: the last output back
  EXPECT_EQ(filter.filter(5.0, 1.02), twin.filter(5.0, 1.02));
  filter.reset();
  EXPECT_EQ(filter.filter(-2.0, 1.03), -2.0);
}

}  // namespace
}  // namespace curvefold
