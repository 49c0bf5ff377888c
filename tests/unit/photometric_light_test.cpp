// Luminaires with IES and EULUMDAT tables in a solve: exact direct light I(γ, C)·cos θ / d² for
// any aim and rotation, the same answer from both formats, and the table's flux conserved in the
// first bounce.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "photometric_files.h"
#include "photometry/ies_reader.h"
#include "photometry/intensity_table.h"
#include "photometry/ldt_reader.h"
#include "radiant/solve.h"
#include "scene_builder.h"

namespace radiant {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

/// Asymmetric in C, smooth, with an up-light part: every table direction matters. The
/// C-variation fades at the poles, where all planes meet in one direction.
double beam(double gamma, double c) {
    const double down = gamma < 90 ? 800 * std::pow(std::cos(gamma * kDeg), 1.5) : 0;
    const double s = std::sin(gamma * kDeg);
    return (down + 150 + 100 * s) *
           (1 + s * (0.3 * std::cos(c * kDeg) + 0.15 * std::sin(2 * c * kDeg)));
}

PhotometricTable table_from(const std::variant<PhotometricTable, std::string>& parsed) {
    if (const auto* message = std::get_if<std::string>(&parsed)) ADD_FAILURE() << *message;
    return std::get<PhotometricTable>(parsed);
}

PhotometricTable ies_beam() {
    return table_from(proto::read_ies(
        testing::ies_text(testing::angles(0, 180, 5), testing::angles(0, 345, 15), beam, 1000)));
}

Luminaire photometric(const PhotometricTable& table, Vec3 position, Vec3 aim, double rotation) {
    Luminaire l;
    l.name = "L";
    l.position = position;
    l.distribution = Distribution::photometric;
    l.photometry = table;
    l.aim = aim;
    l.rotation_deg = rotation;
    return l;
}

/// A point at distance d from the luminaire toward (γ, C) of its own frame.
struct Probe {
    double gamma, c, d;
    Vec3 normal;
};

struct Frame {
    Vec3 position, aim, c0, c90;
    Vec3 toward(const Probe& p) const {
        const double g = p.gamma * kDeg, c = p.c * kDeg;
        return position +
               (aim * std::cos(g) + (c0 * std::cos(c) + c90 * std::sin(c)) * std::sin(g)) * p.d;
    }
};

/// Sensors toward each probe under the luminaire over a black floor: the solve's illuminance is
/// direct light only, to be compared with I(γ, C)·cos θ / d² from the function the file holds.
void expect_direct_light(const Frame& frame, double rotation, const std::vector<Probe>& probes,
                         double relative) {
    Scene scene;
    scene.name = "direct";
    scene.materials = {testing::gray("black", 0)};
    scene.surfaces = {testing::polygon_surface(
        "floor", "black", testing::rect({-20, -20, -5}, {40, 0, 0}, {0, 40, 0}))};
    scene.luminaires = {photometric(ies_beam(), frame.position, frame.aim, rotation)};
    for (std::size_t k = 0; k < probes.size(); ++k) {
        // Built with append: GCC 12 reports a false -Wrestrict on "p" + std::to_string(k) here.
        scene.sensors.push_back(testing::sensor_points(std::string("p").append(std::to_string(k)),
                                                       {frame.toward(probes[k])},
                                                       probes[k].normal));
    }
    SolveOptions options;
    options.method = "direct";
    const Result result = solve(scene, options);
    ASSERT_EQ(result.status, SolveStatus::converged) << result.error;
    for (std::size_t k = 0; k < probes.size(); ++k) {
        const Probe& p = probes[k];
        const Vec3 to_light = normalized(frame.position - frame.toward(p));
        const double cos_theta = dot(normalized(p.normal), to_light);
        const double want = beam(p.gamma, p.c) * cos_theta / (p.d * p.d);
        const double got = result.sensors[k].illuminance[0];
        EXPECT_NEAR(got / want, 1, relative)
            << "gamma " << p.gamma << " C " << p.c << ": got " << got << " lx, want " << want;
    }
}

// The file's own angles are exact; between them the smooth interpolation stays within 0.5 %.
const std::vector<Probe> kProbes{
    {0, 0, 2.0, {0, 0, 1}},          {30, 45, 2.5, {0.2, 0.1, 1}}, {55, 90, 1.5, {0, 0, 1}},
    {70, 195, 3.0, {-0.3, 0, 1}},    {120, 300, 2.0, {0, 0, -1}},  {12.5, 22.5, 2.2, {0, 0, 1}},
    {47.5, 127.5, 1.8, {0, 0.3, 1}}, {81, 250, 2.6, {0, 0, 1}},
};

TEST(PhotometricLight, DirectIlluminanceUnderAnAimedDownLuminaire) {
    const Frame frame{{0, 0, 3}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}};
    expect_direct_light(frame, 0, kProbes, 0.005);
}

// Aimed 45° off nadir toward +x and turned 30° about its aim: the C0 plane follows (by hand:
// straight down turned toward +x carries x to (cos 45°, 0, sin 45°); C90 stays +y).
TEST(PhotometricLight, DirectIlluminanceUnderATiltedRotatedLuminaire) {
    const double a = std::sqrt(0.5), r = 30 * kDeg;
    const Vec3 aim{a, 0, -a}, c0{a, 0, a}, c90{0, 1, 0};
    const Frame frame{{1, -1, 3},
                      aim,
                      c0 * std::cos(r) + c90 * std::sin(r),
                      c90 * std::cos(r) - c0 * std::sin(r)};
    std::vector<Probe> probes = kProbes;
    for (Probe& p : probes)
        p.normal = normalized(frame.position - frame.toward(p)) + Vec3{0, 0.1, 0};
    expect_direct_light(frame, 30, probes, 0.005);
}

TEST(PhotometricLight, NodesAreExact) {
    const Frame frame{{0, 0, 3}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}};
    expect_direct_light(
        frame, 0, {{30, 45, 2.5, {0, 0, 1}}, {0, 0, 2, {0, 0, 1}}, {85, 330, 2, {-1, 0, 0}}}, 1e-9);
}

/// A closed 5 × 4 × 3 m room, ρ = 0.5, with the luminaire under the ceiling and a work plane.
Scene closed_room(const Luminaire& luminaire) {
    Scene scene;
    scene.name = "closed";
    scene.materials = {testing::gray("wall", 0.5)};
    scene.surfaces = {testing::box_surface("room", "wall", {0, 0, 0}, {5, 4, 3}, true)};
    scene.luminaires = {luminaire};
    scene.sensors = {testing::sensor_grid("wp", {0.5, 0.5, 0.8}, {4, 0, 0}, {0, 3, 0}, 8, 6)};
    return scene;
}

// IES and EULUMDAT files of the same luminaire give the same illuminance within 1 %.
TEST(PhotometricLight, IesAndEulumdatAgree) {
    const double lamp_flux = 3000;
    const PhotometricTable ldt = table_from(
        proto::read_ldt(testing::ldt_text(0, 24, testing::angles(0, 180, 5), beam, lamp_flux)));
    const Vec3 at{2.5, 2, 2.7}, aim = normalized(Vec3{0.3, 0, -1});
    const Result from_ies = solve(closed_room(photometric(ies_beam(), at, aim, 20)), {});
    const Result from_ldt = solve(closed_room(photometric(ldt, at, aim, 20)), {});
    ASSERT_EQ(from_ies.status, SolveStatus::converged);
    ASSERT_EQ(from_ldt.status, SolveStatus::converged);
    const auto& a = from_ies.sensors[0].illuminance;
    const auto& b = from_ldt.sensors[0].illuminance;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(b[k] / a[k], 1, 0.01) << k;
}

// In a closed room every lumen the table emits lands on a wall and is reflected: the first
// bounce integrates the table over each patch, so Σ A·E = Φ / (1 − ρ) for every solver.
TEST(PhotometricLight, FirstBounceConservesTheTablesFlux) {
    const PhotometricTable table = ies_beam();
    const double flux = IntensityTable(table).flux_lm();
    for (const char* method : {"direct", "hierarchical"}) {
        // Close to the ceiling, where patches are large seen from the luminaire.
        Scene scene = closed_room(photometric(table, {1.2, 1.1, 2.8}, {0, 0, -1}, 0));
        SolveOptions options;
        options.method = method;
        const Result result = solve(scene, options);
        ASSERT_EQ(result.status, SolveStatus::converged) << method;
        EXPECT_NEAR(result.stats.emitted_flux_lm / flux, 1, 1e-12) << method;
        double arriving = 0;
        for (const SurfaceResult& s : result.surfaces) arriving += s.area_m2 * s.average_irradiance;
        EXPECT_NEAR(arriving / (flux / 0.5), 1, 0.01) << method;
    }
}

// A scene flux rescales the table: twice the flux, twice the light everywhere.
TEST(PhotometricLight, SceneFluxScalesTheTable) {
    const PhotometricTable table = ies_beam();
    const double flux = IntensityTable(table).flux_lm();
    Luminaire doubled = photometric(table, {2.5, 2, 2.7}, {0, 0, -1}, 0);
    doubled.flux_lm = 2 * flux;
    const Result one = solve(closed_room(photometric(table, {2.5, 2, 2.7}, {0, 0, -1}, 0)), {});
    const Result two = solve(closed_room(doubled), {});
    EXPECT_NEAR(two.stats.emitted_flux_lm / flux, 2, 1e-12);
    for (std::size_t k = 0; k < one.sensors[0].illuminance.size(); ++k) {
        EXPECT_NEAR(two.sensors[0].illuminance[k] / one.sensors[0].illuminance[k], 2, 1e-9);
    }
}

}  // namespace
}  // namespace radiant
