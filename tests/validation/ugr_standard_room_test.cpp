// UGR on the standard room of the CIE tabular method (CIE 117:1995, CIE 190:2010): a room 4H
// across and 8H along the line of sight, H = 2 m between the eye's plane and the luminaires',
// reflectances 0.7 (ceiling, at the luminaire plane), 0.5 (walls), 0.2 (the plane of the eye),
// luminaires at spacing H (spacing-to-height ratio 1), the observer at the middle of the short
// wall looking along the room. The test computes the tabular value from the method's own
// formulas — the glare sum with the Guth position index, and the background luminance
// L_b = E_WID/π with E_WID = Σ Φ_direct · F_T / A_w, the transfer factors F_T of a three-surface
// room by exact view factors, the direct flux on the floor by exact form factors — and the
// solve must agree within 1 UGR unit. Its background luminance is the radiosity the eye sees.
// Rooms of 2H × 2H and 8H × 4H check the same formulas away from the table's room.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"
#include "solve_with.h"

namespace radiant {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kH = 2;

/// A room of the tabular method: `across` and `along` the observer's line of sight, metres.
struct Room {
    double across = 4 * kH, along = 8 * kH;
    const char* method = "monte-carlo";
};
constexpr double kFlux = 3000, kSide = 0.6;  // lm per luminaire; its square luminous area, m
// The luminaires hang just under the ceiling; the eye is just off the wall and the floor.
constexpr double kLuminaireZ = kH - 0.005, kEye = 0.01;

/// A square recessed panel of uniform luminance: I(γ) = I₀ cos γ, I₀ = Φ/π.
std::string panel_ies() {
    std::string ies = "IESNA:LM-63-2002\n[TEST] uniform panel\nTILT=NONE\n1 " +
                      std::to_string(kFlux) + " 1 19 1 1 2 " + std::to_string(kSide) + " " +
                      std::to_string(kSide) + " 0\n1.0 1.0 30\n";
    for (int g = 0; g <= 90; g += 5) ies += std::to_string(g) + " ";
    ies += "\n0\n";
    for (int g = 0; g <= 90; g += 5)
        ies += std::to_string(kFlux / kPi * std::cos(g * kPi / 180)) + " ";
    return ies + "\n";
}

std::string scene_json(const Room& room) {
    using Json = nlohmann::json;
    const double kX = room.across, kY = room.along;
    // The room's six faces, each facing in: corners counter-clockwise seen from inside.
    const auto face = [](const char* name, const char* material, const Json& corners) {
        return Json{{"name", name}, {"material", material}, {"polygon", corners}};
    };
    const Json surfaces = {
        face("floor", "floor", {{0, 0, 0}, {kX, 0, 0}, {kX, kY, 0}, {0, kY, 0}}),
        face("ceiling", "ceiling", {{0, 0, kH}, {0, kY, kH}, {kX, kY, kH}, {kX, 0, kH}}),
        face("south", "wall", {{0, 0, 0}, {0, 0, kH}, {kX, 0, kH}, {kX, 0, 0}}),
        face("north", "wall", {{0, kY, 0}, {kX, kY, 0}, {kX, kY, kH}, {0, kY, kH}}),
        face("west", "wall", {{0, 0, 0}, {0, kY, 0}, {0, kY, kH}, {0, 0, kH}}),
        face("east", "wall", {{kX, 0, 0}, {kX, 0, kH}, {kX, kY, kH}, {kX, kY, 0}})};
    Json luminaires = Json::array();
    for (double lx = kH / 2; lx < kX; lx += kH) {
        for (double ly = kH / 2; ly < kY; ly += kH) {
            luminaires.push_back({{"name", "L"},
                                  {"position", {lx, ly, kLuminaireZ}},
                                  {"distribution", {{"ies", panel_ies()}}}});
        }
    }
    Json scene = Json::parse(R"({"format": "radiant-scene/1", "name": "cie-standard-room",
      "materials": {"floor": {"reflectance": 0.2}, "wall": {"reflectance": 0.5},
                    "ceiling": {"reflectance": 0.7}},
      "settings": {"tolerance": 0.02}})");
    // A sensor grid on the floor, 1 m apart: the Monte Carlo method measures its error there.
    scene["sensors"] = {{{"name", "reference plane"},
                         {"normal", {0, 0, 1}},
                         {"grid",
                          {{"origin", {0.5, 0.5, 0.01}},
                           {"u", {kX - 1, 0, 0}},
                           {"v", {0, kY - 1, 0}},
                           {"nu", std::lround(kX - 1)},
                           {"nv", std::lround(kY - 1)}}}}};
    scene["surfaces"] = surfaces;
    scene["luminaires"] = luminaires;
    scene["observers"] = {
        {{"name", "wall middle"}, {"position", {kX / 2, kEye, kEye}}, {"view", {0, 1, 0}}}};
    scene["settings"]["method"] = room.method;
    return scene.dump();
}

// CIE 117's fit of the Luckiesh–Guth position index, written out again here.
double guth(double r, double t, double h) {
    const double alpha = std::atan2(std::abs(t), h) * 180 / kPi;
    const double beta = std::atan(std::hypot(t, h) / r) * 180 / kPi;
    return std::exp((35.2 - 0.31889 * alpha - 1.22 * std::exp(-2 * alpha / 9)) * 1e-3 * beta +
                    (21 + 0.26667 * alpha - 0.002963 * alpha * alpha) * 1e-5 * beta * beta);
}

/// View factor between directly opposed parallel rectangles a × b at distance c (Hottel).
double parallel_rectangles(double a, double b, double c) {
    const double x = a / c, y = b / c;
    const double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
    return 2 / (kPi * x * y) *
           (std::log(std::sqrt((1 + x * x) * (1 + y * y) / (1 + x * x + y * y))) +
            x * sy * std::atan(x / sy) + y * sx * std::atan(y / sx) - x * std::atan(x) -
            y * std::atan(y));
}

/// Form factor from a downward-facing point at height h above a corner of an a × b rectangle.
double point_to_corner_rectangle(double a, double b, double h) {
    const double x = a / h, y = b / h;
    return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
            y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
           (2 * kPi);
}

/// CIE 190's transfer factors: indirect flux reaching the walls per lumen falling directly on
/// the floor, walls and ceiling of the three-surface room (exact view factors, radiosity solved).
std::array<double, 3> transfer_factors(const Room& room) {
    const double kX = room.across, kY = room.along;
    const double af = kX * kY, aw = 2 * kH * (kX + kY);
    const double ffc = parallel_rectangles(kX, kY, kH), ffw = 1 - ffc;
    const double fwf = af * ffw / aw, fww = 1 - 2 * fwf;
    const double f[3][3] = {{0, ffw, ffc}, {fwf, fww, fwf}, {ffc, ffw, 0}};
    const double rho[3] = {0.2, 0.5, 0.7}, area[3] = {af, aw, af};
    std::array<double, 3> out{};
    for (int source = 0; source < 3; ++source) {
        // M = ρ (E_direct + F M), by Gauss–Seidel (the system is well conditioned).
        double m[3] = {0, 0, 0};
        for (int it = 0; it < 1000; ++it) {
            for (int i = 0; i < 3; ++i) {
                const double direct = i == source ? 1 / area[i] : 0;
                m[i] = rho[i] * (direct + f[i][0] * m[0] + f[i][1] * m[1] + f[i][2] * m[2]);
            }
        }
        out[static_cast<std::size_t>(source)] =
            (f[1][0] * m[0] + f[1][1] * m[1] + f[1][2] * m[2]) * aw;
    }
    return out;
}

TEST(UgrStandardRoomTable, TransferFactorsAreCie190s) {
    // CIE 190:2010 Table 5, k = 2.67, reflectances 0.7 / 0.5 / 0.2: 0.115, 0.211, 0.307.
    const auto t = transfer_factors(Room{});
    EXPECT_NEAR(t[0], 0.115, 0.0005);
    EXPECT_NEAR(t[1], 0.211, 0.0005);
    EXPECT_NEAR(t[2], 0.307, 0.0005);
}

// The Monte Carlo method gathers the background at the eye; the radiosity methods cast rays from
// the eye into their solved mesh.
// Rooms other than the one of the transfer factors' table check the same formulas.
class UgrStandardRoom : public ::testing::TestWithParam<Room> {};

TEST_P(UgrStandardRoom, AgreesWithTheTabularMethodWithinOneUnit) {
    const Room& room = GetParam();
    const double kX = room.across, kY = room.along;
    const proto::ParseOutcome outcome = proto::parse_scene(scene_json(room));
    ASSERT_TRUE(outcome.ok()) << outcome.problems[0].pointer << ": " << outcome.problems[0].message;
    const Result r = solve(*outcome.scene, options_from(outcome.scene->settings));
    ASSERT_EQ(r.status, SolveStatus::converged) << testing::describe(r);
    ASSERT_EQ(r.observers.size(), 1u);

    // The tabular method. The eye at the middle of the wall at y = 0, the luminaire plane H up.
    const double i0 = kFlux / kPi, area = kSide * kSide;
    double glare = 0, floor_flux = 0;
    int luminaires = 0;
    for (double lx = kH / 2; lx < kX; lx += kH) {
        for (double ly = kH / 2; ly < kY; ly += kH) {
            ++luminaires;
            const double t = lx - kX / 2, rr = ly - kEye, h = kLuminaireZ - kEye;
            const double d2 = t * t + rr * rr + h * h;
            const double cos_gamma = h / std::sqrt(d2);
            // L = I/A_p = I₀cosγ/(A cosγ); ω = A cosγ/d².
            const double luminance = i0 / area, omega = area * cos_gamma / d2;
            const double p = guth(rr, t, h);
            glare += luminance * luminance * omega / (p * p);
            // Direct flux on the floor: the four corner rectangles under the luminaire.
            floor_flux += kFlux * (point_to_corner_rectangle(lx, ly, kLuminaireZ) +
                                   point_to_corner_rectangle(kX - lx, ly, kLuminaireZ) +
                                   point_to_corner_rectangle(lx, kY - ly, kLuminaireZ) +
                                   point_to_corner_rectangle(kX - lx, kY - ly, kLuminaireZ));
        }
    }
    const double wall_flux = luminaires * kFlux - floor_flux;  // no light goes up
    const auto ft = transfer_factors(room);
    const double e_wid = (floor_flux * ft[0] + wall_flux * ft[1]) / (2 * kH * (kX + kY));
    const double lb = e_wid / kPi;
    const double tabular = 8 * std::log10(0.25 / lb * glare);

    const ObserverResult& o = r.observers[0];
    EXPECT_NEAR(o.glare_sum, glare, 0.02 * glare);  // the same luminaires, nearly the same eye
    EXPECT_NEAR(o.ugr, tabular, 1.0) << "background " << o.background_luminance << " cd/m², the "
                                     << "tabular method's " << lb;
    EXPECT_LT(o.ugr_error_estimate, 0.25);
    RecordProperty("ugr", std::to_string(o.ugr));
    RecordProperty("tabular_ugr", std::to_string(tabular));
}

std::string room_name(const ::testing::TestParamInfo<Room>& param) {
    const Room& r = param.param;
    std::string name = std::to_string(std::lround(r.across / kH)) + "Hx" +
                       std::to_string(std::lround(r.along / kH)) + "H_";
    name += std::string(r.method) == "monte-carlo" ? "monte_carlo" : r.method;
    return name;
}

INSTANTIATE_TEST_SUITE_P(Rooms, UgrStandardRoom,
                         ::testing::Values(Room{}, Room{4 * kH, 8 * kH, "hierarchical"},
                                           Room{2 * kH, 2 * kH}, Room{8 * kH, 4 * kH}),
                         room_name);

}  // namespace
}  // namespace radiant
