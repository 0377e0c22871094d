// Tonehole placement: the CSV reader accepts comments, blank lines, spaces and CRLF, and rejects
// every malformed input with "origin:line: what"; the statistics per hole are the mean, the
// sample SD (n - 1), range, subject count and depth = mean - SD (not below 0; the mean alone
// for a single measurement), checked against values worked by hand; the least-variation hole is
// the smallest SD among holes with n >= 2, the smaller hole on a tie; the shipped synthetic
// example is labelled SYNTHETIC and loads.
#include "tactus/placement/placement.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "tactus/placement/measurements.hpp"

namespace tactus {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

std::vector<Measurement> parse(const std::string& text) {
    std::istringstream in(text);
    return parse_measurements(in, "m.csv");
}

std::string error_of(const std::string& text) {
    try {
        parse(text);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(no error)";
}

const std::string kHeader = "subject,finger,hole_mm,extension_mm\n";

TEST(Measurements, ReadsRowsCommentsBlankLinesSpacesAndCrlf) {
    const auto rows = parse(
        "# synthetic\n\n subject , finger,hole_mm,extension_mm\r\n"
        "a,index,6,0.8\r\n  # a note\n b , ring , 7.5 , 1.2 \n\n");
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].subject, "a");
    EXPECT_EQ(rows[0].finger, "index");
    EXPECT_EQ(rows[0].hole_mm, 6.0);
    EXPECT_EQ(rows[0].extension_mm, 0.8);
    EXPECT_EQ(rows[0].line, 4);
    EXPECT_EQ(rows[1].subject, "b");
    EXPECT_EQ(rows[1].finger, "ring");
    EXPECT_EQ(rows[1].hole_mm, 7.5);
    EXPECT_EQ(rows[1].line, 6);
}

TEST(Measurements, ErrorsNameTheLineAndTheProblem) {
    struct Case {
        std::string text, starts, says;
    };
    const Case cases[] = {
        {"hole,extension\n", "m.csv:1:", "expected the header"},
        {"# only a comment\n" + kHeader + "a,index,6\n", "m.csv:3:", "expected 4 fields"},
        {kHeader + "a,index,6,0.8,9\n", "m.csv:2:", "got 5"},
        {kHeader + "a,index,six,0.8\n", "m.csv:2:", "hole_mm 'six' is not a number"},
        {kHeader + "a,index,6,0.8mm\n", "m.csv:2:", "extension_mm '0.8mm' is not a number"},
        {kHeader + "a,index,6,\n", "m.csv:2:", "extension_mm '' is not a number"},
        {kHeader + "a,index,6,nan\n", "m.csv:2:", "is not a number"},
        {kHeader + "a,index,0,0.8\n", "m.csv:2:", "hole_mm 0 must be > 0"},
        {kHeader + "a,index,6,-0.2\n", "m.csv:2:", "extension_mm -0.2 must be >= 0"},
        {kHeader + ",index,6,0.2\n", "m.csv:2:", "subject is empty"},
        {kHeader + "a,,6,0.2\n", "m.csv:2:", "finger is empty"},
        {kHeader + "a,index,6,0.2\n\na,index,6.0,0.4\n",
         "m.csv:4:", "subject a finger index hole 6 mm was already measured on line 2"},
    };
    for (const Case& c : cases) {
        const std::string m = error_of(c.text);
        EXPECT_THAT(m, StartsWith(c.starts)) << c.text;
        EXPECT_THAT(m, HasSubstr(c.says)) << c.text;
        EXPECT_EQ(m.find('\n'), std::string::npos) << "one line: " << m;
    }
    EXPECT_EQ(error_of(""), "m.csv: no header line '" + std::string(kMeasurementHeader) +
                                "' and no measurements");
    EXPECT_EQ(error_of("# nothing\n" + kHeader), "m.csv: no measurements");
}

TEST(Measurements, MissingFileIsNamed) {
    try {
        read_measurements("/no/such/dir/m.csv");
        ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_THAT(e.what(), HasSubstr("/no/such/dir/m.csv"));
    }
}

// Hole 6: 0.6, 0.8, 1.0 -> mean 0.8, SD 0.2, depth 0.6. Hole 8: 1.0, 1.4, 1.4, 2.2 -> mean 1.5,
// SD sqrt(0.76 / 3), depth 1.5 - 0.5033. Hole 10: 2.0 alone -> SD undefined, depth 2.0.
TEST(Placement, StatisticsWorkedByHand) {
    const auto rows = parse(kHeader +
                            "s1,index,6,0.6\ns1,middle,6,0.8\ns2,index,6,1.0\n"
                            "s1,index,8,1.0\ns1,middle,8,1.4\ns2,index,8,1.4\ns3,ring,8,2.2\n"
                            "s1,index,10,2.0\n");
    const PlacementReport r = summarise_placement(rows);
    ASSERT_EQ(r.holes.size(), 3u);
    const HoleSummary &six = r.holes[0], &eight = r.holes[1], &ten = r.holes[2];
    EXPECT_EQ(six.hole_mm, 6.0);
    EXPECT_EQ(six.n, 3);
    EXPECT_EQ(six.subjects, 2);
    EXPECT_NEAR(six.mean_mm, 0.8, 1e-12);
    EXPECT_NEAR(six.sd_mm, 0.2, 1e-12);
    EXPECT_NEAR(six.depth_mm, 0.6, 1e-12);
    EXPECT_EQ(six.min_mm, 0.6);
    EXPECT_EQ(six.max_mm, 1.0);
    EXPECT_EQ(eight.n, 4);
    EXPECT_EQ(eight.subjects, 3);
    EXPECT_NEAR(eight.mean_mm, 1.5, 1e-12);
    EXPECT_NEAR(eight.sd_mm, std::sqrt(0.76 / 3), 1e-12);
    EXPECT_NEAR(eight.depth_mm, 1.5 - std::sqrt(0.76 / 3), 1e-12);
    EXPECT_EQ(ten.n, 1);
    EXPECT_TRUE(std::isnan(ten.sd_mm));
    EXPECT_EQ(ten.depth_mm, 2.0);
    ASSERT_TRUE(r.least_variation.has_value());
    EXPECT_EQ(*r.least_variation, 0u);  // 0.2 < 0.503; the single 10 mm value does not count
}

TEST(Placement, DepthNeverAboveTheSurfaceAndTiesGoToTheSmallerHole) {
    const auto rows = parse(kHeader + "a,i,9,0\na,m,9,1.0\na,i,7,0\na,m,7,1.0\n");
    const PlacementReport r = summarise_placement(rows);
    ASSERT_EQ(r.holes.size(), 2u);
    EXPECT_EQ(r.holes[0].hole_mm, 7.0);
    EXPECT_EQ(r.holes[0].depth_mm, 0.0);  // mean 0.5 - SD 0.707 < 0
    EXPECT_EQ(*r.least_variation, 0u);
    EXPECT_FALSE(summarise_placement(parse(kHeader + "a,i,6,1\na,i,7,2\n")).least_variation);
}

TEST(Placement, ShippedSyntheticExample) {
    const std::filesystem::path path =
        std::filesystem::path(TACTUS_SOURCE_DIR) / "examples" / "placement_synthetic.csv";
    std::ifstream in(path);
    std::string first;
    std::getline(in, first);
    EXPECT_THAT(first, StartsWith("# SYNTHETIC DATA"));
    const auto rows = read_measurements(path);
    EXPECT_EQ(rows.size(), 45u);  // 3 subjects x 3 fingers x 5 holes
    const PlacementReport r = summarise_placement(rows);
    ASSERT_EQ(r.holes.size(), 5u);
    for (const HoleSummary& h : r.holes) EXPECT_EQ(h.n, 9) << h.hole_mm;
    EXPECT_LT(r.holes.front().sd_mm, r.holes.back().sd_mm);  // spread grows with hole size
    EXPECT_EQ(r.holes[*r.least_variation].hole_mm, 6.0);
}

}  // namespace
}  // namespace tactus
