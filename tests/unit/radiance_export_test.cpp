// The RADIANCE converter (tools/radiance) on a small scene, without RADIANCE: its materials,
// emitter and luminaire radiances, polygons, points file and photometric data, and the
// radiant-to-radiance command's exit codes.
#include "radiance_export.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "photometric_files.h"
#include "photometry/intensity_table.h"
#include "radiant/proto/scene_json.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;
using namespace radiant;
using radiance::ExportOptions;
using radiance::write_radiance_scene;
constexpr double kPi = std::numbers::pi;

// I(γ, C) with a C-dependence, so the data file's order of γ and C shows.
double table_intensity(double gamma_deg, double c_deg) {
    const double g = gamma_deg * kPi / 180, c = c_deg * kPi / 180;
    return 100 + 50 * std::cos(g) + 20 * std::sin(g) * std::cos(c);
}

// In centimetres: a one-sided RGB floor, a two-sided reflecting panel of exitance 179π lm/m²
// (RADIANCE radiance 1), a room box, and one luminaire of each distribution.
nlohmann::json small_scene() {
    using nlohmann::json;
    const auto square = [](double z, bool up) {
        json p = json::array({{0, 0, z}, {200, 0, z}, {200, 200, z}, {0, 200, z}});
        if (!up) std::reverse(p.begin(), p.end());
        return p;
    };
    const std::string ies =
        radiant::testing::ies_text(radiant::testing::angles(0, 180, 10),
                                   radiant::testing::angles(0, 360, 30), table_intensity);
    return {
        {"format", "radiant-scene/1"},
        {"name", "small room"},
        {"units", "cm"},
        {"materials",
         {{"floor", {{"reflectance", {0.2, 0.4, 0.6}}}},
          {"panel",
           {{"reflectance", 0.5}, {"two_sided", true}, {"emission", {{"exitance", 179 * kPi}}}}},
          {"wall", {{"reflectance", 0.5}}}}},
        {"surfaces",
         {{{"name", "floor"}, {"material", "floor"}, {"polygon", square(1, true)}},
          {{"name", "panel"}, {"material", "panel"}, {"polygon", square(250, false)}},
          {{"name", "room"},
           {"material", "wall"},
           {"box", {{"min", {-10, -10, 0}}, {"max", {210, 210, 300}}}}}}},
        {"luminaires",
         {{{"name", "iso"}, {"position", {50, 50, 200}}, {"flux", 1000}},
          {{"name", "lamb"},
           {"position", {150, 50, 200}},
           {"flux", 1000},
           {"distribution", "lambertian"},
           {"aim", {0, 0, -1}}},
          {{"name", "table"},
           {"position", {100, 150, 200}},
           {"flux", 2000},
           {"distribution", {{"ies", ies}}},
           {"aim", {0, 0, -1}}}}},
        {"sensors",
         {{{"name", "desk"}, {"points", {{50, 50, 80}, {150, 100, 80}}}, {"normal", {0, 0, 1}}},
          {{"name", "wall"}, {"points", {{0, 100, 150}}}, {"normal", {1, 0, 0}}}}}};
}

Scene parsed(const nlohmann::json& j) {
    auto outcome = proto::parse_scene(j.dump());
    EXPECT_TRUE(outcome.ok()) << (outcome.problems.empty() ? "" : outcome.problems[0].message);
    return *outcome.scene;
}

fs::path scratch_root() {
    return fs::temp_directory_path() / ("radiance_export_test_" + std::to_string(::getpid()));
}

// Removes this process's scratch directory once every test has run.
class ScratchCleanup : public ::testing::Environment {
public:
    void TearDown() override { fs::remove_all(scratch_root()); }
};
const auto* const kCleanup = ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

fs::path temp_dir(const std::string& name) {
    const fs::path dir = scratch_root() / name;
    fs::remove_all(dir);
    return dir;
}

// The three numbers after "void light ID\n0\n0\n3" (or the light modified by a pattern).
std::vector<double> light_radiance(const std::string& rad, const std::string& id) {
    const std::string head = " light " + id + "\n0\n0\n3 ";
    const auto at = rad.find(head);
    if (at == std::string::npos) return {};
    std::istringstream in(rad.substr(at + head.size()));
    std::vector<double> v(3);
    in >> v[0] >> v[1] >> v[2];
    return v;
}

std::vector<std::vector<double>> rows(const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::vector<double>> out;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::vector<double> row;
        for (double v; s >> v;) row.push_back(v);
        out.push_back(row);
    }
    return out;
}

TEST(RadianceExport, WritesMaterialsPolygonsLightsAndPoints) {
    const fs::path dir = temp_dir("small");
    const auto outcome = write_radiance_scene(parsed(small_scene()), dir);
    ASSERT_TRUE(outcome.ok) << outcome.error;
    const auto& s = outcome.summary;
    EXPECT_EQ(s.channels, 3);
    EXPECT_EQ(s.polygons, 10u);  // floor, panel (light, layer, back), the box's six faces
    // black; floor: plastic + mixfunc; wall: plastic; panel: light, plastic, mixfunc, back;
    // luminaires: 1 + 1 + 2 (pattern)
    EXPECT_EQ(s.materials, 12u);
    EXPECT_EQ(s.light_sources, 4u);
    EXPECT_EQ(s.area_sources, 1u);  // the panel; its shadow rays need -dj 1
    const std::string rad = test::read_text(dir / "scene.rad");

    // One-sided: the front plastic and the mix to black on the back.
    EXPECT_NE(rad.find("void plastic m0_floor_front\n0\n0\n5 0.2 0.4 0.6 0 0\n"), std::string::npos)
        << rad;
    EXPECT_NE(rad.find("void mixfunc m0_floor\n4 m0_floor_front radiant_black if(Rdot,1,0) ."),
              std::string::npos);
    EXPECT_NE(rad.find("void plastic radiant_black\n0\n0\n5 0 0 0 0 0\n"), std::string::npos);
    // The box faces in and everything is inside: no ray meets a back, so plain plastic.
    EXPECT_NE(rad.find("void plastic m2_wall\n0\n0\n5 0.5 0.5 0.5 0 0\n"), std::string::npos);

    // Exitance 179π lm/m² is radiance 1 in RADIANCE's unit, on each channel; the light behind
    // the reflecting layer (c = (1 + 0.5)/2) has 1/(1 − c) = 4, the layer's plastic ρ/c.
    const auto panel = light_radiance(rad, "m1_panel");
    ASSERT_EQ(panel.size(), 3u);
    for (const double v : panel) EXPECT_NEAR(v, 4.0, 1e-9);
    EXPECT_NE(rad.find("void plastic m1_panel_reflects\n0\n0\n5 0.6666666667"), std::string::npos);
    EXPECT_NE(rad.find("void mixfunc m1_panel_layer\n4 m1_panel_reflects void 0.75 .\n"),
              std::string::npos);
    // The layer 10 µm in front of the downward-facing panel at 2.5 m.
    const auto layer = rad.find("m1_panel_layer polygon s1_panel.0.layer\n0\n0\n12\n");
    ASSERT_NE(layer, std::string::npos);
    EXPECT_EQ(rad.substr(rad.find('\n', layer + 50) - 8, 8), " 2.49999");
    EXPECT_NE(rad.find("m1_panel_back polygon s1_panel.0.back\n"), std::string::npos);

    // Point luminaires: intensity / (π r² · 179) for the sphere, I0 / (π r² · 179) for the disk.
    const double projected = kPi * 0.01 * 0.01 * radiance::kLumensPerWatt;
    const auto iso = light_radiance(rad, "l0_iso_light");
    ASSERT_EQ(iso.size(), 3u);
    EXPECT_NEAR(iso[1], 1000 / (4 * kPi) / projected, 1e-6 * iso[1]);
    const auto lamb = light_radiance(rad, "l1_lamb_light");
    ASSERT_EQ(lamb.size(), 3u);
    EXPECT_NEAR(lamb[1], 1000 / kPi / projected, 1e-6 * lamb[1]);
    EXPECT_NE(rad.find("l1_lamb_light ring l1_lamb\n0\n0\n8 1.5 0.5 2 0 0 -1 0 0.01"),
              std::string::npos);
    EXPECT_NE(rad.find("l0_iso_light sphere l0_iso\n0\n0\n4 0.5 0.5 2 0.01"), std::string::npos);

    // Photometric: a pattern over the data file; the light scales the table to 2000 lm.
    EXPECT_NE(rad.find("void brightdata l2_table_table\n5 noop ./l2_table.dat ./radiant_lum.cal "
                       "radiant_gamma radiant_c\n0\n9 0 0 -1 "),
              std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "radiant_lum.cal"));
    const auto table = light_radiance(rad, "l2_table_light");
    ASSERT_EQ(table.size(), 3u);
    EXPECT_GT(table[0], 0);

    // Every polygon's vertices in metres, world frame: the box's corner at -10 cm.
    EXPECT_NE(rad.find("-0.1 -0.1 0\n"), std::string::npos);
    EXPECT_NE(rad.find("s1_panel.0\n0\n0\n12\n"), std::string::npos);

    // points.txt: every set in order, metres, with its normal.
    const auto points = rows(dir / "points.txt");
    ASSERT_EQ(points.size(), 3u);
    EXPECT_EQ(points[0], (std::vector<double>{0.5, 0.5, 0.8, 0, 0, 1}));
    EXPECT_EQ(points[2], (std::vector<double>{0, 1, 1.5, 1, 0, 0}));
    ASSERT_EQ(s.sensors.size(), 2u);
    EXPECT_EQ(s.sensors[1].name, "wall");
    EXPECT_EQ(s.sensors[1].first, 2u);
    EXPECT_EQ(s.points, 3u);

    // The reflecting panel needs every shadow ray tested.
    EXPECT_TRUE(s.needs_all_shadow_tests);
    EXPECT_NE(test::read_text(dir / "README")
                  .find("rtrace -I -h -ab 8 -aa 0 -ad 2048 -lw 1e-4 -dt 0 -ds 0.02 -dj 1"),
              std::string::npos);
}

TEST(RadianceExport, PhotometricDataFileHasGammaRowsAndCColumns) {
    const fs::path dir = temp_dir("table");
    ExportOptions options;
    options.photometric_step_deg = 10;
    ASSERT_TRUE(write_radiance_scene(parsed(small_scene()), dir, options).ok);
    const auto data = rows(dir / "l2_table.dat");
    // Dimensions, γ (every 2.5°: four times finer than C), C, then one row per γ.
    ASSERT_EQ(data.size(), 3u + 73u);
    EXPECT_EQ(data[1], (std::vector<double>{0, 180, 73}));
    EXPECT_EQ(data[2], (std::vector<double>{0, 360, 37}));
    // At the table's own angles the values are the table's: row γ = 90°, C = 0°, 90°, 180°.
    ASSERT_EQ(data[3 + 36].size(), 37u);
    EXPECT_NEAR(data[3 + 36][0], table_intensity(90, 0), 1e-6);
    EXPECT_NEAR(data[3 + 36][9], table_intensity(90, 90), 1e-6);
    EXPECT_NEAR(data[3 + 36][18], table_intensity(90, 180), 1e-6);
    EXPECT_NEAR(data[3][5], table_intensity(0, 0), 1e-6);
}

// A narrow spot alike in every C-plane: its file is over γ alone, fine enough that RADIANCE's
// linear interpolation reads its flank as the engine does.
TEST(RadianceExport, ASymmetricSpotIsAFineCurveOverGamma) {
    const auto spot = [](double gamma_deg, double) {
        return gamma_deg < 60 ? 1000 * std::pow(std::cos(gamma_deg * kPi / 180), 40) : 0.0;
    };
    nlohmann::json scene = small_scene();
    scene["luminaires"][2]["distribution"]["ies"] = radiant::testing::ies_text(
        radiant::testing::angles(0, 90, 2.5), radiant::testing::angles(0, 0, 1), spot);
    const fs::path dir = temp_dir("spot");
    ASSERT_TRUE(write_radiance_scene(parsed(scene), dir, ExportOptions{}).ok);
    EXPECT_NE(test::read_text(dir / "scene.rad")
                  .find("void brightdata l2_table_table\n4 noop ./l2_table.dat "
                        "./radiant_lum.cal radiant_gamma\n0\n9 0 0 -1 "),
              std::string::npos);
    const auto data = rows(dir / "l2_table.dat");
    ASSERT_EQ(data.size(), 2u + 3601u);  // dimensions, γ every 0.05°, one value per row
    EXPECT_EQ(data[1], (std::vector<double>{0, 180, 3601}));
    EXPECT_NEAR(data[2 + 200][0], spot(10, 0), 1e-6);  // a table angle: the table's value
    // Between two samples RADIANCE's straight line is within 0.01 % of the engine's curve in the
    // flank, where a 1° step read 0.5 % high at 20.5°.
    const Scene s = parsed(scene);
    const IntensityTable table =
        std::get<IntensityTable>(read_intensity_table(*s.luminaires[2].photometry));
    for (const int g : {200, 300, 400, 500}) {
        const double mid = 0.5 * (data[2 + g][0] + data[3 + g][0]);
        const double curve = table.candela((g + 0.5) * 0.05 * kPi / 180, 0);
        EXPECT_NEAR(mid, curve, 1e-4 * curve) << "at " << (g + 0.5) * 0.05 << "°";
    }
}

// A 2 m LED strip 5 cm wide is written as ten lengths of 20 cm (rtrace misjudges a long source
// taken whole), which together are the strip; the panel, 2 by 2, stays one polygon.
TEST(RadianceExport, ALongEmitterIsWrittenInLengthsOfFourWidths) {
    nlohmann::json scene = small_scene();
    scene["surfaces"].push_back(
        {{"name", "strip"},
         {"material", "panel"},
         {"polygon", {{0, 50, 240}, {0, 55, 240}, {200, 55, 240}, {200, 50, 240}}}});
    const fs::path dir = temp_dir("strip");
    const auto outcome = write_radiance_scene(parsed(scene), dir);
    ASSERT_TRUE(outcome.ok) << outcome.error;
    EXPECT_EQ(outcome.summary.area_sources, 11u);
    const std::string rad = test::read_text(dir / "scene.rad");
    double area = 0;
    int parts = 0;
    for (std::size_t at = rad.find("m1_panel polygon s"); at != std::string::npos;
         at = rad.find("m1_panel polygon s", at + 1)) {
        std::istringstream in(rad.substr(rad.find("\n0\n0\n", at) + 5));
        int count = 0;
        in >> count;
        std::vector<Vec3> v(static_cast<std::size_t>(count / 3));
        for (Vec3& p : v) in >> p.x >> p.y >> p.z;
        double length = 0;
        for (const Vec3& a : v) {
            for (const Vec3& b : v) length = std::max(length, std::sqrt(length_squared(b - a)));
        }
        double polygon_area = 0;
        for (std::size_t k = 1; k + 1 < v.size(); ++k)
            polygon_area += 0.5 * std::sqrt(length_squared(cross(v[k] - v[0], v[k + 1] - v[0])));
        if (polygon_area < 1) {  // the strip's parts, not the panel's 4 m²
            area += polygon_area;
            ++parts;
            EXPECT_LE(length, std::hypot(0.2, 0.05) + 1e-9);
        }
    }
    EXPECT_EQ(parts, 10);
    EXPECT_NEAR(area, 2 * 0.05, 1e-9);
}

TEST(RadianceExport, SurfaceSamplesCoverTheSurfaceArea) {
    const fs::path dir = temp_dir("samples");
    ExportOptions options;
    options.surface_samples = 100;
    options.sample_surfaces = {"floor", "room"};
    const auto outcome = write_radiance_scene(parsed(small_scene()), dir, options);
    ASSERT_TRUE(outcome.ok) << outcome.error;
    const auto& surfaces = outcome.summary.surfaces;
    ASSERT_EQ(surfaces.size(), 2u);
    double floor_area = 0;
    for (const double w : surfaces[0].weights_m2) floor_area += w;
    EXPECT_NEAR(floor_area, 4.0, 1e-9);
    EXPECT_GE(surfaces[0].weights_m2.size(), 50u);
    EXPECT_EQ(rows(dir / "surface-points.txt").size(), outcome.summary.surface_points);

    // A uniform irradiance averages to itself; radiosity is ρ·E per channel, then luminance.
    std::vector<Rgb> e(outcome.summary.surface_points, Rgb{10, 20, 30});
    const auto avg = radiance::surface_average(surfaces[0], e);
    EXPECT_NEAR(avg.irradiance_lux, radiance::photometric({10, 20, 30}), 1e-9);
    EXPECT_NEAR(avg.radiosity_lm_m2, radiance::photometric({2, 8, 18}), 1e-9);
}

TEST(RadianceExport, ReadsRtraceIrradianceInLux) {
    std::istringstream out("0.1 0.2 0.3\n1 1 1\nnot a number\n2 2 2\n");
    const auto e = radiance::irradiance_from_rtrace(out);
    ASSERT_EQ(e.size(), 2u);
    EXPECT_NEAR(e[0][0], 17.9, 1e-12);
    EXPECT_NEAR(e[0][2], 53.7, 1e-12);
    EXPECT_NEAR(radiance::photometric(e[1]), 179, 1e-9);
}

TEST(RadianceExport, RefusesADirectoryItCannotCreate) {
    const fs::path file = temp_dir("blocker");
    fs::create_directories(file.parent_path());
    std::ofstream(file) << "x";
    const auto outcome = write_radiance_scene(parsed(small_scene()), file / "sub");
    EXPECT_FALSE(outcome.ok);
    EXPECT_NE(outcome.error.find("cannot create"), std::string::npos);
}

int run(const std::string& args) {
    const std::string command =
        std::string(RADIANT_BIN_DIR) + "/radiant-to-radiance " + args + " > /dev/null 2> /dev/null";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(RadianceExport, CommandWritesTheRoomAndRefusesBadScenes) {
    const fs::path dir = temp_dir("room-s2");
    const std::string room = std::string(RADIANT_TEST_DATA) + "/radiance/room-s2.json";
    ASSERT_EQ(run("'" + room + "' --out '" + dir.string() + "'"), 0);
    EXPECT_EQ(rows(dir / "points.txt").size(), 81u);
    EXPECT_TRUE(fs::exists(dir / "scene.rad"));
    const std::string bad = std::string(RADIANT_TEST_DATA) + "/bad/unknown-material.json";
    EXPECT_EQ(run("'" + bad + "' --out '" + (dir / "bad").string() + "'"), 2);
    EXPECT_FALSE(fs::exists(dir / "bad"));
    EXPECT_EQ(run("'" + room + "'"), 2);  // --out is required
}

}  // namespace
