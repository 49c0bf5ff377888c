// Visibility: Embree against the double-precision brute-force oracle, plus the hard cases of
// validation/README.md §5.4 (light leaks through thin walls) and §5.7 (huge scale range).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "parallel/fork_join.h"
#include "visibility/visibility.h"

namespace radiant {
namespace {

constexpr double kSegmentEnd = 1.0 - 1e-6;  // the interface's margin at the target

// ---------------------------------------------------------------------------------------------
// Scene building

void add_quad(std::vector<Triangle>& tris, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
    tris.push_back({a, b, c});
    tris.push_back({a, c, d});
}

/// Axis-aligned box surface, 12 triangles.
void add_box(std::vector<Triangle>& tris, Vec3 lo, Vec3 hi) {
    const auto p = [&](int i, int j, int k) {
        return Vec3{i ? hi.x : lo.x, j ? hi.y : lo.y, k ? hi.z : lo.z};
    };
    add_quad(tris, p(0, 0, 0), p(1, 0, 0), p(1, 1, 0), p(0, 1, 0));  // z = lo
    add_quad(tris, p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1));  // z = hi
    add_quad(tris, p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1));  // y = lo
    add_quad(tris, p(0, 1, 0), p(1, 1, 0), p(1, 1, 1), p(0, 1, 1));  // y = hi
    add_quad(tris, p(0, 0, 0), p(0, 1, 0), p(0, 1, 1), p(0, 0, 1));  // x = lo
    add_quad(tris, p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1));  // x = hi
}

std::vector<Triangle> transformed(std::vector<Triangle> tris, double scale, Vec3 offset) {
    for (Triangle& t : tris)
        for (Vec3* v : {&t.a, &t.b, &t.c}) *v = *v * scale + offset;
    return tris;
}

Vec3 bbox_centre(const std::vector<Triangle>& tris) {
    Vec3 lo{1e300, 1e300, 1e300}, hi = -lo;
    for (const Triangle& t : tris)
        for (const Vec3* v : {&t.a, &t.b, &t.c})
            for (int i = 0; i < 3; ++i) {
                lo[i] = std::min(lo[i], (*v)[i]);
                hi[i] = std::max(hi[i], (*v)[i]);
            }
    return 0.5 * (lo + hi);
}

Vec3 random_in_box(std::mt19937_64& rng, Vec3 lo, Vec3 hi) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return {lo.x + u(rng) * (hi.x - lo.x), lo.y + u(rng) * (hi.y - lo.y),
            lo.z + u(rng) * (hi.z - lo.z)};
}

Vec3 random_unit(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    for (;;) {
        const Vec3 v{n(rng), n(rng), n(rng)};
        if (length(v) > 1e-3) return normalized(v);
    }
}

/// ~200 random triangles (0.05–1 m) in a 4 m cube, plus degenerate ones interleaved so that
/// index mapping past skipped triangles is exercised.
std::vector<Triangle> random_scene(std::mt19937_64& rng) {
    std::vector<Triangle> tris;
    std::uniform_real_distribution<double> size(0.05, 1.0);
    for (int i = 0; i < 200; ++i) {
        if (i % 37 == 5) {
            const Vec3 a = random_in_box(rng, {-2, -2, -2}, {2, 2, 2});
            const Vec3 d = random_unit(rng);
            tris.push_back({a, a + d, a + 2.0 * d});  // collinear
            tris.push_back({a, a, a + d});            // repeated vertex
        }
        if (i == 100) {
            const double nan = std::numeric_limits<double>::quiet_NaN();
            tris.push_back({{nan, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        }
        const Vec3 c = random_in_box(rng, {-2, -2, -2}, {2, 2, 2});
        const double s = size(rng);
        tris.push_back(
            {c + s * random_unit(rng), c + s * random_unit(rng), c + s * random_unit(rng)});
    }
    return tris;
}

// ---------------------------------------------------------------------------------------------
// Ambiguity filter: float (Embree) and double (oracle) may legitimately differ when a segment
// passes within float round-off of a triangle edge, ends on a triangle, or grazes a plane.
// Such queries are regenerated, so the comparisons below can demand exact agreement.

/// True when segment o + t·dir, t in [0, t_end], comes within `d` (metres, perpendicular) of
/// deciding differently for `tri`; *t_hit receives t for a clear-cut hit, else stays.
bool ambiguous(const Triangle& tri, const Vec3& o, const Vec3& dir, double t_end, double d,
               double* t_hit) {
    if (is_degenerate(tri)) return false;
    const Vec3 n = normalized(cross(tri.b - tri.a, tri.c - tri.a));
    const double dist_o = dot(o - tri.a, n);
    const double dist_e = dot(o + t_end * dir - tri.a, n);
    if (dist_o * dist_e > 0.0 && std::min(std::abs(dist_o), std::abs(dist_e)) >= d)
        return false;  // the segment clearly stays on one side of the plane
    const double rate = dot(dir, n);
    const double sine = std::abs(rate) / length(dir);
    if (sine < 1e-9) return true;  // lies in the plane
    const double t = -dist_o / rate;
    const Vec3 p = o + t * dir;
    // Signed in-plane distance to the three edge lines, positive inside.
    const Vec3* v[3] = {&tri.a, &tri.b, &tri.c};
    double m = std::numeric_limits<double>::max();
    for (int i = 0; i < 3; ++i) {
        const Vec3 e = *v[(i + 1) % 3] - *v[i];
        m = std::min(m, dot(cross(e, p - *v[i]), n) / length(e));
    }
    const double d_edge = d / sine;  // a perpendicular error d moves the crossing by d/sin
    if (m <= -d_edge) return false;  // clearly misses the triangle
    if (m < d_edge) return true;     // near an edge or vertex
    if (std::abs(dist_o) < d || std::abs(dist_e) < d) return true;  // ends near the surface
    *t_hit = t;
    return false;
}

/// True when no triangle makes the segment query ambiguous and the two nearest hits (for
/// first_hit) are well separated.
bool clear_cut(const std::vector<Triangle>& tris, const Vec3& o, const Vec3& dir, double t_end,
               double d) {
    double first = std::numeric_limits<double>::infinity();
    double second = first;
    for (const Triangle& tri : tris) {
        double t = -1.0;
        if (ambiguous(tri, o, dir, t_end, d, &t)) return false;
        if (t > 0.0 && t < t_end) {
            if (t < first) {
                second = first;
                first = t;
            } else {
                second = std::min(second, t);
            }
        }
    }
    return !(std::isfinite(second) && (second - first) * length(dir) < 10 * d);
}

/// `count` clear-cut segments from a point in box A to a point in box B.
std::vector<SegmentQuery> clear_queries(const std::vector<Triangle>& tris, std::mt19937_64& rng,
                                        std::size_t count, Vec3 lo_a, Vec3 hi_a, Vec3 lo_b,
                                        Vec3 hi_b, double d, std::size_t* rejected = nullptr) {
    std::vector<SegmentQuery> queries;
    std::size_t rejects = 0;
    while (queries.size() < count) {
        const Vec3 a = random_in_box(rng, lo_a, hi_a);
        const Vec3 b = random_in_box(rng, lo_b, hi_b);
        if (clear_cut(tris, a, b - a, kSegmentEnd, d))
            queries.push_back({a, b});
        else
            ++rejects;
    }
    if (rejected) *rejected = rejects;
    return queries;
}

// ---------------------------------------------------------------------------------------------
// (a), (b): agreement with the oracle

TEST(Visibility, EmbreeAgreesWithBruteForceOnRandomSegments) {
    std::mt19937_64 rng(12345);
    const auto tris = random_scene(rng);
    const auto embree = make_embree_visibility(tris);
    const auto brute = make_brute_force_visibility(tris);
    std::size_t rejected = 0;
    const auto queries = clear_queries(tris, rng, 20000, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5},
                                       {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5}, 1e-5, &rejected);
    EXPECT_LT(rejected, queries.size() / 20) << "ambiguity filter rejects too much";

    std::size_t disagreements = 0, blocked = 0;
    for (const SegmentQuery& q : queries) {
        const bool e = embree->visible(q.from, q.to);
        const bool b = brute->visible(q.from, q.to);
        disagreements += e != b;
        blocked += !b;
    }
    EXPECT_EQ(disagreements, 0u);
    // Both outcomes must be well represented for the comparison to mean anything.
    EXPECT_GT(blocked, queries.size() / 10);
    EXPECT_LT(blocked, queries.size() * 9 / 10);
}

TEST(Visibility, FirstHitAgreesWithBruteForceAndMapsOriginalIndices) {
    std::mt19937_64 rng(777);
    const auto tris = random_scene(rng);
    const auto embree = make_embree_visibility(tris);
    const auto brute = make_brute_force_visibility(tris);
    std::uniform_real_distribution<double> u(0.0, 1.0);

    std::size_t compared = 0, hits = 0, disagreements = 0;
    int max_index = -1;
    while (compared < 20000) {
        const Vec3 o = random_in_box(rng, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5});
        const Vec3 dir = (0.1 + 3.0 * u(rng)) * random_unit(rng);
        const bool infinite = u(rng) < 0.2;
        const double t_max =
            infinite ? std::numeric_limits<double>::infinity() : (0.5 + 4.5 * u(rng)) / length(dir);
        const double t_end = infinite ? 20.0 / length(dir) : t_max;  // beyond the scene
        if (!clear_cut(tris, o, dir, t_end, 1e-5)) continue;
        ++compared;
        const int e = embree->first_hit(o, dir, t_max);
        const int b = brute->first_hit(o, dir, t_max);
        disagreements += e != b;
        hits += b >= 0;
        max_index = std::max(max_index, b);
    }
    EXPECT_EQ(disagreements, 0u);
    EXPECT_GT(hits, compared / 10);
    EXPECT_GT(max_index, 150);  // hits past the skipped degenerate triangles occur
}

TEST(Visibility, DegenerateTrianglesNeverHitAndEmptySceneIsVisible) {
    const std::vector<Triangle> degenerate = {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}},
                                              {{0, 0, 0}, {0, 0, 0}, {0, 1, 0}}};
    for (const auto& tris : {degenerate, std::vector<Triangle>{}}) {
        for (const auto& vis : {make_embree_visibility(tris), make_brute_force_visibility(tris)}) {
            EXPECT_GT(vis->epsilon(), 0.0);
            EXPECT_TRUE(vis->visible({0.5, -1, 0}, {0.5, 1, 0}));
            EXPECT_EQ(vis->first_hit({0.5, -1, 0}, {0, 1, 0}, 10.0), -1);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// (c): closed rooms and thin walls (validation §5.4)

struct Face {
    Vec3 origin, u, v, inward;  // points origin + s·u + t·v, s, t in [0, 1]
};

/// A point on `face`; coordinates snap close to an edge a third of the time (corner cases).
Vec3 point_on(const Face& f, double eps, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const auto coord = [&](double len) {
        const double r = u(rng);
        if (r < 1.0 / 6) return (eps + 1e-3 * u(rng)) / len;
        if (r < 1.0 / 3) return 1.0 - (eps + 1e-3 * u(rng)) / len;
        return u(rng);
    };
    return f.origin + coord(length(f.u)) * f.u + coord(length(f.v)) * f.v + eps * f.inward;
}

/// Inner faces of the box room [lo, hi].
std::vector<Face> room_faces(Vec3 lo, Vec3 hi) {
    const Vec3 d = hi - lo;
    return {{lo, {d.x, 0, 0}, {0, d.y, 0}, {0, 0, 1}},
            {{lo.x, lo.y, hi.z}, {d.x, 0, 0}, {0, d.y, 0}, {0, 0, -1}},
            {lo, {d.x, 0, 0}, {0, 0, d.z}, {0, 1, 0}},
            {{lo.x, hi.y, lo.z}, {d.x, 0, 0}, {0, 0, d.z}, {0, -1, 0}},
            {lo, {0, d.y, 0}, {0, 0, d.z}, {1, 0, 0}},
            {{hi.x, lo.y, lo.z}, {0, d.y, 0}, {0, 0, d.z}, {-1, 0, 0}}};
}

TEST(Visibility, ClosedRoomWallsSeeEachOther) {
    std::vector<Triangle> tris;
    const Vec3 lo{-2, -2, -1.5}, hi{2, 2, 1.5};
    add_box(tris, lo, hi);
    const auto faces = room_faces(lo, hi);
    std::mt19937_64 rng(5);
    for (const auto& vis : {make_embree_visibility(tris), make_brute_force_visibility(tris)}) {
        const double eps = vis->epsilon();
        int blocked = 0;
        for (int i = 0; i < 20000; ++i) {
            const std::size_t a = rng() % 6, b = (a + 1 + rng() % 5) % 6;
            blocked += !vis->visible(point_on(faces[a], eps, rng), point_on(faces[b], eps, rng));
        }
        EXPECT_EQ(blocked, 0);
    }
}

/// Two 4 × 4 × 3 rooms, A at x < −t/2 and B at x > t/2, sharing one floor and one ceiling
/// polygon that run under/over the partition (§5.4). t = 0: a single two-sided quad.
std::vector<Triangle> two_rooms(double t) {
    std::vector<Triangle> tris;
    const double x0 = -4 - t / 2, x1 = 4 + t / 2;
    add_quad(tris, {x0, -2, 0}, {x1, -2, 0}, {x1, 2, 0}, {x0, 2, 0});  // floor
    add_quad(tris, {x0, -2, 3}, {x1, -2, 3}, {x1, 2, 3}, {x0, 2, 3});  // ceiling
    add_quad(tris, {x0, -2, 0}, {x1, -2, 0}, {x1, -2, 3}, {x0, -2, 3});
    add_quad(tris, {x0, 2, 0}, {x1, 2, 0}, {x1, 2, 3}, {x0, 2, 3});
    add_quad(tris, {x0, -2, 0}, {x0, 2, 0}, {x0, 2, 3}, {x0, -2, 3});
    add_quad(tris, {x1, -2, 0}, {x1, 2, 0}, {x1, 2, 3}, {x1, -2, 3});
    if (t > 0)
        add_box(tris, {-t / 2, -2, 0}, {t / 2, 2, 3});  // stands on the floor
    else
        add_quad(tris, {0, -2, 0}, {0, 2, 0}, {0, 2, 3}, {0, -2, 3});
    return tris;
}

class ThinWall : public ::testing::TestWithParam<double> {};

TEST_P(ThinWall, NothingPassesBetweenRoomsAndEachRoomSeesItself) {
    const double t = GetParam();
    const auto tris = two_rooms(t);
    const auto room_a = room_faces({-4 - t / 2, -2, 0}, {-t / 2, 2, 3});
    const auto room_b = room_faces({t / 2, -2, 0}, {4 + t / 2, 2, 3});
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const auto& vis : {make_embree_visibility(tris), make_brute_force_visibility(tris)}) {
        const double eps = vis->epsilon();
        ASSERT_LT(eps, 1e-4);
        int leaks = 0, self_blocked = 0;
        for (int i = 0; i < 10000; ++i) {
            const Vec3 a = point_on(room_a[rng() % 6], eps, rng);
            const Vec3 b = point_on(room_b[rng() % 6], eps, rng);
            leaks += vis->visible(a, b) + vis->visible(b, a);
            self_blocked += !vis->visible(a, point_on(room_a[rng() % 6], eps, rng));
            self_blocked += !vis->visible(b, point_on(room_b[rng() % 6], eps, rng));
        }
        // Along the wall base: start 0.5 mm (or ε) above the floor right next to the wall and
        // aim under it; the wall stands on the floor, so nothing may pass.
        for (int i = 0; i < 4000; ++i) {
            const double gap_a = std::pow(10.0, -5 + 3 * u(rng));  // 10 µm .. 1 cm
            const double gap_b = std::pow(10.0, -5 + 3 * u(rng));
            const double za = i % 2 ? 5e-4 : eps, zb = i % 3 ? 5e-4 : eps;
            const Vec3 a{-t / 2 - std::max(gap_a, eps), -2 + 4 * u(rng), za};
            const Vec3 b{t / 2 + std::max(gap_b, eps), -2 + 4 * u(rng), zb};
            leaks += vis->visible(a, b) + vis->visible(b, a);
        }
        EXPECT_EQ(leaks, 0) << "wall thickness " << t;
        EXPECT_EQ(self_blocked, 0) << "wall thickness " << t;
    }
}

INSTANTIATE_TEST_SUITE_P(Visibility, ThinWall, ::testing::Values(0.2, 0.01, 0.0));

// ---------------------------------------------------------------------------------------------
// (d): huge scale range (validation §5.7)

/// 100 × 50 × 20 m hall with a 2 mm thick 0.5 × 0.5 m shelf 10 mm above the floor, 80 m out.
std::vector<Triangle> hall_with_shelf() {
    std::vector<Triangle> tris;
    add_box(tris, {0, 0, 0}, {100, 50, 20});
    add_box(tris, {80.1, 24.7, 0.010}, {80.6, 25.2, 0.012});
    return tris;
}

TEST(Visibility, CentredHallKeepsMillimetreShelfOpaque) {
    const auto raw = hall_with_shelf();
    const Vec3 shift = -bbox_centre(raw);
    const auto tris = transformed(raw, 1.0, shift);
    const Vec3 shelf_centre = Vec3{80.35, 24.95, 0.011} + shift;
    std::mt19937_64 rng(3);
    for (const auto& vis : {make_embree_visibility(tris), make_brute_force_visibility(tris)}) {
        const double eps = vis->epsilon();
        EXPECT_LT(eps, 0.5e-3);
        EXPECT_FALSE(vis->visible(shelf_centre + Vec3{0, 0, 0.002},
                                  shelf_centre - Vec3{0, 0, 0.002}));  // 1 mm above to below
        // Ceiling above the shelf → its underside (lifted ε downwards, ≥ 5 cm from the plate
        // edges so no ray can slip in from the side) is blocked by the plate; the floor under
        // the shelf still sees the underside.
        int leaks = 0, blocked = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3 under =
                random_in_box(rng, {80.15, 24.75, 0.010 - eps}, {80.55, 25.15, 0.010 - eps}) +
                shift;
            const Vec3 ceiling = random_in_box(rng, {75, 20, 20 - eps}, {85, 30, 20 - eps}) + shift;
            const Vec3 floor = random_in_box(rng, {80.2, 24.8, eps}, {80.5, 25.1, eps}) + shift;
            leaks += vis->visible(ceiling, under);
            blocked += !vis->visible(floor, under);
        }
        EXPECT_EQ(leaks, 0);
        EXPECT_EQ(blocked, 0);
    }
    // Why the engine recentres: at 10 km, float spacing alone forces ε beyond the plate.
    EXPECT_GT(ray_epsilon(transformed(raw, 1.0, {1e4, 1e4, 0})), 0.002);
}

TEST(Visibility, AnswersInvariantUnderTranslationAndMillimetreUnits) {
    const auto raw = hall_with_shelf();
    const auto base = transformed(raw, 1.0, -bbox_centre(raw));
    const auto far_raw = transformed(raw, 1.0, {1e4, 1e4, 0});
    const auto far = transformed(far_raw, 1.0, -bbox_centre(far_raw));  // engine recentres
    const auto mm = transformed(base, 1000.0, {});

    const auto vis_base = make_embree_visibility(base);
    const auto vis_far = make_embree_visibility(far);
    const auto vis_mm = make_embree_visibility(mm);
    const auto oracle = make_brute_force_visibility(base);
    EXPECT_NEAR(vis_far->epsilon(), vis_base->epsilon(), 1e-12);
    EXPECT_GT(vis_mm->epsilon() / vis_base->epsilon(), 500.0);
    EXPECT_LT(vis_mm->epsilon() / vis_base->epsilon(), 2000.0);

    std::mt19937_64 rng(8);
    // Half the queries anywhere in the hall, half from above the shelf to below it (many of
    // those blocked by the 2 mm plate).
    const Vec3 c = Vec3{80.35, 24.95, 0.011} - bbox_centre(raw);
    auto queries = clear_queries(base, rng, 5000, {-50, -25, -10}, {50, 25, 10}, {-50, -25, -10},
                                 {50, 25, 10}, 1e-4);
    const auto near_shelf =
        clear_queries(base, rng, 5000, c + Vec3{-0.4, -0.4, 0.002}, c + Vec3{0.4, 0.4, 0.5},
                      c + Vec3{-0.4, -0.4, -0.011 + 1e-4}, c + Vec3{0.4, 0.4, -0.001}, 1e-4);
    queries.insert(queries.end(), near_shelf.begin(), near_shelf.end());
    std::size_t differ_far = 0, differ_mm = 0, differ_oracle = 0, blocked = 0;
    for (const SegmentQuery& q : queries) {
        const bool v = vis_base->visible(q.from, q.to);
        differ_far += v != vis_far->visible(q.from, q.to);
        differ_mm += v != vis_mm->visible(1000.0 * q.from, 1000.0 * q.to);
        differ_oracle += v != oracle->visible(q.from, q.to);
        blocked += !v;
    }
    EXPECT_EQ(differ_far, 0u);
    EXPECT_EQ(differ_mm, 0u);
    EXPECT_EQ(differ_oracle, 0u);
    EXPECT_GT(blocked, 1000u);
}

// ---------------------------------------------------------------------------------------------
// (e), (f): batch and threads

TEST(Visibility, BatchEqualsPerQuery) {
    std::mt19937_64 rng(11);
    const auto tris = random_scene(rng);
    std::vector<SegmentQuery> queries;
    for (int i = 0; i < 10007; ++i)  // not a multiple of any packet width
        queries.push_back({random_in_box(rng, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5}),
                           random_in_box(rng, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5})});
    // Shafts of 16 rays between two small patches: the coherent packet path.
    std::uniform_real_distribution<double> u(0.0, 0.2);
    for (int link = 0; link < 500; ++link) {
        const Vec3 p = random_in_box(rng, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5});
        const Vec3 q = random_in_box(rng, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5});
        for (int k = 0; k < 16; ++k)
            queries.push_back({p + Vec3{u(rng), u(rng), u(rng)}, q + Vec3{u(rng), u(rng), u(rng)}});
    }
    queries[17].to.y = std::numeric_limits<double>::quiet_NaN();
    for (const auto& vis : {make_embree_visibility(tris), make_brute_force_visibility(tris)}) {
        std::vector<std::uint8_t> out(queries.size(), 7);
        vis->visible_batch(queries, out);
        std::size_t differ = 0;
        for (std::size_t i = 0; i < queries.size(); ++i)
            differ += out[i] != (vis->visible(queries[i].from, queries[i].to) ? 1 : 0);
        EXPECT_EQ(differ, 0u);
        EXPECT_EQ(out[17], 0);
        std::vector<std::uint8_t> wrong(3);
        EXPECT_THROW(vis->visible_batch(queries, wrong), std::invalid_argument);
    }
}

TEST(Visibility, ParallelQueriesMatchSerial) {
    std::mt19937_64 rng(21);
    const auto tris = random_scene(rng);
    const auto vis = make_embree_visibility(tris);
    const std::size_t n = 50000;
    std::vector<SegmentQuery> queries(n);
    for (auto& q : queries)
        q = {random_in_box(rng, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5}),
             random_in_box(rng, {-2.5, -2.5, -2.5}, {2.5, 2.5, 2.5})};
    std::vector<std::uint8_t> serial_vis(n), parallel_vis(n), parallel_batch(n);
    std::vector<int> serial_hit(n), parallel_hit(n);
    for (std::size_t i = 0; i < n; ++i) {
        serial_vis[i] = vis->visible(queries[i].from, queries[i].to);
        serial_hit[i] = vis->first_hit(queries[i].from, queries[i].to - queries[i].from, 1.0);
    }
    parallel_for(0, n, [&](std::size_t i) {
        parallel_vis[i] = vis->visible(queries[i].from, queries[i].to);
        parallel_hit[i] = vis->first_hit(queries[i].from, queries[i].to - queries[i].from, 1.0);
    });
    parallel_for(0, n / 100, [&](std::size_t chunk) {
        vis->visible_batch(std::span(queries).subspan(chunk * 100, 100),
                           std::span(parallel_batch).subspan(chunk * 100, 100));
    });
    EXPECT_EQ(serial_vis, parallel_vis);
    EXPECT_EQ(serial_vis, parallel_batch);
    EXPECT_EQ(serial_hit, parallel_hit);
}

// ---------------------------------------------------------------------------------------------
// (g): no self-hits for grazing rays leaving a large surface

TEST(Visibility, GrazingRaysLeavingALargeFloorNeverHitIt) {
    // 200 m floor, tilted so its plane is not exactly representable, centred like the engine.
    const Vec3 n = normalized({0.013, -0.021, 1.0});
    const Vec3 e1 = normalized(cross({0, 1, 0}, n));
    const Vec3 e2 = cross(n, e1);
    const Vec3 o{0.37, -0.21, 0.11};
    std::vector<Triangle> tris;
    add_quad(tris, o - 100 * e1 - 100 * e2, o + 100 * e1 - 100 * e2, o + 100 * e1 + 100 * e2,
             o - 100 * e1 + 100 * e2);
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (const auto& vis : {make_embree_visibility(tris), make_brute_force_visibility(tris)}) {
        const double eps = vis->epsilon();
        int self_hits = 0;
        for (int i = 0; i < 20000; ++i) {
            const Vec3 p = o + (200 * u(rng) - 100) * e1 + (200 * u(rng) - 100) * e2 + eps * n;
            const double phi = 2 * std::numbers::pi * u(rng);
            const double rise = std::pow(10.0, -6 + 4 * u(rng));  // sin(elevation) 1e-6 .. 1e-2
            const Vec3 dir =
                std::sqrt(1 - rise * rise) * (std::cos(phi) * e1 + std::sin(phi) * e2) + rise * n;
            const double len = 300 * u(rng);
            self_hits += vis->first_hit(p, dir, len) >= 0;
            self_hits += vis->first_hit(p, dir, std::numeric_limits<double>::infinity()) >= 0;
            self_hits += !vis->visible(p, p + len * dir);
        }
        EXPECT_EQ(self_hits, 0);
    }
}

// ---------------------------------------------------------------------------------------------
// Micro-benchmark (disabled; run with --gtest_also_run_disabled_tests): packets vs single rays.

TEST(Visibility, DISABLED_BenchmarkPacketsAgainstSingleRays) {
    std::mt19937_64 rng(1);
    std::vector<Triangle> tris;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const Vec3 c = random_in_box(rng, {-5, -5, -5}, {5, 5, 5});
        tris.push_back({c + 0.15 * random_unit(rng), c + 0.15 * random_unit(rng),
                        c + 0.15 * random_unit(rng)});
    }
    const auto vis = make_embree_visibility(tris);
    // Coherent: 16 stratified rays per link between two 0.3 m patches (one HR link);
    // incoherent: independent random segments.
    std::vector<SegmentQuery> coherent, incoherent;
    while (coherent.size() < 400000) {
        const Vec3 p = random_in_box(rng, {-5, -5, -5}, {5, 5, 5});
        const Vec3 q = random_in_box(rng, {-5, -5, -5}, {5, 5, 5});
        for (int k = 0; k < 16; ++k)
            coherent.push_back(
                {p + Vec3{0.3 * u(rng), 0.3 * u(rng), 0}, q + Vec3{0.3 * u(rng), 0.3 * u(rng), 0}});
    }
    for (std::size_t i = 0; i < coherent.size(); ++i)
        incoherent.push_back({random_in_box(rng, {-5, -5, -5}, {5, 5, 5}),
                              random_in_box(rng, {-5, -5, -5}, {5, 5, 5})});
    for (const auto* set : {&coherent, &incoherent}) {
        std::vector<std::uint8_t> single(set->size()), batch(set->size());
        using clock = std::chrono::steady_clock;
        for (int rep = 0; rep < 3; ++rep) {
            auto t0 = clock::now();
            for (std::size_t i = 0; i < set->size(); ++i)
                single[i] = vis->visible((*set)[i].from, (*set)[i].to);
            auto t1 = clock::now();
            for (std::size_t i = 0; i < set->size(); i += 16)
                vis->visible_batch(std::span(*set).subspan(i, 16), std::span(batch).subspan(i, 16));
            auto t2 = clock::now();
            const double n = static_cast<double>(set->size());
            std::printf("%s: single %.1f ns/ray, batch %.1f ns/ray\n",
                        set == &coherent ? "coherent" : "incoherent",
                        std::chrono::duration<double, std::nano>(t1 - t0).count() / n,
                        std::chrono::duration<double, std::nano>(t2 - t1).count() / n);
        }
        EXPECT_EQ(single, batch);
    }
}

}  // namespace
}  // namespace radiant
