// The path-traced reference against an exact answer, and what it refuses.
#include "path_reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "reference_csv_file.h"
#include "scene_files.h"

namespace radiant::bench {
namespace {

std::filesystem::path temp_csv(const std::string& name) {
    return std::filesystem::temp_directory_path() / ("radiant-path-reference-" + name + ".csv");
}

// In a closed box whose every surface emits 1 and reflects ρ, the light is the same everywhere
// and in every direction: any point facing any way receives 1 / (1 − ρ), 10 at ρ 0.9, of which
// nine tenths come after one bounce or more (most after more than two, where the paths go on
// by Russian roulette).
TEST(PathReference, ReadsAFurnaceAsItsExactIrradiance) {
    Scene scene = testing::load_scene(testing::data_path("scenes/furnace-rho0.9.json"));
    SensorSet set;
    set.name = "inside";
    set.points = {{0.5, 0.5, 0.5}, {0.1, 0.2, 0.05}, {0.9, 0.9, 0.9}, {0.02, 0.5, 0.98}};
    set.normal = {0, 0.6, 0.8};
    scene.sensors.push_back(set);
    const auto csv = temp_csv("furnace");
    PathReferenceOptions options;
    options.relative_error = 0.005;
    std::ostringstream out, log;
    ASSERT_TRUE(write_path_reference(scene, csv, options, out, log)) << log.str();
    const testing::ReferenceCsv file = testing::read_reference_csv_file(csv);
    ASSERT_EQ(file.header, testing::kReferenceCsvHeaderWithError);
    ASSERT_EQ(file.illuminance.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_NEAR(file.points[i][0], set.points[i][0], 1e-6);
        EXPECT_LE(file.standard_error[i], 0.005 * 10 * 2);
        EXPECT_GT(file.standard_error[i], 0);
        // Four standard errors: one point in 16 000 lies further by chance.
        EXPECT_NEAR(file.illuminance[i], 10.0, 4 * file.standard_error[i]) << i;
    }
    EXPECT_NE(out.str().find("standard error: RMS"), std::string::npos) << out.str();
    std::filesystem::remove(csv);
}

// A cylinder's illuminance averages receiver normals; the tracer follows one normal.
TEST(PathReference, RefusesACylindricalSensorSet) {
    Scene scene = testing::load_scene(testing::data_path("scenes/furnace-rho0.9.json"));
    SensorSet set;
    set.name = "cylinder";
    set.points = {{0.5, 0.5, 0.5}};
    set.kind = SensorKind::cylindrical;
    scene.sensors.push_back(set);
    std::ostringstream out, log;
    EXPECT_FALSE(write_path_reference(scene, temp_csv("cylinder"), {}, out, log));
    EXPECT_NE(log.str().find("cylindrical"), std::string::npos) << log.str();
    scene.sensors.clear();
    EXPECT_FALSE(write_path_reference(scene, temp_csv("none"), {}, out, log));
    EXPECT_NE(log.str().find("no sensor set"), std::string::npos) << log.str();
}

}  // namespace
}  // namespace radiant::bench
