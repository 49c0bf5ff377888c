// room-s2 (a 4 × 4 × 3 m room with a flush 1000 lm ceiling panel) against the RADIANCE reference
// (shared/validation/radiance/README.md): 81 work-plane illuminances at default settings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "reference_csv.h"
#include "scene_files.h"

namespace radiant {
namespace {

using testing::data_path;

// The shared reference, or the -dj 1 one made in this project (0.2 % brighter; see
// tests/data/radiance/README.md).
std::vector<double> reference_illuminance(const char* file = "radiance/room-s2.reference.csv") {
    return testing::read_reference_csv(data_path(file)).illuminance;
}

// At a loose tolerance the dense mesh is the room's coarsest, so the discretisation check's
// coarser solve is the same mesh again: it must not read that as no error at all.
class CoarseDenseMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(CoarseDenseMesh, EstimateBoundsTheWorkPlaneError) {
    Scene scene = testing::load_scene(data_path("radiance/room-s2.json"));
    scene.settings.method = GetParam();
    scene.settings.tolerance = 0.3;
    // Scored as radiant-bench scores it: an estimate tight to 0.2 % cannot be judged against
    // a reference 0.2 % off.
    const std::vector<double> reference =
        reference_illuminance("radiance/room-s2.dj1-reference.csv");
    const Result result = solve(scene, options_from(scene.settings));
    ASSERT_EQ(result.status, SolveStatus::converged) << result.error;
    const auto* plane = testing::find_sensor(result, "workplane");
    ASSERT_NE(plane, nullptr);
    ASSERT_EQ(plane->illuminance.size(), reference.size());
    const double error = testing::normalised_rms(plane->illuminance, reference);
    EXPECT_GE(result.stats.error_estimate, error)
        << result.stats.patches << " patches, discretisation part "
        << result.stats.error_parts.discretisation;
    // And tightly (issue 27: at most 4× an error above 0.1 %); the largest difference over
    // surfaces and sensors, three times over, made it 19× the error.
    ASSERT_GT(error, 1e-3);
    EXPECT_LE(result.stats.error_estimate, 4 * error)
        << result.stats.patches << " patches, discretisation part "
        << result.stats.error_parts.discretisation;
    EXPECT_GT(result.stats.error_parts.discretisation, 0.0);
    EXPECT_TRUE(std::isfinite(result.stats.error_parts.residual));
}

INSTANTIATE_TEST_SUITE_P(Methods, CoarseDenseMesh,
                         ::testing::Values("direct", "gauss-seidel", "jacobi", "shooting"));

TEST(RadianceRoom, WorkPlaneWithinThreePercentNormalisedRms) {
    const Scene scene = testing::load_scene(data_path("radiance/room-s2.json"));
    const std::vector<double> reference = reference_illuminance();
    ASSERT_EQ(reference.size(), 81u);

    const Result result = solve(scene, options_from(scene.settings));
    ASSERT_EQ(result.status, SolveStatus::converged) << result.error;
    const auto* plane = testing::find_sensor(result, "workplane");
    ASSERT_NE(plane, nullptr);
    ASSERT_EQ(plane->illuminance.size(), reference.size());

    double sum_sq = 0, sum_ref = 0, max_rel = 0;
    std::size_t worst = 0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        const double got = plane->illuminance[i];
        ASSERT_TRUE(std::isfinite(got)) << "point " << i;
        sum_sq += (got - reference[i]) * (got - reference[i]);
        sum_ref += reference[i];
        const double rel = std::abs(got / reference[i] - 1.0);
        if (rel > max_rel) {
            max_rel = rel;
            worst = i;
        }
    }
    const double n = static_cast<double>(reference.size());
    const double nrms = std::sqrt(sum_sq / n) / (sum_ref / n);
    EXPECT_LE(nrms, 0.03) << "normalised RMS error " << nrms * 100 << " %; max relative error "
                          << max_rel * 100 << " % at point " << worst << " (got "
                          << plane->illuminance[worst] << " lx, reference " << reference[worst]
                          << " lx); " << result.stats.patches << " patches, "
                          << result.stats.seconds << " s";
    RecordProperty("nrms_percent", std::to_string(nrms * 100));
    RecordProperty("max_relative_percent", std::to_string(max_rel * 100));
}

}  // namespace
}  // namespace radiant
