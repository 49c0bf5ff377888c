// How radiant-bench scores a result against a reference of sensor values.
#include "reference_answer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

namespace radiant::bench {
namespace {

Result result_with(std::vector<double> maintained, std::optional<std::vector<double>> initial) {
    SensorResult set;
    set.name = "work plane";
    set.illuminance = std::move(maintained);
    if (initial) set.initial = InitialValues{*initial};
    Result r;
    r.sensors.push_back(std::move(set));
    return r;
}

// A reference made of several runs carries its standard error, which the benchmark counts as
// the reference's own error; one without it has none the benchmark knows of.
TEST(ReferenceAnswer, ReadsTheStandardErrorOfAReferenceCsv) {
    const auto dir = std::filesystem::temp_directory_path();
    const auto with = dir / "radiant-reference-with-error.csv";
    const auto without = dir / "radiant-reference-without-error.csv";
    std::ofstream(with) << "x,y,z,irradiance,standard_error\n"
                        << "0,0,0.8,100,1\n1,0,0.8,300,7\n";
    std::ofstream(without) << "x,y,z,irradiance\n0,0,0.8,100\n1,0,0.8,300\n";
    const ReferenceAnswer a = read_reference_csv(with, "RADIANCE", "work plane");
    EXPECT_EQ(a.illuminance, (std::vector<double>{100, 300}));
    EXPECT_DOUBLE_EQ(a.error_estimate, std::sqrt((1.0 + 49.0) / 2) / 200);
    EXPECT_EQ(a.sensor, "work plane");
    const ReferenceAnswer b = read_reference_csv(without, "RADIANCE", "work plane");
    EXPECT_EQ(b.illuminance, (std::vector<double>{100, 300}));
    EXPECT_EQ(b.error_estimate, 0);
    std::filesystem::remove(with);
    std::filesystem::remove(without);
}

// RADIANCE references are of new lamps: a maintained result (factor 0.8) is scored on its
// initial values, not as 20 % off.
TEST(ReferenceAnswer, ScoresTheLightOfNewLamps) {
    const ReferenceAnswer reference{"RADIANCE", nullptr, "work plane", {100, 300}};
    const RelativeError maintained =
        relative_error(result_with({80, 240}, {{100, 300}}), reference);
    EXPECT_DOUBLE_EQ(maintained.rms, 0);
    const RelativeError off = relative_error(result_with({102, 300}, std::nullopt), reference);
    EXPECT_DOUBLE_EQ(off.max, 2.0 / 200);
    EXPECT_DOUBLE_EQ(off.rms, std::sqrt(0.01 * 0.01 / 2));
}

// The result's estimate is its worst set's; a row scores one set, so it shows that set's.
TEST(ReferenceAnswer, ShowsTheEstimateOfTheSetItScores) {
    Result r = result_with({100, 300}, std::nullopt);
    r.stats.error_estimate = 0.025;  // a darker band's
    const ReferenceAnswer reference{"RADIANCE", nullptr, "work plane", {100, 300}};
    EXPECT_DOUBLE_EQ(scored_estimate(r, reference), 0.025);  // the set has none of its own
    r.sensors[0].error_estimate = 0.01;
    EXPECT_DOUBLE_EQ(scored_estimate(r, reference), 0.01);
    const ReferenceAnswer checks{"exact", nlohmann::json::array(), "", {}};
    EXPECT_DOUBLE_EQ(scored_estimate(r, checks), 0.025);
}

TEST(ReferenceAnswer, NothingToScoreWithoutTheSensorSet) {
    const ReferenceAnswer reference{"RADIANCE", nullptr, "desk", {100}};
    EXPECT_TRUE(std::isnan(relative_error(result_with({100}, std::nullopt), reference).rms));
}

}  // namespace
}  // namespace radiant::bench
