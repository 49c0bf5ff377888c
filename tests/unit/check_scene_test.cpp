#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "radiant/scene.h"

namespace radiant {
namespace {

Scene unit_square() {
    Scene scene;
    scene.materials.push_back({"m", {0.5, 0.5, 0.5}, false, std::nullopt, false});
    scene.surfaces.push_back({"s", "m", Polygon{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}});
    return scene;
}

std::vector<std::string> pointers(const Scene& scene, const SceneLimits& limits = {}) {
    std::vector<std::string> out;
    for (const Problem& p : check_scene(scene, limits)) out.push_back(p.pointer);
    return out;
}

using Pointers = std::vector<std::string>;

TEST(CheckScene, AcceptsAGoodScene) { EXPECT_TRUE(check_scene(unit_square()).empty()); }

TEST(CheckScene, SceneWithoutEmittersIsValid) {
    Scene scene = unit_square();
    scene.surfaces.push_back({"box", "m", BoxGeometry{{0, 0, 0}, {1, 1, 1}, false}});
    EXPECT_TRUE(check_scene(scene).empty());
}

TEST(CheckScene, EmptyScene) { EXPECT_EQ(pointers(Scene{}), Pointers{"/surfaces"}); }

TEST(CheckScene, NonFiniteCoordinate) {
    Scene scene = unit_square();
    std::get<Polygon>(scene.surfaces[0].geometry)[2].y = std::numeric_limits<double>::infinity();
    EXPECT_EQ(pointers(scene), Pointers{"/surfaces/0/polygon/2/1"});
}

TEST(CheckScene, ReflectanceRange) {
    Scene scene = unit_square();
    scene.materials[0].reflectance = {1.0, 1.0, 1.0};
    EXPECT_EQ(pointers(scene), Pointers{"/materials/m/reflectance"});
    scene.materials[0].rgb_reflectance = true;
    scene.materials[0].reflectance = {0.5, -0.1, 0.5};
    EXPECT_EQ(pointers(scene), Pointers{"/materials/m/reflectance/1"});
}

TEST(CheckScene, NegativeEmission) {
    Scene scene = unit_square();
    scene.materials[0].emission = Emission{Emission::Kind::flux, -1, std::nullopt, {}};
    EXPECT_EQ(pointers(scene), Pointers{"/materials/m/emission/flux"});
}

TEST(CheckScene, PolygonShape) {
    Scene scene = unit_square();
    scene.surfaces[0].geometry = Polygon{{0, 0, 0}, {1, 0, 0}};
    EXPECT_EQ(pointers(scene), Pointers{"/surfaces/0/polygon"});
    scene.surfaces[0].geometry = Polygon{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    EXPECT_EQ(pointers(scene), Pointers{"/surfaces/0/polygon"});
    scene.surfaces[0].geometry = Polygon{{0, 0, 0}, {1, 0, 0}, {1, 1, 0.1}, {0, 1, 0}};
    EXPECT_EQ(pointers(scene), Pointers{"/surfaces/0/polygon"});
}

// A polygon or face of more vertices than the limit is refused before its triangulation, which
// takes time in the square of them: a star of 100 000 vertices took 14 s to prepare.
TEST(CheckScene, PolygonsAndFacesOfTooManyVerticesAreRefused) {
    const SceneLimits limits;
    auto circle = [](std::size_t n) {
        Polygon out;
        for (std::size_t k = 0; k < n; ++k) {
            const double a =
                2 * 3.141592653589793 * static_cast<double>(k) / static_cast<double>(n);
            out.push_back({std::cos(a), std::sin(a), 0});
        }
        return out;
    };
    Scene scene = unit_square();
    scene.surfaces[0].geometry = circle(limits.max_polygon_vertices);
    EXPECT_TRUE(check_scene(scene).empty());
    scene.surfaces[0].geometry = circle(limits.max_polygon_vertices + 1);
    EXPECT_EQ(pointers(scene), Pointers{"/surfaces/0/polygon"});
    // One face naming the same three vertices over and over costs a few bytes a vertex.
    MeshGeometry mesh{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 1, 2}, {}}};
    for (std::size_t k = 0; k <= limits.max_polygon_vertices; ++k)
        mesh.faces[1].push_back(static_cast<int>(k % 3));
    scene.surfaces[0].geometry = mesh;
    EXPECT_EQ(
        pointers(scene),
        Pointers{"/surfaces/0/mesh/faces/1"});  // Polygons of many vertices count together: ten of
                                                // the largest fit, the eleventh does not.
    scene.surfaces.assign(10, scene.surfaces[0]);
    for (Surface& s : scene.surfaces) s.geometry = circle(limits.max_polygon_vertices);
    EXPECT_TRUE(check_scene(scene).empty());
    scene.surfaces.push_back(scene.surfaces[0]);
    EXPECT_EQ(pointers(scene), Pointers{"/surfaces"});
}

TEST(CheckScene, ToleranceIsRelativeToSize) {
    Scene scene = unit_square();
    // A 1 µm square 1e-7 µm off its plane is fine; units must not matter.
    scene.surfaces[0].geometry =
        Polygon{{0, 0, 0}, {1e-6, 0, 0}, {1e-6, 1e-6, 1e-13}, {0, 1e-6, 0}};
    EXPECT_TRUE(check_scene(scene).empty());
}

TEST(CheckScene, MeshFaces) {
    Scene scene = unit_square();
    scene.surfaces[0].geometry =
        MeshGeometry{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 1, 2}, {0, 1, 5}, {0, 1}, {0, 1, 1}}};
    EXPECT_EQ(pointers(scene), (Pointers{"/surfaces/0/mesh/faces/1/2", "/surfaces/0/mesh/faces/2",
                                         "/surfaces/0/mesh/faces/3"}));
}

TEST(CheckScene, UnknownMaterialAndInvertedBox) {
    Scene scene = unit_square();
    scene.surfaces.push_back({"b", "nope", BoxGeometry{{0, 0, 0}, {1, 0, 1}, true}});
    EXPECT_EQ(pointers(scene), (Pointers{"/surfaces/1/material", "/surfaces/1/box"}));
}

TEST(CheckScene, ZeroNormalAndAim) {
    Scene scene = unit_square();
    SensorSet zero_normal;
    zero_normal.name = "s";
    zero_normal.points = {{0, 0, 1}};
    zero_normal.normal = {0, 0, 0};
    scene.sensors.push_back(zero_normal);
    Luminaire l;
    l.flux_lm = 1;
    l.aim = {0, 0, 0};
    scene.luminaires.push_back(l);
    EXPECT_EQ(pointers(scene), (Pointers{"/luminaires/0/aim", "/sensors/0/normal"}));
}

// A table carries its own flux; its angles must describe one of the file symmetries.
TEST(CheckScene, PhotometricTables) {
    Scene scene = unit_square();
    Luminaire l;
    l.distribution = Distribution::photometric;
    l.photometry = PhotometricTable{{0, 90}, {0, 90}, {100, 0, 100, 0}, {}};
    scene.luminaires = {l};
    EXPECT_EQ(pointers(scene), Pointers{});
    scene.luminaires[0].photometry->c_deg = {0, 45};
    scene.luminaires[0].rotation_deg = std::numeric_limits<double>::infinity();
    EXPECT_EQ(pointers(scene), (Pointers{"/luminaires/0/distribution", "/luminaires/0/rotation"}));
    scene.luminaires[0].photometry = PhotometricTable{{0, 90}, {0}, {0, 0}, {}};
    scene.luminaires[0].rotation_deg = 0;
    EXPECT_EQ(pointers(scene), Pointers{"/luminaires/0/distribution"});
}

TEST(CheckScene, Settings) {
    Scene scene = unit_square();
    scene.settings.tolerance = 0;
    scene.settings.max_seconds = -1;
    EXPECT_EQ(pointers(scene), (Pointers{"/settings/tolerance", "/settings/max_seconds"}));
}

TEST(CheckScene, Limits) {
    Scene scene = unit_square();
    SceneLimits limits;
    limits.max_vertices = 3;
    EXPECT_EQ(pointers(scene, limits), Pointers{"/surfaces"});
}

TEST(CheckScene, DuplicateSurfaceNamesAreAllowed) {
    Scene scene = unit_square();
    scene.surfaces.push_back(scene.surfaces[0]);
    EXPECT_TRUE(check_scene(scene).empty());
}

}  // namespace
}  // namespace radiant
