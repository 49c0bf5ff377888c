// The light tree: its draws are the probabilities it reports, and the direct light it samples
// on a hall of many sources is the exact direct light on average (none lost, none counted twice),
// also where a wall hides half of them, or a shade half of one large panel.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>

#include "formfactor/luminaire_light.h"
#include "formfactor/point_polygon.h"
#include "montecarlo/element_mesh.h"
#include "montecarlo/light_sources.h"
#include "montecarlo/light_tree.h"
#include "scene/prepared_scene.h"
#include "scene_builder.h"

namespace radiant {
namespace {

std::vector<LightTreeSource> scattered_sources(int count) {
    std::vector<LightTreeSource> out;
    SampleStream rng(5, 0, 0);
    for (int i = 0; i < count; ++i) {
        const Vec3 c{10 * rng.next(), 10 * rng.next(), 2 + rng.next()};
        Box b;
        b.add(c - Vec3{0.2, 0.2, 0});
        b.add(c + Vec3{0.2, 0.2, 0});
        const double power = 100 + 1000 * rng.next();
        out.push_back({b, power, power / 3});
    }
    return out;
}

TEST(LightTree, DrawsEachSourceWithTheProbabilityItReports) {
    const std::vector<LightTreeSource> sources = scattered_sources(37);
    const LightTree tree(sources);
    const Vec3 x{3, 4, 0.8}, n{0, 0, 1};
    const auto leaf = [&](std::size_t s) {
        return sources[s].power / length_squared(sources[s].bounds.centre() - x);
    };
    double total = 0;
    for (std::size_t s = 0; s < sources.size(); ++s) total += tree.probability(s, x, n, leaf);
    EXPECT_NEAR(total, 1, 1e-12);

    const int draws = 200000;
    std::map<std::size_t, int> count;
    for (int k = 0; k < draws; ++k) {
        SampleStream rng(7, 1, static_cast<std::uint64_t>(k));
        std::size_t s = 0;
        double p = 0;
        ASSERT_TRUE(tree.draw(x, n, rng.next(), leaf, s, p));
        EXPECT_NEAR(p, tree.probability(s, x, n, leaf), 1e-12);
        ++count[s];
    }
    for (std::size_t s = 0; s < sources.size(); ++s) {
        const double p = tree.probability(s, x, n, leaf);
        const double sigma = std::sqrt(p * (1 - p) / draws);
        EXPECT_NEAR(static_cast<double>(count[s]) / draws, p, 5 * sigma + 1e-12) << "source " << s;
    }
}

TEST(LightTree, CutsEverySourceInFrontOnceAndLeavesOutThoseBehind) {
    std::vector<LightTreeSource> sources = scattered_sources(200);
    const LightTree tree(sources);
    const Vec3 x{5, 5, 2.5}, n{0, 0, 1};  // sources below z = 2.5 are behind
    const LightCut cut = tree.cut(x, n, 0.01, 32);
    EXPECT_LE(cut.sources.size() + cut.clusters.size(), 32u);
    EXPECT_FALSE(cut.clusters.empty());
    // Draw every cluster by power many times: the sources reached, with the cut's own, hold
    // each source that is not wholly behind x once; one behind is at most in a cluster (where
    // it sends nothing).
    std::map<std::size_t, int> seen;
    for (const std::size_t s : cut.sources) ++seen[s];
    for (const int c : cut.clusters) {
        std::map<std::size_t, bool> reached;
        for (int k = 0; k < 20000; ++k) {
            SampleStream rng(9, static_cast<std::uint64_t>(c), static_cast<std::uint64_t>(k));
            double p = 0;
            reached[tree.draw_by_power(c, rng.next(), p)] = true;
        }
        for (const auto& [s, yes] : reached) ++seen[s];
    }
    for (std::size_t s = 0; s < sources.size(); ++s) {
        const bool in_front = sources[s].bounds.hi.z > x.z;
        const int times = seen.count(s) ? seen[s] : 0;
        if (in_front) {
            EXPECT_EQ(times, 1) << "source " << s;
        } else {
            EXPECT_LE(times, 1) << "source " << s;
        }
    }
}

// 400 small sources over a sphere, each facing out: seen from below, the upper half faces away.
TEST(LightTree, MostWaysDownEndAtSourcesThatFaceThePoint) {
    std::vector<LightTreeSource> sources;
    const Vec3 centre{0, 0, 3};
    SampleStream rng(3, 0, 0);
    for (int i = 0; i < 400; ++i) {
        const double z = 2 * rng.next() - 1, a = 2 * std::numbers::pi * rng.next();
        const double r = std::sqrt(1 - z * z);
        const Vec3 normal{r * std::cos(a), r * std::sin(a), z};
        Box b;
        b.add(centre + normal - Vec3{0.01, 0.01, 0.01});
        b.add(centre + normal + Vec3{0.01, 0.01, 0.01});
        sources.push_back({b, 10, 10 / std::numbers::pi, normal});
    }
    const LightTree tree(sources);
    const Vec3 x{0.3, 0.2, 0}, n{0, 0, 1};
    const auto faces_x = [&](std::size_t s) {
        return dot(sources[s].normal, x - sources[s].bounds.centre()) > 0;
    };
    // Importance that knows each source's front, as LightSources' rough light does.
    const auto leaf = [&](std::size_t s) {
        const Vec3 d = x - sources[s].bounds.centre();
        return faces_x(s) ? dot(sources[s].normal, d) / std::pow(length_squared(d), 1.5) : 0.0;
    };
    // The share of ways down that end at a source: clusters that straddle the sphere's rim as
    // seen from x still lead to some that face away (blind to the fronts, 0.42 of them did).
    double total = 0;
    for (std::size_t s = 0; s < sources.size(); ++s) total += tree.probability(s, x, n, leaf);
    EXPECT_GT(total, 0.7);
    int found = 0;
    for (int k = 0; k < 20000; ++k) {
        SampleStream draw(5, 1, static_cast<std::uint64_t>(k));
        std::size_t s = 0;
        double p = 0;
        if (!tree.draw(x, n, draw.next(), leaf, s, p)) continue;
        ++found;
        EXPECT_TRUE(faces_x(s)) << "source " << s;
    }
    EXPECT_NEAR(found / 20000.0, total, 0.02);
    // The cut leaves the clusters of the far half out, so the near half's sources fit in it.
    const LightCut cut = tree.cut(x, n, 0.01, 64);
    for (const std::size_t s : cut.sources) EXPECT_TRUE(faces_x(s)) << "source " << s;
}

// A 16 × 8 m hall with 8 × 4 panels hung under its ceiling and a row of 12 downlights; with
// `wall`, a wall at x = 8 splits it into two rooms.
Scene hall(bool wall) {
    Scene scene;
    scene.name = "hall";
    scene.materials = {testing::gray("wall", 0.5), testing::gray("panel", 0.5, 2000)};
    scene.surfaces = testing::closed_room(16, 8, 3, "wall");
    for (Surface& panel : testing::ceiling_tiles("panel", "panel", 8, 4, 0.7, 0.7, 2, 0.6, 2.95))
        scene.surfaces.push_back(std::move(panel));
    for (int i = 0; i < 12; ++i) {
        scene.luminaires.push_back(testing::luminaire("downlight-" + std::to_string(i),
                                                      {0.5 + 1.25 * i + 0.1, 4, 2.5}, 800,
                                                      Distribution::lambertian));
    }
    if (wall) {
        scene.surfaces.push_back(testing::polygon_surface(
            "wall-west-side", "wall", testing::rect({8, 0, 0}, {0, 0, 3}, {0, 8, 0})));
        scene.surfaces.push_back(testing::polygon_surface(
            "wall-east-side", "wall", testing::rect({8, 0, 0}, {0, 8, 0}, {0, 0, 3})));
    }
    scene.sensors.push_back(
        testing::sensor_points("points", {{3.1, 2.3, 0.8}, {12.4, 6.1, 0.8}, {7.6, 4.2, 1.2}}));
    return scene;
}

// The exact direct light at x: every source on x's side of the wall (or all), unoccluded.
double exact_direct(const PreparedScene& scene, const Vec3& x, const Vec3& n, bool wall) {
    const double wall_x = 8 - scene.world_origin.x;
    const auto same_side = [&](const Vec3& p) { return !wall || (p.x < wall_x) == (x.x < wall_x); };
    double sum = 0;
    for (const PreparedLuminaire& l : scene.luminaires) {
        if (same_side(l.position)) sum += l.flux_lm[0] * direct_kernel_per_lm(l, x, n);
    }
    for (const Piece& p : scene.pieces) {
        const PreparedMaterial& m = scene.materials[static_cast<std::size_t>(p.material)];
        if (!m.emits() || !same_side(p.vertices[0])) continue;
        sum += m.exitance_lm_m2[0] * front_point_to_polygon_factor(x, n, p.vertices, p.normal);
    }
    return sum;
}

struct Mean {
    double mean = 0, standard_error = 0;
};

template <class Sample>
Mean mean_of(int n, const Sample& sample) {
    double sum = 0, sum2 = 0;
    for (int k = 0; k < n; ++k) {
        const double v = sample(k);
        sum += v;
        sum2 += v * v;
    }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

TEST(LightSources, SampleTheExactDirectLightOfManySourcesOnAverage) {
    for (const bool wall : {false, true}) {
        const PreparedScene scene = prepare_scene(hall(wall));
        const ElementMesh mesh(scene, {1.0});
        const std::unique_ptr<Visibility> visibility = make_embree_visibility(mesh.triangles());
        const LightSources sources(scene, visibility->epsilon());
        const Vec3 up{0, 0, 1};
        for (const Vec3& x : scene.sensors[0].points) {
            const double exact = exact_direct(scene, x, up, wall);
            std::uint64_t rays = 0;
            const LightSources::SensorSources seen = sources.sensor_sources(
                x, SensorReceiver(SensorKind::planar, up), *visibility, true, rays);
            EXPECT_FALSE(seen.clusters.empty());  // 44 sources: more than a cut holds
            const Mean at_sensor = mean_of(2000, [&](int k) {
                SampleStream rng(11, 0, static_cast<std::uint64_t>(k));
                return seen.luminaires[0] +
                       sources.sensor_set_light(seen, x, up, *visibility, rng, rays)[0];
            });
            EXPECT_NEAR(at_sensor.mean, exact, 4 * at_sensor.standard_error + 1e-9 * exact)
                << "sensor, wall " << wall;
            EXPECT_LT(at_sensor.standard_error, 0.01 * exact);
            const Mean by_draws = mean_of(20000, [&](int k) {
                SampleStream rng(13, 0, static_cast<std::uint64_t>(k));
                return sources.direct_at(x, up, *visibility, rng, rays)[0];
            });
            EXPECT_NEAR(by_draws.mean, exact, 4 * by_draws.standard_error + 1e-9 * exact)
                << "next-event draws, wall " << wall;
            EXPECT_LT(by_draws.standard_error, 0.02 * exact);
        }
    }
}

// Past max_nodes a cut splits only the nodes `seen` lets it: seeing none, it is the cut of
// max_nodes; seeing all, the cut of max_seen_nodes; seeing some, a cut in between that still
// holds every source once.
TEST(LightTree, PastMaxNodesOnlySeenNodesAreSplit) {
    const std::vector<LightTreeSource> sources = scattered_sources(300);
    const LightTree tree(sources);
    const Vec3 x{5, 5, 0.8}, n{0, 0, 1};
    const auto same = [](const LightCut& a, const LightCut& b) {
        return a.sources == b.sources && a.clusters == b.clusters;
    };
    const LightCut small = tree.cut(x, n, 0.001, 8), large = tree.cut(x, n, 0.001, 64);
    ASSERT_GT(large.sources.size(), small.sources.size());
    EXPECT_TRUE(same(tree.cut(x, n, 0.001, 8, 64, [](int) { return false; }), small));
    EXPECT_TRUE(same(tree.cut(x, n, 0.001, 8, 64, [](int) { return true; }), large));
    std::vector<int> asked;
    const LightCut some = tree.cut(x, n, 0.001, 8, 64, [&](int node) {
        asked.push_back(node);
        return node % 2 == 0;
    });
    EXPECT_FALSE(asked.empty());
    EXPECT_LE(some.sources.size() + some.clusters.size(), 64u);
    EXPECT_GT(some.sources.size() + some.clusters.size(), 8u);
    // Still every source once (all are in front of x): on its own or in one cluster.
    std::map<std::size_t, int> times;
    for (const std::size_t source : some.sources) ++times[source];
    for (const int c : some.clusters) {
        std::map<std::size_t, bool> reached;
        for (int k = 0; k < 20000; ++k) {
            double p = 0;
            reached[tree.draw_by_power(c, (k + 0.5) / 20000, p)] = true;
        }
        for (const auto& [source, yes] : reached) ++times[source];
    }
    EXPECT_EQ(times.size(), sources.size());
    for (const auto& [source, count] : times) EXPECT_EQ(count, 1) << "source " << source;
}

// A lamp: a bulb of 96 faces in a black shade open below, and a sensor below and beside it
// that sees half the bulb's lower half through the opening, with a second such lamp farther
// off. The sensor's cut lists the pieces it sees on their own (a cluster drawn by power spent
// most draws on pieces the shade hides or that face away: a spread of 8.8 % of the light per
// set, where it is now 0.7 %).
TEST(LightSources, ASensorBesideALampsBulbSamplesEachPieceItSees) {
    Scene scene;
    scene.materials = {testing::gray("black", 0), testing::gray("bulb", 0, 20000)};
    for (const double at : {0.0, 1.5}) {
        scene.surfaces.push_back(
            testing::sphere_surface("bulb " + std::to_string(at), "bulb", {at, 0, 2}, 0.1, 8, 12));
        // The shade: a black box around the bulb's upper part, without a bottom.
        const Vec3 lo{at - 0.2, -0.2, 1.95};
        const double w = 0.4, h = 0.35;
        const std::vector<Polygon> sides = {
            testing::rect(lo + Vec3{0, 0, h}, {w, 0, 0}, {0, w, 0}),
            testing::rect(lo, {w, 0, 0}, {0, 0, h}), testing::rect(lo, {0, w, 0}, {0, 0, h}),
            testing::rect(lo + Vec3{w, 0, 0}, {0, w, 0}, {0, 0, h}),
            testing::rect(lo + Vec3{0, w, 0}, {w, 0, 0}, {0, 0, h})};
        for (std::size_t k = 0; k < sides.size(); ++k) {
            scene.surfaces.push_back(testing::polygon_surface(
                "shade " + std::to_string(at) + " " + std::to_string(k), "black", sides[k]));
        }
    }
    const PreparedScene prepared = prepare_scene(scene);
    const ElementMesh mesh(prepared, {1.0});
    const std::unique_ptr<Visibility> visibility = make_embree_visibility(mesh.triangles());
    const LightSources sources(prepared, visibility->epsilon());
    const Vec3 x = Vec3{0.5, 0.1, 0.8} - prepared.world_origin, up{0, 0, 1};
    std::uint64_t rays = 0;
    const LightSources::SensorSources seen =
        sources.sensor_sources(x, SensorReceiver(SensorKind::planar, up), *visibility, true, rays);
    const Mean at_sensor = mean_of(4000, [&](int k) {
        SampleStream rng(23, 0, static_cast<std::uint64_t>(k));
        return sources.sensor_set_light(seen, x, up, *visibility, rng, rays)[0];
    });
    ASSERT_GT(at_sensor.mean, 0);
    EXPECT_LT(at_sensor.standard_error * std::sqrt(4000.0), 0.02 * at_sensor.mean);
}

// Two bulbs of 96 faces, one of them shut in a black box: at the point below the open one, each
// emitting surface gets a draw of its own among its pieces, and no draw is spent on the shut
// bulb's pieces that the box hides (drawn from both bulbs' 192 pieces at once, half the draws
// went to it and found nothing: a standard error of 1.4 % of the light where it is now 0.39 %).
TEST(LightSources, EachEmittingSurfaceGetsADrawOfItsOwn) {
    Scene scene;
    scene.materials = {testing::gray("black", 0), testing::gray("bulb", 0, 20000)};
    scene.surfaces.push_back(testing::sphere_surface("open bulb", "bulb", {0, 0, 2}, 0.1, 8, 12));
    scene.surfaces.push_back(testing::sphere_surface("shut bulb", "bulb", {1, 0, 2}, 0.1, 8, 12));
    scene.surfaces.push_back(
        testing::box_surface("box", "black", {0.8, -0.2, 1.8}, {1.2, 0.2, 2.2}, false));
    const PreparedScene prepared = prepare_scene(scene);
    const ElementMesh mesh(prepared, {1.0});
    const std::unique_ptr<Visibility> visibility = make_embree_visibility(mesh.triangles());
    const LightSources sources(prepared, visibility->epsilon());
    const Vec3 x = Vec3{0.6, 0.1, 0} - prepared.world_origin, up{0, 0, 1};
    double exact = 0;
    for (const Piece& p : prepared.pieces) {
        if (prepared.surface_names[static_cast<std::size_t>(p.surface)] == "open bulb")
            exact += 20000 * front_point_to_polygon_factor(x, up, p.vertices, p.normal);
    }
    std::uint64_t rays = 0;
    const Mean by_draws = mean_of(4000, [&](int k) {
        SampleStream rng(19, 0, static_cast<std::uint64_t>(k));
        return sources.direct_at(x, up, *visibility, rng, rays)[0];
    });
    EXPECT_NEAR(by_draws.mean, exact, 4 * by_draws.standard_error);
    EXPECT_LT(by_draws.standard_error, 0.007 * exact);
}

// A 2 m panel 2.2 m above a point, its end x < 0.7 m behind a black shade 1 mm under it; the
// point lies under the open part, whose light is 2.8 times the shaded end's. It gets the open
// part's light: the whole panel's factor times the share of points seen (the old estimate)
// gives 0.65 × the whole's, 11 % short.
TEST(LightSources, APartlyShadedPanelGivesItsOpenPartsLight) {
    Scene scene;
    scene.materials = {testing::gray("black", 0), testing::gray("panel", 0.5, 1000)};
    scene.surfaces.push_back(
        testing::polygon_surface("panel", "panel", testing::ceiling_rect(0, 2, 0, 2, 3)));
    scene.surfaces.push_back(
        testing::polygon_surface("shade", "black", testing::ceiling_rect(0, 0.7, 0, 2, 2.999)));
    scene.sensors.push_back(testing::sensor_points("point", {{1.5, 1, 0.8}}));
    const PreparedScene prepared = prepare_scene(scene);
    const ElementMesh mesh(prepared, {1.0});
    const std::unique_ptr<Visibility> visibility = make_embree_visibility(mesh.triangles());
    const LightSources sources(prepared, visibility->epsilon());
    const Vec3 x = prepared.sensors[0].points[0], up{0, 0, 1}, down{0, 0, -1};
    const Vec3 o = prepared.world_origin;
    const std::vector<Vec3> open_part{Vec3{0.7, 0, 3} - o, Vec3{0.7, 2, 3} - o, Vec3{2, 2, 3} - o,
                                      Vec3{2, 0, 3} - o};
    const double exact = 1000 * front_point_to_polygon_factor(x, up, open_part, down);
    std::uint64_t rays = 0;
    const LightSources::SensorSources seen =
        sources.sensor_sources(x, SensorReceiver(SensorKind::planar, up), *visibility, true, rays);
    const Mean at_sensor = mean_of(4000, [&](int k) {
        SampleStream rng(17, 0, static_cast<std::uint64_t>(k));
        return sources.sensor_set_light(seen, x, up, *visibility, rng, rays)[0];
    });
    // The shade's 1 mm below the panel moves its shadow's edge by under 0.1 % of the light.
    EXPECT_NEAR(at_sensor.mean, exact, 4 * at_sensor.standard_error + 3e-3 * exact);
    EXPECT_LT(at_sensor.standard_error, 0.01 * exact);
}

}  // namespace
}  // namespace radiant
