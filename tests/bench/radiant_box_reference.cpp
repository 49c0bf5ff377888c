// radiant-box-reference: converged reference answers for closed box rooms, computed outside
// the solver (box_room_reference.h), written as scenes plus expected values for
// tests/validation/box_rooms_test.cpp. Generated once and committed:
//
//   build/tests/bench/radiant-box-reference --out tests/data/box_rooms
//
// It first reproduces validation README §2.7(a) and refuses to write anything if that fails.
// `--quick-check` (a ctest) compares the cube's discrete solutions at N = 8 and 16 with the
// README's table instead, which takes seconds.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "box_room_reference.h"
#include "box_room_scene.h"

namespace {

namespace fs = std::filesystem;
using namespace radiant::bench;

// The accuracy bar of the engine core for face means (tests/data/scenes/expected.json).
constexpr double kRelTol = 0.005;

struct RoomCase {
    BoxRoom room;
    std::array<int, 3> cells_per_metre;
};

BoxRoom uniform_cube(const std::string& name, double floor, double walls, double ceiling) {
    BoxRoom room;
    room.name = name;
    room.size = {1, 1, 1};
    for (int f = 0; f < kBoxFaces; ++f) room.faces[f].reflectance = walls;
    room.faces[floor_face].reflectance = floor;
    room.faces[ceiling_face] = {ceiling, 1.0};
    return room;
}

BoxRoom office(const std::string& name) {
    BoxRoom room;
    room.name = name;
    room.size = {4, 4, 3};
    for (int f = 0; f < kBoxFaces; ++f) room.faces[f].reflectance = 0.5;
    room.faces[floor_face].reflectance = 0.2;
    room.faces[ceiling_face].reflectance = 0.8;
    return room;
}

// Cubes at N = 16/24/32 per face as in §2.7; the 4 m rooms at 4/6/8 cells per metre
// (1280/2880/5120 patches) and the corridor too (1600/3600/6400), all within ~7000.
std::vector<RoomCase> rooms() {
    std::vector<RoomCase> out;
    out.push_back({uniform_cube("box-cube-rho0.2", 0.2, 0.2, 0.2), {16, 24, 32}});
    out.push_back({uniform_cube("box-cube-rho0.8", 0.8, 0.8, 0.8), {16, 24, 32}});
    out.push_back({uniform_cube("box-cube-mixed", 0.2, 0.5, 0.8), {16, 24, 32}});

    BoxRoom panel = office("box-room-panel");
    panel.panel = BoxPanel{ceiling_face, 1.5, 2.5, 1.5, 2.5, {0.8, 1000}};
    out.push_back({panel, {4, 6, 8}});

    BoxRoom point = office("box-room-point");
    point.luminaires.push_back({{2, 2, 2.5}, 1000});
    out.push_back({point, {4, 6, 8}});

    BoxRoom corridor;
    corridor.name = "box-corridor-panel";
    corridor.size = {10, 2, 2.5};
    for (int f = 0; f < kBoxFaces; ++f) corridor.faces[f].reflectance = 0.5;
    corridor.panel = BoxPanel{ceiling_face, 1.0, 2.0, 0.5, 1.5, {0.5, 1000}};
    out.push_back({corridor, {4, 6, 8}});
    return out;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

bool close_to(double got, double want, double tol, const std::string& what) {
    const bool ok = std::abs(got - want) <= tol;
    std::printf("  %-28s %.7f  README %.7g  %s\n", what.c_str(), got, want, ok ? "ok" : "FAIL");
    return ok;
}

bool sane(const BoxRoomSolution& s) {
    std::printf("  %d patches: max |row sum - 1| %.1e, energy balance %.1e\n", s.patches,
                s.max_row_sum_error, s.energy_error);
    return s.max_row_sum_error < 1e-11 && s.energy_error < 1e-9;
}

// §2.7(a): unit cube, ceiling emits 1, ρ = 0.5 everywhere. Columns N = 8 and N = 16 of the
// README's table are the discrete model's own values, to six digits.
bool quick_check() {
    const BoxRoom cube = uniform_cube("cube", 0.5, 0.5, 0.5);
    bool ok = true;
    const struct {
        int n;
        double floor, wall, ceiling;
    } columns[] = {{8, 0.171373, 0.181196, 1.103845}, {16, 0.171256, 0.181133, 1.104211}};
    for (const auto& c : columns) {
        const BoxRoomSolution s = solve_box_room(cube, c.n);
        ok &= sane(s);
        ok &= close_to(s.faces[floor_face].radiosity, c.floor, 5e-7,
                       "N " + std::to_string(c.n) + " floor");
        ok &= close_to(s.faces[south_face].radiosity, c.wall, 5e-7,
                       "N " + std::to_string(c.n) + " wall");
        ok &= close_to(s.faces[ceiling_face].radiosity, c.ceiling, 5e-7,
                       "N " + std::to_string(c.n) + " ceiling");
    }
    std::puts(ok ? "quick check passed" : "quick check FAILED");
    return ok;
}

// §2.7(a) converged: floor 0.171216, wall 0.181107, ceiling 1.10436 (to the stated digits).
bool acceptance() {
    std::puts("validation README 2.7(a): unit cube, ceiling emits 1, rho 0.5");
    const BoxRoomReference r = reference_for(uniform_cube("cube", 0.5, 0.5, 0.5), {16, 24, 32});
    bool ok = true;
    for (const auto& s : r.solutions) ok &= sane(s);
    std::printf("  extrapolated uncertainties: floor %.1e, wall %.1e, ceiling %.1e\n",
                r.radiosity[floor_face].uncertainty, r.radiosity[south_face].uncertainty,
                r.radiosity[ceiling_face].uncertainty);
    ok &= close_to(r.radiosity[floor_face].value, 0.171216, 5e-7, "floor mean B");
    for (int f : {south_face, north_face, west_face, east_face})
        ok &= close_to(r.radiosity[f].value, 0.181107, 5e-7,
                       std::string(box_face_name(f)) + " mean B");
    ok &= close_to(r.radiosity[ceiling_face].value, 1.10436, 5e-6, "ceiling mean B");
    return ok;
}

void print_reference(const BoxRoom& room, const BoxRoomReference& r) {
    std::printf("%s (%d/%d/%d cells per metre):\n", room.name.c_str(), r.resolutions[0],
                r.resolutions[1], r.resolutions[2]);
    const auto line = [](const char* name, const ExtrapolatedMean& b, const ExtrapolatedMean& h) {
        std::printf("  %-11s B %-12.7g ± %.1e   H %-12.7g ± %.1e\n", name, b.value, b.uncertainty,
                    h.value, h.uncertainty);
    };
    for (int f = 0; f < kBoxFaces; ++f) line(box_face_name(f), r.radiosity[f], r.irradiance[f]);
    if (room.panel) line("panel", r.panel_radiosity, r.panel_irradiance);
}

// The reference must be far more accurate than the bar it is used for.
bool precise_enough(const BoxRoomReference& r, bool has_panel) {
    bool ok = true;
    const auto check = [&](const ExtrapolatedMean& m) {
        ok &= m.uncertainty <= 0.05 * kRelTol * std::abs(m.value);
    };
    for (int f = 0; f < kBoxFaces; ++f) {
        check(r.radiosity[f]);
        check(r.irradiance[f]);
    }
    if (has_panel) {
        check(r.panel_radiosity);
        check(r.panel_irradiance);
    }
    return ok;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "Converged box-room references (validation README 2.7) as scenes + expected values"};
    std::string out_dir = "tests/data/box_rooms";
    bool quick = false;
    app.add_option("--out", out_dir, "directory for the scenes and expected.json");
    app.add_flag("--quick-check", quick, "only compare the cube's N = 8, 16 solutions (seconds)");
    CLI11_PARSE(app, argc, argv);

    if (quick) return quick_check() ? 0 : 1;

    const auto t0 = std::chrono::steady_clock::now();
    if (!acceptance()) {
        std::cerr << "2.7(a) not reproduced; nothing written\n";
        return 1;
    }
    std::printf("  (%.0f s)\n", seconds_since(t0));

    nlohmann::ordered_json expected = nlohmann::ordered_json::object();
    fs::create_directories(out_dir);
    for (const RoomCase& c : rooms()) {
        const auto t = std::chrono::steady_clock::now();
        const BoxRoomReference r = reference_for(c.room, c.cells_per_metre);
        bool ok = true;
        for (const auto& s : r.solutions) ok &= sane(s);
        print_reference(c.room, r);
        std::printf("  (%.0f s)\n", seconds_since(t));
        if (!ok || !precise_enough(r, c.room.panel.has_value())) {
            std::cerr << c.room.name << ": reference not converged enough; nothing written\n";
            return 1;
        }
        std::ofstream(fs::path(out_dir) / (c.room.name + ".json"))
            << box_room_scene(c.room).dump(1) << '\n';
        expected[c.room.name] = box_room_checks(c.room, r, kRelTol);
    }
    std::ofstream(fs::path(out_dir) / "expected.json") << expected.dump(1) << '\n';
    std::printf("wrote %s (%.0f s in all)\n", out_dir.c_str(), seconds_since(t0));
    return 0;
}
