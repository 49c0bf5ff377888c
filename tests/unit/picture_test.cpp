// `radiant render` and `radiant plan` on a room lit by one downlight in the middle of the
// ceiling: the PNGs are decoded and checked for what they claim to show — the brightest spot
// under the lamp, the room's symmetry, the legend.
#include <gtest/gtest.h>
#include <stb_image.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;

struct Picture {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;

    const unsigned char* at(int x, int y) const {
        return &rgb[3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                         static_cast<std::size_t>(x))];
    }
    double grey(int x, int y) const {
        const unsigned char* p = at(x, y);
        return (p[0] + p[1] + p[2]) / 3.0;
    }
};

/// Hue in degrees (0 red … 240 blue): the false-colour ramp runs from blue to red, so a smaller
/// hue means more lux.
double hue(const unsigned char* p) {
    const double r = p[0], g = p[1], b = p[2];
    const double hi = std::max({r, g, b}), lo = std::min({r, g, b});
    if (hi - lo < 1) return -1;
    double h = hi == r   ? std::fmod((g - b) / (hi - lo), 6.0)
               : hi == g ? (b - r) / (hi - lo) + 2
                         : (r - g) / (hi - lo) + 4;
    h *= 60;
    return h < 0 ? h + 360 : h;
}

/// sRGB-encoded grey level → linear luminance relative to white.
double linear(double grey) {
    const double v = grey / 255;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

bool saturated(const unsigned char* p) {
    return std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) > 40;
}

class Pictures : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("radiant_picture_test_" + std::to_string(getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    /// Runs the CLI writing `name` and decodes it; fails the test when the CLI did.
    Picture make(const std::string& command, const std::string& name) {
        const fs::path png = dir_ / name;
        const radiant::test::CliRun r =
            radiant::test::run_cli(command + " '" + scene_ + "' --out '" + png.string() + "'");
        EXPECT_EQ(r.exit_code, 0) << r.err;
        const std::string bytes = radiant::test::read_text(png);
        Picture picture;
        int channels = 0;
        std::unique_ptr<unsigned char, decltype(&stbi_image_free)> data(
            stbi_load_from_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                                  static_cast<int>(bytes.size()), &picture.width, &picture.height,
                                  &channels, 3),
            &stbi_image_free);
        EXPECT_TRUE(data) << "not a PNG: " << png;
        if (data) {
            picture.rgb.assign(data.get(), data.get() + 3 * picture.width * picture.height);
        }
        return picture;
    }

    std::string scene_ = std::string(RADIANT_TEST_DATA) + "/pictures/lamp-room.json";
    fs::path dir_;
};

// Looking straight down from just below the lamp: the floor fills the view.
const std::string kDownView =
    "render --eye 2 2 2.4 --target 2 2 0 --up 0 1 0 --fov 60 --width 201 --height 151";

TEST_F(Pictures, LuminanceViewIsBrightestUnderTheLampAndSymmetric) {
    const Picture p = make(kDownView, "down.png");
    ASSERT_EQ(p.width, 201);
    ASSERT_EQ(p.height, 151);
    int best_x = 0, best_y = 0;
    double mirror_difference = 0;
    for (int y = 0; y < p.height; ++y) {
        for (int x = 0; x < p.width; ++x) {
            if (p.grey(x, y) > p.grey(best_x, best_y)) best_x = x, best_y = y;
            mirror_difference += std::abs(p.grey(x, y) - p.grey(p.width - 1 - x, y)) +
                                 std::abs(p.grey(x, y) - p.grey(x, p.height - 1 - y));
        }
    }
    EXPECT_NEAR(best_x, 100, 12);
    EXPECT_NEAR(best_y, 75, 12);
    EXPECT_LT(mirror_difference / (2.0 * p.width * p.height), 2.0);  // grey levels
    // Light falls off towards the edges of the view: the downlight's direct part as cos⁴ (0.66
    // at the top edge, 1.39 m off-centre), diluted by the nearly even reflected light.
    const double edge_ratio = linear(p.grey(100, 0)) / linear(p.grey(100, 75));
    EXPECT_GT(edge_ratio, 0.6);
    EXPECT_LT(edge_ratio, 0.9);
}

TEST_F(Pictures, FalseColourViewHasLegendAndHottestColourUnderTheLamp) {
    const Picture p = make(kDownView + " --falsecolor", "false.png");
    ASSERT_GT(p.width, 201);  // the legend sits to the right of the view
    ASSERT_EQ(p.height, 151);
    EXPECT_LT(hue(p.at(100, 75)), hue(p.at(3, 3)));
    EXPECT_LT(hue(p.at(100, 75)), hue(p.at(197, 147)));
    int red = 0, blue = 0;
    for (int y = 0; y < p.height; ++y) {
        for (int x = 201; x < p.width; ++x) {
            if (!saturated(p.at(x, y))) continue;
            const double h = hue(p.at(x, y));
            red += h < 20 || h > 340;
            blue += h > 200 && h < 280;
        }
    }
    EXPECT_GT(red, 20);   // the top of the legend bar
    EXPECT_GT(blue, 20);  // its bottom
}

TEST_F(Pictures, PlanMapsTheGridSymmetricallyWithTheHottestCellsInTheMiddle) {
    const Picture p = make("plan --size 400", "plan.png");
    // The map is the first run of columns holding false colours; the legend comes after a gap.
    const auto coloured_column = [&](int x) {
        for (int y = 0; y < p.height; ++y) {
            if (saturated(p.at(x, y))) return true;
        }
        return false;
    };
    int x0 = 0;
    while (x0 < p.width && !coloured_column(x0)) ++x0;
    int x1 = x0;
    while (x1 + 1 < p.width && coloured_column(x1 + 1)) ++x1;
    int y0 = p.height, y1 = -1;
    for (int y = 0; y < p.height; ++y) {
        if (saturated(p.at(x0 + (x1 - x0) / 2, y))) y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    ASSERT_GT(x1 - x0, 390);           // --size 400
    ASSERT_NEAR(x1 - x0, y1 - y0, 3);  // a square room gives a square map
    const double cell = (x1 - x0 + 1) / 8.0;
    // Sample each cell away from its centred label, and its mirror image across both axes.
    const auto sample = [&](double i, double j) {
        return p.at(x0 + static_cast<int>(i * cell), y0 + static_cast<int>(j * cell));
    };
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const double h = hue(sample(i + 0.2, j + 0.2));
            EXPECT_NEAR(h, hue(sample(8 - i - 0.2, j + 0.2)), 6) << i << "," << j;
            EXPECT_NEAR(h, hue(sample(i + 0.2, 8 - j - 0.2)), 6) << i << "," << j;
        }
    }
    EXPECT_LT(hue(sample(3.2, 3.2)), hue(sample(0.2, 0.2)) - 30);
}

/// Rows from the top that hold a pixel of exactly this colour.
std::vector<int> rows_with(const Picture& p, const std::array<unsigned char, 3>& colour) {
    std::vector<int> rows;
    for (int y = 0; y < p.height; ++y) {
        for (int x = 0; x < p.width; ++x) {
            if (std::equal(colour.begin(), colour.end(), p.at(x, y))) {
                rows.push_back(y);
                break;
            }
        }
    }
    return rows;
}

/// The longest horizontal run of pixels of exactly this colour.
int longest_run(const Picture& p, const std::array<unsigned char, 3>& colour) {
    int longest = 0;
    for (int y = 0; y < p.height; ++y) {
        int run = 0;
        for (int x = 0; x < p.width; ++x) {
            run = std::equal(colour.begin(), colour.end(), p.at(x, y)) ? run + 1 : 0;
            longest = std::max(longest, run);
        }
    }
    return longest;
}

// The plan's colours for a passed and a failed check, the task area's outline and the band's
// cell edges (clients/cli/picture/sensor_plan.cpp).
constexpr std::array<unsigned char, 3> kPass{0, 130, 40}, kFail{200, 20, 20}, kInk{20, 20, 20},
    kBandEdge{120, 120, 120};

// A 2 × 2 m desk whose requirement asks for Ēm ≥ 1 lx (passed) and U₀ ≥ 0.99 (failed): the
// verdict is a red line, then the checks in green and red; the band hatched around the desk
// widens the map to 3 m, of which the desk's black outline spans two thirds.
TEST_F(Pictures, PlanOfATaskAreaOutlinesItHatchesItsBandAndColoursEveryCheck) {
    const Picture plain = make("plan --size 400", "plain.png");
    EXPECT_TRUE(rows_with(plain, kPass).empty());
    EXPECT_TRUE(rows_with(plain, kFail).empty());
    EXPECT_TRUE(rows_with(plain, kBandEdge).empty());

    scene_ = std::string(RADIANT_TEST_DATA) + "/pictures/task-room.json";
    const Picture p = make("plan --size 400", "task.png");
    const std::vector<int> pass = rows_with(p, kPass), fail = rows_with(p, kFail);
    ASSERT_FALSE(pass.empty());
    ASSERT_FALSE(fail.empty());
    EXPECT_LT(fail.front(), pass.front());  // the verdict first: failed
    EXPECT_LT(pass.front(), fail.back());   // Ēm passed above U₀ failed
    EXPECT_FALSE(rows_with(p, kBandEdge).empty());
    const int outline = longest_run(p, kInk);
    EXPECT_NEAR(outline, 400 * 2.0 / 3.0, 12);
}

// The stored result carries the task area's compliance, so a plan drawn from it marks the area
// as the plan of a new solve does: the same verdict and check lines, band and outline.
TEST_F(Pictures, PlanFromAStoredResultMarksTheTaskAreaAsASolveDoes) {
    scene_ = std::string(RADIANT_TEST_DATA) + "/pictures/task-room.json";
    const fs::path stored = dir_ / "task-result.json";
    const radiant::test::CliRun solved =
        radiant::test::run_cli("solve '" + scene_ + "' --out '" + stored.string() + "'");
    ASSERT_EQ(solved.exit_code, 0) << solved.err;
    const Picture fresh = make("plan --size 400", "fresh.png");
    const Picture redrawn =
        make("plan --size 400 --result '" + stored.string() + "'", "stored.png");
    ASSERT_FALSE(rows_with(redrawn, kFail).empty());
    EXPECT_EQ(rows_with(redrawn, kPass), rows_with(fresh, kPass));
    EXPECT_EQ(rows_with(redrawn, kFail), rows_with(fresh, kFail));
    EXPECT_FALSE(rows_with(redrawn, kBandEdge).empty());
    EXPECT_EQ(longest_run(redrawn, kInk), longest_run(fresh, kInk));
}

TEST_F(Pictures, ACameraLookingAtItsOwnEyeIsRefused) {
    const radiant::test::CliRun r =
        radiant::test::run_cli("render '" + scene_ + "' --eye 1 1 1 --target 1 1 1 --out '" +
                               (dir_ / "x.png").string() + "'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("camera"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

TEST_F(Pictures, PlanOfAnUnknownSensorSetIsRefused) {
    const radiant::test::CliRun r = radiant::test::run_cli(
        "plan '" + scene_ + "' --sensors nope --out '" + (dir_ / "x.png").string() + "'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("nope"), std::string::npos) << r.err;
}

/// The lamp room solved with its mesh, as `radiant solve --mesh` writes it.
nlohmann::json solved_with_mesh(const std::string& scene, const fs::path& out) {
    const radiant::test::CliRun r =
        radiant::test::run_cli("solve '" + scene + "' --mesh --out '" + out.string() + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(radiant::test::read_text(out));
}

// Pictures of a stored result show its numbers, not a new solve's: a result whose values no
// solve of this symmetric room would give is drawn as it is.
TEST_F(Pictures, AStoredResultIsDrawnAsItIsWithoutSolving) {
    nlohmann::json result = solved_with_mesh(scene_, dir_ / "solved.json");
    nlohmann::json& mesh = result["mesh"];
    for (std::size_t v = 0; v < mesh["vertices"].size(); ++v) {
        mesh["vertex_radiosity"][v] = mesh["vertices"][v][0].get<double>() < 2 ? 100.0 : 0.0;
    }
    for (auto& set : result["sensors"]) {
        for (auto& lux : set["illuminance"]) lux = 10.0;
        set["illuminance"][0] = 1000.0;  // the corner cell at the grid's origin
    }
    const fs::path doctored = dir_ / "doctored.json";
    std::ofstream(doctored) << result.dump();
    const std::string from = " --result '" + doctored.string() + "'";

    const Picture view = make(kDownView + from, "stored-view.png");
    ASSERT_EQ(view.width, 201);
    double left = 0, right = 0;
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < 60; ++x) left += view.grey(x, y), right += view.grey(200 - x, y);
    }
    EXPECT_GT(left, right + 50.0 * 60 * view.height) << "the west half is the bright one";

    const Picture plan = make("plan --size 400" + from, "stored-plan.png");
    int red = 0;
    for (int y = 0; y < plan.height; ++y) {
        for (int x = 0; x < plan.width * 2 / 3; ++x) {  // the map, not the legend
            const double h = hue(plan.at(x, y));
            red += saturated(plan.at(x, y)) && (h < 20 || h > 340);
        }
    }
    // One cell of 64 in red: about a 64th of the 400 × 400 map (less its label).
    EXPECT_GT(red, 1000);
    EXPECT_LT(red, 4000);
}

TEST_F(Pictures, AResultThatCannotBeDrawnIsRefusedWithItsPointer) {
    const nlohmann::json solved = solved_with_mesh(scene_, dir_ / "solved.json");
    const auto refusal = [&](const std::string& command, const nlohmann::json& result) {
        const fs::path file = dir_ / "result.json";
        std::ofstream(file) << result.dump();
        const radiant::test::CliRun r =
            radiant::test::run_cli(command + " '" + scene_ + "' --result '" + file.string() +
                                   "' --out '" + (dir_ / "x.png").string() + "'");
        EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
        EXPECT_FALSE(fs::exists(dir_ / "x.png"));
        return r.err;
    };
    nlohmann::json broken = solved;
    broken["mesh"]["triangles"][0][1] = 1 << 30;
    EXPECT_NE(refusal("render", broken).find(": /mesh/triangles/0/1: "), std::string::npos);
    nlohmann::json other = solved;
    other["scene"] = "another-room";
    EXPECT_NE(refusal("render", other).find(": /scene: "), std::string::npos);
    nlohmann::json no_mesh = solved;
    no_mesh.erase("mesh");
    EXPECT_NE(refusal("render", no_mesh).find("no mesh"), std::string::npos);
    nlohmann::json short_set = solved;
    short_set["sensors"][0]["points"].erase(0);
    EXPECT_NE(refusal("plan", short_set).find(": /sensors/0/points: "), std::string::npos);
    // Nothing is solved, so the solve flags do not go with --result.
    EXPECT_FALSE(refusal("render --tolerance 0.1", solved).empty());
}

}  // namespace
