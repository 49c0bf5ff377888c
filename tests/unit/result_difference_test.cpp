// relative_rms_difference and surface_rms_difference: the measures behind the discretisation
// and completion parts of the error estimate.
#include <gtest/gtest.h>

#include <cmath>

#include "solution/result_difference.h"

namespace radiant {
namespace {

Result two_surfaces(double bright, double dark) {
    Result r;
    r.surfaces.push_back({"bright", 1.0, bright, 0.5 * bright});
    r.surfaces.push_back({"dark", 1.0, dark, 0.5 * dark});
    return r;
}

TEST(RelativeRmsDifference, DarkSurfacesAreMeasuredAgainstATenthOfTheMean) {
    // Mean irradiance (100 + 0.001) / 2, mean radiosity half that; the dark surface's change
    // counts against a tenth of each, not against its own 0.001 lux.
    const double d = 0.001 / (0.1 * 100.001 / 2);
    EXPECT_NEAR(relative_rms_difference(two_surfaces(100, 0.001), two_surfaces(100, 0.002)),
                std::sqrt(2 * d * d / 4), 1e-12);
}

TEST(RelativeRmsDifference, SurfacesUnderOnePercentOfTheAreaDoNotCount) {
    Result a = two_surfaces(100, 100), b = a;
    a.surfaces.push_back({"chair leg", 0.01, 100, 50});
    b.surfaces.push_back({"chair leg", 0.01, 150, 75});
    EXPECT_EQ(relative_rms_difference(a, b), 0.0);
    a.surfaces.back().area_m2 = b.surfaces.back().area_m2 = 0.1;
    EXPECT_NEAR(relative_rms_difference(a, b), std::sqrt(2 * 0.25 / 6), 1e-12);
}

TEST(RelativeRmsDifference, SensorsCountAsEachSetsRmsOverItsMean) {
    Result a = two_surfaces(100, 100), b = two_surfaces(200, 200);
    SensorResult desk;
    desk.illuminance = {200, 400};
    a.sensors.push_back(desk);
    desk.illuminance = {200, 412};
    b.sensors.push_back(desk);
    // √((0² + 12²) / 2) / 300; the surfaces' 100 % do not count where there are sensors.
    EXPECT_NEAR(relative_rms_difference(a, b), std::sqrt(72.0) / 300, 1e-12);
    SensorResult wall;
    wall.illuminance = {100, 100};
    a.sensors.push_back(wall);
    wall.illuminance = {90, 110};
    b.sensors.push_back(wall);
    EXPECT_NEAR(relative_rms_difference(a, b), 0.1, 1e-12);  // the larger set's
}

TEST(RelativeRmsDifference, DarkSensorSetsCountAgainstATenthOfTheMean) {
    Result a, b;
    SensorResult lit, dark;
    lit.illuminance = {100, 100, 100};
    dark.illuminance = {0.001};
    a.sensors = {lit, dark};
    dark.illuminance = {0.002};
    b.sensors = {lit, dark};
    EXPECT_NEAR(relative_rms_difference(a, b), 0.001 / (0.1 * 300.001 / 4), 1e-12);
}

TEST(RelativeRmsDifference, WithoutSensorsSurfacesCountByTheirRelativeDifferences) {
    // 2 % and 4 %, irradiance and radiosity alike; the 1 % chair leg does not count.
    Result a = two_surfaces(100, 50), b = two_surfaces(102, 52);
    a.surfaces.push_back({"chair leg", 0.01, 100, 50});
    b.surfaces.push_back({"chair leg", 0.01, 150, 75});
    EXPECT_NEAR(relative_rms_difference(a, b), std::sqrt((2 * 0.0004 + 2 * 0.0016) / 4), 1e-12);
    EXPECT_EQ(relative_rms_difference(a, a), 0.0);
}

TEST(SurfaceRmsDifference, CountsTheSurfacesWhereThereAreSensorsToo) {
    Result a = two_surfaces(100, 50), b = two_surfaces(102, 52);
    SensorResult desk;
    desk.illuminance = {200, 400};
    a.sensors.push_back(desk);
    b.sensors.push_back(desk);
    EXPECT_EQ(relative_rms_difference(a, b), 0.0);  // the sensors agree
    EXPECT_NEAR(surface_rms_difference(a, b), std::sqrt((2 * 0.0004 + 2 * 0.0016) / 4), 1e-12);
}

}  // namespace
}  // namespace radiant
