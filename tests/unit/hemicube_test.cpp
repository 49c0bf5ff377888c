// Ray-cast hemicube against Lambert's exact point-to-polygon factor in a closed unit cube.
#include "formfactor/hemicube.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "formfactor/point_polygon.h"
#include "formfactor/quadrature.h"

namespace radiant {

namespace {

using Quad = std::array<Vec3, 4>;

// Unit cube faces with inward normals: floor, ceiling, y = 0, y = 1, x = 0, x = 1.
std::array<Quad, 6> cube_faces() {
    const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    const auto rect = [](const Vec3& o, const Vec3& a, const Vec3& b) {
        return Quad{o, o + a, o + a + b, o + b};
    };
    return {rect({}, x, y), rect(z, y, x),  rect({}, z, x),
            rect(y, x, z),  rect({}, y, z), rect(x, z, y)};
}

struct Scene {
    std::array<Quad, 6> faces = cube_faces();
    std::vector<Triangle> triangles;
    std::vector<int> patch;
    Scene() {
        for (int f = 0; f < 6; ++f) {
            const Quad& q = faces[f];
            triangles.push_back({q[0], q[1], q[2]});
            triangles.push_back({q[0], q[2], q[3]});
            patch.insert(patch.end(), {f, f});
        }
    }
};

TEST(Hemicube, PointFactorsMatchLambertInsideCube) {
    const Scene scene;
    const auto vis_ptr = make_brute_force_visibility(scene.triangles);
    const Visibility& vis = *vis_ptr;
    struct Probe {
        Vec3 x, n;
    };
    const Probe probes[] = {{{0.5, 0.5, 1e-12}, {0, 0, 1}},
                            {{0.5, 0.5, 0.5}, normalized({0.3, -0.5, 0.8})},
                            {{0.4, 0.6, 0.5}, {0, 0, -1}},
                            {{0.2, 0.7, 0.3}, normalized({-1, 0.2, -0.1})}};
    for (const Probe& p : probes) {
        const auto f = hemicube_factors(p.x, p.n, 128, vis, scene.patch, 6);
        double total = 0.0;
        for (int j = 0; j < 6; ++j) {
            const double exact = point_to_polygon_factor(p.x, p.n, scene.faces[j]);
            EXPECT_NEAR(f[j], exact, 0.02 * exact + 1e-4) << "face " << j;
            total += f[j];
        }
        EXPECT_NEAR(total, 1.0, 1e-3);
    }
}

TEST(Hemicube, AreaAveragedCubeFactors) {
    // Hemicubes at degree-5 points of the floor split 2 × 2 (points off the shared edges).
    const Scene scene;
    const auto vis_ptr = make_brute_force_visibility(scene.triangles);
    const Visibility& vis = *vis_ptr;
    std::array<double, 6> sum{};
    for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) {
            const std::vector<Vec3> sub{{0.5 * i, 0.5 * j, 0},
                                        {0.5 * i + 0.5, 0.5 * j, 0},
                                        {0.5 * i + 0.5, 0.5 * j + 0.5, 0},
                                        {0.5 * i, 0.5 * j + 0.5, 0}};
            for (const auto& q : polygon_quadrature(sub, 5)) {
                const auto f = hemicube_factors(q.position, {0, 0, 1}, 128, vis, scene.patch, 6);
                for (int k = 0; k < 6; ++k) sum[k] += q.weight * f[k];
            }
        }
    }
    EXPECT_EQ(sum[0], 0.0);
    EXPECT_NEAR(sum[1], 0.199825, 0.02 * 0.199825);
    for (int k = 2; k < 6; ++k) EXPECT_NEAR(sum[k], 0.200044, 0.02 * 0.200044) << "face " << k;
    EXPECT_NEAR(sum[1] + sum[2] + sum[3] + sum[4] + sum[5], 1.0, 1e-3);
}

TEST(Hemicube, UnmappedTrianglesAndZeroNormalAreIgnored) {
    const Scene scene;
    const auto vis_ptr = make_brute_force_visibility(scene.triangles);
    const Visibility& vis = *vis_ptr;
    const std::vector<int> none(scene.triangles.size(), -1);
    for (const double f : hemicube_factors({0.5, 0.5, 0.5}, {0, 0, 1}, 16, vis, none, 6)) {
        EXPECT_EQ(f, 0.0);
    }
    for (const double f : hemicube_factors({0.5, 0.5, 0.5}, {}, 16, vis, scene.patch, 6)) {
        EXPECT_EQ(f, 0.0);
    }
}

}  // namespace
}  // namespace radiant
