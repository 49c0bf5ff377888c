// The RADIANCE converter against RADIANCE itself (docs/radiance-peer.md). Skipped unless
// RADIANCE's oconv and rtrace are on PATH (all but the RAYPATH test). room-s2 converted and traced
// must agree with the reference made outside the project (shared/validation/radiance/README.md)
// within RADIANCE's noise; rtrace's direct light from each kind of Radiant emitter must be
// Radiant's own.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "formfactor/luminaire_light.h"
#include "formfactor/point_polygon.h"
#include "photometric_files.h"
#include "radiance_export.h"
#include "radiance_run.h"
#include "reference_csv.h"
#include "scene/prepared_scene.h"
#include "scene_files.h"

namespace radiant {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

fs::path scratch_root() {
    return fs::temp_directory_path() / ("radiance_peer_test_" + std::to_string(::getpid()));
}

// Removes this process's scratch directory once every test has run.
class ScratchCleanup : public ::testing::Environment {
public:
    void TearDown() override { fs::remove_all(scratch_root()); }
};
const auto* const kCleanup = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

fs::path work_dir(const std::string& name) {
    const fs::path dir = scratch_root() / name;
    fs::remove_all(dir);
    return dir;
}

std::vector<double> reference_illuminance() {
    return testing::read_reference_csv(testing::data_path("radiance/room-s2.reference.csv"))
        .illuminance;
}

// The command line of the converter's README for a scene with emitting surfaces.
constexpr const char* kReadmeSettings = "-ab 8 -aa 0 -ad 2048 -lw 1e-4 -ds 0.02 -dj 1 -n 2";

TEST(RadiancePeer, RoomS2AgreesWithTheReferenceWithinRadiancesNoise) {
    const auto bin = radiance::find_radiance();
    if (!bin) GTEST_SKIP() << "RADIANCE (oconv, rtrace) is not on PATH";
    const Scene scene = testing::load_scene(testing::data_path("radiance/room-s2.json"));
    const fs::path dir = work_dir("room-s2");
    const auto written = radiance::write_radiance_scene(scene, dir);
    ASSERT_TRUE(written.ok) << written.error;
    ASSERT_EQ(radiance::make_octree(*bin, dir), "");
    const auto run = radiance::run_rtrace(*bin, dir, kReadmeSettings);
    ASSERT_TRUE(run.ok) << run.error;

    const std::vector<double> want = reference_illuminance();
    ASSERT_EQ(run.irradiance_lux.size(), want.size());
    double mean = 0, got_mean = 0, sq = 0;
    for (std::size_t i = 0; i < want.size(); ++i) {
        const double got = radiance::photometric(run.irradiance_lux[i]);
        mean += want[i];
        got_mean += got;
        sq += (got - want[i]) * (got - want[i]);
    }
    const double n = static_cast<double>(want.size());
    mean /= n;
    got_mean /= n;
    const double rms = std::sqrt(sq / n) / mean;
    // One run at these settings scatters by about 0.3 % per point (0.28 % measured; 0.21 %
    // without -ds 0.02 -dj 1, whose jitter adds noise to the direct light).
    EXPECT_LE(rms, 0.01) << "RMS " << 100 * rms << " % in " << run.seconds << " s";
    EXPECT_NEAR(got_mean / mean, 1.0, 0.005);
    RecordProperty("rms_percent", std::to_string(100 * rms));
    RecordProperty("seconds", std::to_string(run.seconds));
}

double table_intensity(double gamma_deg, double c_deg) {
    const double g = gamma_deg * kPi / 180, c = c_deg * kPi / 180;
    return 300 + 200 * std::cos(g) + 80 * std::sin(g) * std::cos(c) +
           40 * std::sin(g) * std::sin(2 * c);
}

// Black surfaces, so rtrace -ab 0 sees only direct light: a 1 m² panel facing down and three
// luminaires, two of them tilted (the photometric one also turned about its aim).
nlohmann::json direct_scene() {
    using nlohmann::json;
    const std::string ies = radiant::testing::ies_text(
        radiant::testing::angles(0, 180, 5), radiant::testing::angles(0, 360, 15), table_intensity);
    json up = json::array(), tilted = json::array();
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 5; ++j) {
            up.push_back({0.5 + 1.6 * i, 0.5 + 1.6 * j, 0.8});
            if ((i + j) % 2 == 0) tilted.push_back({0.5 + 1.6 * i, 0.5 + 1.6 * j, 1.2});
        }
    }
    return {{"format", "radiant-scene/1"},
            {"name", "direct"},
            {"materials",
             {{"black", {{"reflectance", 0.0}}},
              {"panel", {{"reflectance", 0.0}, {"emission", {{"exitance", 2000.0}}}}}}},
            {"surfaces",
             {{{"name", "floor"},
               {"material", "black"},
               {"polygon", {{0, 0, 0}, {8, 0, 0}, {8, 8, 0}, {0, 8, 0}}}},
              {{"name", "panel"},
               {"material", "panel"},
               {"polygon", {{3.5, 3.5, 3}, {3.5, 4.5, 3}, {4.5, 4.5, 3}, {4.5, 3.5, 3}}}}}},
            {"luminaires",
             {{{"name", "iso"}, {"position", {2, 2, 2.5}}, {"flux", 1500}},
              {{"name", "lamb"},
               {"position", {6, 2, 2.5}},
               {"flux", 2500},
               {"distribution", "lambertian"},
               {"aim", {0.3, 0.2, -1}}},
              {{"name", "table"},
               {"position", {4, 6, 2.5}},
               {"flux", 3000},
               {"distribution", {{"ies", ies}}},
               {"aim", {0.2, -0.3, -1}},
               {"rotation", 30}}}},
            {"sensors",
             {{{"name", "up"}, {"points", up}, {"normal", {0, 0, 1}}},
              {{"name", "tilted"}, {"points", tilted}, {"normal", {0.4, -0.3, 0.8}}}}}};
}

TEST(RadiancePeer, DirectLightOfEveryEmitterIsRadiantsOwn) {
    const auto bin = radiance::find_radiance();
    if (!bin) GTEST_SKIP() << "RADIANCE (oconv, rtrace) is not on PATH";
    auto parsed = proto::parse_scene(direct_scene().dump());
    ASSERT_TRUE(parsed.ok()) << parsed.problems.at(0).pointer << ": "
                             << parsed.problems.at(0).message;
    const fs::path dir = work_dir("direct");
    const auto written = radiance::write_radiance_scene(*parsed.scene, dir);
    ASSERT_TRUE(written.ok) << written.error;
    ASSERT_EQ(radiance::make_octree(*bin, dir), "");
    const auto run = radiance::run_rtrace(*bin, dir, "-ab 0 -ds 0.005 -dj 0 -dt 0 -dc 1");
    ASSERT_TRUE(run.ok) << run.error;

    // Radiant's unoccluded direct irradiance: Σ Φ·kernel over the luminaires, M·F to the panel.
    const PreparedScene prepared = prepare_scene(*parsed.scene);
    std::size_t line = 0;
    double worst = 0;
    for (const PreparedSensorSet& set : prepared.sensors) {
        for (const Vec3& x : set.points) {
            double want = 0;
            for (const PreparedLuminaire& l : prepared.luminaires) {
                want += l.flux_lm[0] * direct_kernel_per_lm(l, x, set.normal);
            }
            for (const Piece& p : prepared.pieces) {
                const PreparedMaterial& m =
                    prepared.materials[static_cast<std::size_t>(p.material)];
                if (m.emits()) {
                    want +=
                        m.exitance_lm_m2[0] * point_to_polygon_factor(x, set.normal, p.vertices);
                }
            }
            const double got = radiance::photometric(run.irradiance_lux.at(line++));
            EXPECT_NEAR(got, want, 0.003 * want) << set.name << " point " << line;
            worst = std::max(worst, std::abs(got / want - 1));
        }
    }
    RecordProperty("worst_relative", std::to_string(worst));
}

// A RAYPATH that misses rayinit.cal (one set by hand to a checkout's lib/, which a CMake build
// does not make) must not fail every run: the build's own lib comes after it.
TEST(RadiancePeer, RaypathFallsBackOnTheBuildsLib) {
    const fs::path build = work_dir("raypath") / "radiance-build";
    fs::create_directories(build / "bin");
    const char* saved = std::getenv("RAYPATH");
    const std::string before = saved ? saved : "";
    ::setenv("RAYPATH", ".:/nowhere/lib", 1);
    EXPECT_EQ(radiance::raypath_for(build / "bin"), ".:/nowhere/lib");
    fs::create_directories(build / "lib");
    std::ofstream(build / "lib" / "rayinit.cal") << "{ empty }\n";
    EXPECT_EQ(radiance::raypath_for(build / "bin"), ".:/nowhere/lib:" + (build / "lib").string());
    ::unsetenv("RAYPATH");
    EXPECT_EQ(radiance::raypath_for(build / "bin"), ".:" + (build / "lib").string());
    if (saved) ::setenv("RAYPATH", before.c_str(), 1);
}

}  // namespace
}  // namespace radiant
