#include "meshing/patch_mesh.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <tuple>

#include "formfactor/quadrature.h"
#include "geometry/polygon_split.h"
#include "parallel/fork_join.h"
#include "parallel/stop_poll.h"

namespace radiant {
namespace {

using Poly = std::vector<Vec3>;

struct Segment {
    Vec3 a, b;
};

struct Box3 {
    Vec3 lo, hi;
};

Box3 bounds(const Poly& p, double pad) {
    Box3 b{p[0], p[0]};
    for (const Vec3& v : p) {
        for (int a = 0; a < 3; ++a) {
            b.lo[a] = std::min(b.lo[a], v[a]);
            b.hi[a] = std::max(b.hi[a], v[a]);
        }
    }
    for (int a = 0; a < 3; ++a) {
        b.lo[a] -= pad;
        b.hi[a] += pad;
    }
    return b;
}

bool overlap(const Box3& x, const Box3& y) {
    for (int a = 0; a < 3; ++a) {
        if (x.hi[a] < y.lo[a] || y.hi[a] < x.lo[a]) return false;
    }
    return true;
}

Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return a + (b - a) * t; }

// A convex quad as an nu × nv grid of sub-quads on its bilinear map (planar, so each is planar).
void subdivide_quad(const Poly& q, double h, std::vector<Poly>& out) {
    const int nu = std::max(
        1, static_cast<int>(std::ceil(std::max(length(q[1] - q[0]), length(q[2] - q[3])) / h)));
    const int nv = std::max(
        1, static_cast<int>(std::ceil(std::max(length(q[3] - q[0]), length(q[2] - q[1])) / h)));
    auto at = [&](int i, int j) {
        const double s = static_cast<double>(i) / nu, t = static_cast<double>(j) / nv;
        return lerp(lerp(q[0], q[1], s), lerp(q[3], q[2], s), t);
    };
    for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i)
            out.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
}

// Well-shaped triangles split uniformly into k² similar ones; slivers by longest-edge bisection,
// which keeps the count linear in their length instead of quadratic.
void subdivide_triangle(const Poly& t, double h, std::vector<Poly>& out, int depth = 0) {
    const double e[3] = {length(t[1] - t[0]), length(t[2] - t[1]), length(t[0] - t[2])};
    const double longest = std::max({e[0], e[1], e[2]});
    if (longest <= h || depth > 40) {
        out.push_back(t);
        return;
    }
    const double area = 0.5 * length(cross(t[1] - t[0], t[2] - t[0]));
    const double min_height = 2 * area / longest;
    if (min_height >= 0.3 * longest) {
        const int k = static_cast<int>(std::ceil(longest / h));
        auto at = [&](int i, int j) {  // barycentric lattice point i/k, j/k
            return t[0] + (t[1] - t[0]) * (static_cast<double>(i) / k) +
                   (t[2] - t[0]) * (static_cast<double>(j) / k);
        };
        for (int j = 0; j < k; ++j) {
            for (int i = 0; i + j < k; ++i) {
                out.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
                if (i + j + 1 < k) out.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
        return;
    }
    const int a = e[0] >= e[1] && e[0] >= e[2] ? 0 : (e[1] >= e[2] ? 1 : 2);
    const Vec3& p = t[a];
    const Vec3& q = t[(a + 1) % 3];
    const Vec3& r = t[(a + 2) % 3];
    const Vec3 m = (p + q) * 0.5;
    subdivide_triangle({p, m, r}, h, out, depth + 1);
    subdivide_triangle({m, q, r}, h, out, depth + 1);
}

void subdivide_piece(const Piece& piece, double h, std::vector<Poly>& out) {
    const Poly& v = piece.vertices;
    if (v.size() == 4) {
        subdivide_quad(v, h, out);
    } else if (v.size() == 3) {
        subdivide_triangle(v, h, out);
    } else {
        const Vec3 c = polygon_centroid(v);  // fan from the centroid: well-shaped for round pieces
        for (std::size_t i = 0; i < v.size(); ++i) {
            subdivide_triangle({c, v[i], v[(i + 1) % v.size()]}, h, out);
        }
    }
}

// A parallel piece q closer to r than `near` (a panel hung 1 mm under a ceiling, a rug on a
// floor) shades the region of r under it: r is cut along q's projected outline, so that no patch
// straddles the shaded region's edge and radiates into the gap from its lit part.
void parallel_outline(const Piece& r, const Piece& q, double near, std::vector<Segment>& out) {
    if (std::abs(dot(q.normal, r.normal)) < 1 - 1e-9) return;
    const double d = dot(q.vertices[0] - r.vertices[0], r.normal);
    if (std::abs(d) > near) return;
    const std::size_t k = q.vertices.size();
    for (std::size_t i = 0; i < k; ++i) {
        out.push_back({q.vertices[i] - r.normal * d, q.vertices[(i + 1) % k] - r.normal * d});
    }
}

// Where piece q touches or crosses the plane of piece r, as segments in r's plane.
void contact_segments(const Piece& r, const Piece& q, double eps, std::vector<Segment>& out) {
    const std::size_t k = q.vertices.size();
    std::vector<double> d(k);
    bool any_pos = false, any_neg = false, all_on = true;
    for (std::size_t i = 0; i < k; ++i) {
        d[i] = dot(q.vertices[i] - r.vertices[0], r.normal);
        if (std::abs(d[i]) <= eps) d[i] = 0;
        any_pos |= d[i] > 0;
        any_neg |= d[i] < 0;
        all_on &= d[i] == 0;
    }
    if (all_on) {  // coplanar overlay (a rug, a flush panel, a box bottom): its outline cuts r
        for (std::size_t i = 0; i < k; ++i) out.push_back({q.vertices[i], q.vertices[(i + 1) % k]});
        return;
    }
    if (any_pos && any_neg) {
        std::vector<Vec3> hits;
        for (std::size_t i = 0; i < k; ++i) {
            const std::size_t j = (i + 1) % k;
            if (d[i] == 0) hits.push_back(q.vertices[i]);
            if ((d[i] > 0 && d[j] < 0) || (d[i] < 0 && d[j] > 0)) {
                hits.push_back(lerp(q.vertices[i], q.vertices[j], d[i] / (d[i] - d[j])));
            }
        }
        if (hits.size() >= 2) out.push_back({hits.front(), hits.back()});
        return;
    }
    // Touching from one side: the vertices (an edge) of q lying on r's plane.
    std::vector<Vec3> on;
    for (std::size_t i = 0; i < k; ++i) {
        if (d[i] == 0) on.push_back(q.vertices[i]);
    }
    if (on.size() >= 2) out.push_back({on.front(), on.back()});
}

// Length of the part of segment s inside convex polygon p (in p's plane, normal n).
double clipped_length(const Segment& s, const Poly& p, const Vec3& n) {
    double t0 = 0, t1 = 1;
    const Vec3 d = s.b - s.a;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec3 edge = p[(i + 1) % p.size()] - p[i];
        const Vec3 inward = cross(n, edge);
        const double num = dot(s.a - p[i], inward);
        const double den = dot(d, inward);
        if (std::abs(den) < 1e-300) {
            if (num < 0) return 0;
            continue;
        }
        const double t = -num / den;
        if (den > 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 >= t1) return 0;
    }
    return (t1 - t0) * length(d);
}

// Whether a plane (through o, normal m) has vertices of p further than eps on both sides: the
// only case in which split_by_plane splits p.
bool straddles(const Poly& p, const Vec3& o, const Vec3& m, double eps) {
    bool pos = false, neg = false;
    for (const Vec3& v : p) {
        const double d = dot(v - o, m);
        pos |= d > eps;
        neg |= d < -eps;
    }
    return pos && neg;
}

void split_along(std::vector<Poly>& patches, const Segment& s, const Vec3& n, double eps) {
    const Vec3 dir = s.b - s.a;
    if (length(dir) <= eps) return;
    const Vec3 m = normalized(cross(n, dir));
    // Most contacts split nothing (a mesh's neighbouring triangles touch along its own edges):
    // the list is rebuilt only from the first polygon that splits.
    std::vector<Poly> result;
    bool split = false;
    for (std::size_t i = 0; i < patches.size(); ++i) {
        Poly& p = patches[i];
        if (straddles(p, s.a, m, eps) && clipped_length(s, p, n) > eps) {
            auto [pos, neg] = split_by_plane(p, s.a, m, eps);
            const double min_area = eps * eps;
            if (pos.size() >= 3 && neg.size() >= 3 && polygon_area(pos) > min_area &&
                polygon_area(neg) > min_area) {
                if (!split) {
                    result.reserve(patches.size() + 4);
                    for (std::size_t j = 0; j < i; ++j) result.push_back(std::move(patches[j]));
                    split = true;
                }
                result.push_back(simplify_polygon(pos, 0.0));
                result.push_back(simplify_polygon(neg, 0.0));
                continue;
            }
        }
        if (split) result.push_back(std::move(p));
    }
    if (split) patches = std::move(result);
}

// Piece q overlays piece r when it lies in r's plane, faces the same way and is smaller (equal
// areas: the later one wins), so that of two coincident surfaces exactly one is seen.
bool overlays(const Piece& q, std::size_t qi, const Piece& r, std::size_t ri, double eps) {
    if (dot(q.normal, r.normal) < 1 - 1e-9) return false;
    for (const Vec3& v : q.vertices) {
        if (std::abs(dot(v - r.vertices[0], r.normal)) > eps) return false;
    }
    return q.area_m2 < r.area_m2 || (q.area_m2 == r.area_m2 && qi > ri);
}

bool inside_convex(const Vec3& x, const Poly& p, const Vec3& n, double eps) {
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (dot(cross(p[(i + 1) % p.size()] - p[i], x - p[i]), n) <
            -eps * length(p[(i + 1) % p.size()] - p[i])) {
            return false;
        }
    }
    return true;
}

// Every pair of pieces whose boxes (padded by `pad`) overlap: per piece, its partners in the
// order of a sweep along x (their boxes' lower x), which keeps the pairs near-linear for
// spread-out scenes. The order is the order in which contacts split a piece, so it is fixed.
// Piece i's partners are partner[first[i]] … partner[first[i + 1] − 1] (a plant of 2 000
// triangles has most of its 4 million pairs: one array, counted before it is filled).
struct Partners {
    std::vector<std::size_t> first;
    std::vector<int> partner;
};

// Each lists the other.
constexpr std::size_t kPairBytes = 2 * sizeof(int);

// The sweep asks whether to stop once per this many candidate pairs.
constexpr std::size_t kStopCheckPairs = std::size_t{1} << 20;

// The partners, or nothing when there are more than max_pairs pairs (counted no further); none
// when `should_stop` stopped the sweep (its pieces are then not cut at all).
std::optional<Partners> overlapping_pieces(const PreparedScene& scene, double pad,
                                           std::size_t max_pairs,
                                           const std::function<bool()>& should_stop) {
    const std::size_t k = scene.pieces.size();
    std::vector<Box3> box(k);
    for (std::size_t i = 0; i < k; ++i) box[i] = bounds(scene.pieces[i].vertices, pad);
    std::vector<std::size_t> order(k);
    for (std::size_t i = 0; i < k; ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return box[a].lo.x < box[b].lo.x; });
    // pair(i, j) for every overlapping pair while it returns true; false when it did not, or
    // when should_stop stopped it.
    std::size_t candidates = 0;
    StopPoll stop(should_stop, kStopCheckPairs);
    auto sweep = [&](auto&& pair) {
        for (std::size_t oi = 0; oi < k; ++oi) {
            const std::size_t i = order[oi];
            for (std::size_t oj = oi + 1; oj < k && box[order[oj]].lo.x <= box[i].hi.x; ++oj) {
                if (stop(++candidates)) return false;
                if (overlap(box[i], box[order[oj]]) && !pair(i, order[oj])) return false;
            }
        }
        return true;
    };
    const auto none = [k] { return Partners{std::vector<std::size_t>(k + 1, 0), {}}; };
    Partners out;
    out.first.assign(k + 1, 0);
    std::size_t pairs = 0;
    const bool counted = sweep([&](std::size_t i, std::size_t j) {
        ++out.first[i + 1];
        ++out.first[j + 1];
        return ++pairs <= max_pairs;
    });
    if (pairs > max_pairs) return std::nullopt;
    if (!counted) return none();
    for (std::size_t i = 0; i < k; ++i) out.first[i + 1] += out.first[i];
    out.partner.resize(out.first[k]);
    std::vector<std::size_t> next(out.first.begin(), out.first.end() - 1);
    const bool filled = sweep([&](std::size_t i, std::size_t j) {
        out.partner[next[i]++] = static_cast<int>(j);
        out.partner[next[j]++] = static_cast<int>(i);
        return true;
    });
    if (!filled) return none();
    return out;
}

// What a planned polygon holds: its vector and about four vertices.
constexpr std::size_t kPolygonBytes = sizeof(std::vector<Vec3>) + 4 * sizeof(Vec3);

std::size_t polygon_count(const std::vector<std::vector<Poly>>& polygons) {
    std::size_t n = 0;
    for (const std::vector<Poly>& p : polygons) n += p.size();
    return n;
}

std::size_t count_patches(const PreparedScene& scene, const std::vector<std::vector<Poly>>& sub) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < sub.size(); ++i) {
        const bool two =
            scene.materials[static_cast<std::size_t>(scene.pieces[i].material)].two_sided;
        n += sub[i].size() * (two ? 2 : 1);
    }
    return n;
}

double polygon_diameter(const Poly& p) {
    double d = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        for (std::size_t j = i + 1; j < p.size(); ++j) d = std::max(d, length(p[i] - p[j]));
    }
    return d;
}

double mesh_epsilon(const PreparedScene& scene) {
    return 1e-7 * std::max(scene.diagonal_m, 1e-300);
}

}  // namespace

double target_patch_edge(double mean_free_path_m, double tolerance) {
    const double tol = std::clamp(tolerance, 1e-6, 0.5);
    return std::max(1.5 * mean_free_path_m * std::sqrt(tol), 1e-9);
}

PatchPlan::PatchPlan(const PreparedScene& scene, const MeshingOptions& options)
    : target_edge_m_(options.target_edge_m), epsilon_(mesh_epsilon(scene)) {
    const std::size_t k = scene.pieces.size();
    auto subdivide_all = [&] {
        polygons_.assign(k, {});
        parallel_for(0, k, [&](std::size_t i) {
            subdivide_piece(scene.pieces[i], target_edge_m_, polygons_[i]);
        });
    };
    // Grown until the count fits max_patches.
    subdivide_all();
    for (int round = 0; round < 20 && count_patches(scene, polygons_) > options.max_patches;
         ++round) {
        const double ratio = static_cast<double>(count_patches(scene, polygons_)) /
                             static_cast<double>(options.max_patches);
        target_edge_m_ *= std::max(1.05, std::sqrt(ratio) * 1.02);
        subdivide_all();
    }
    count_ = count_patches(scene, polygons_);
    // Then split along the lines where other pieces touch each piece, partner by partner, while
    // the pairs and polygons fit max_plan_bytes (instances of one mesh laid on each other pair
    // every triangle with every other, and cut each other's pieces into as many slivers).
    const std::size_t max_bytes = options.max_plan_bytes > 0
                                      ? options.max_plan_bytes
                                      : std::numeric_limits<std::size_t>::max();
    const std::size_t subdivided_bytes = polygon_count(polygons_) * kPolygonBytes;
    if (subdivided_bytes > max_bytes) {
        least_bytes_ = subdivided_bytes;
        return;
    }
    const double gap = options.shading_gap_m > 0 ? options.shading_gap_m : 0.5 * target_edge_m_;
    const std::size_t max_pairs = (max_bytes - subdivided_bytes) / kPairBytes;
    const std::optional<Partners> partners =
        overlapping_pieces(scene, std::max(epsilon_, gap), max_pairs, options.should_stop);
    if (!partners) {
        least_bytes_ = subdivided_bytes + (max_pairs + 1) * kPairBytes;
        return;
    }
    const std::size_t pair_bytes = partners->partner.size() / 2 * kPairBytes;
    std::atomic<std::size_t> polygons{polygon_count(polygons_)};
    std::atomic<bool> over{false};
    // Asked every this many contacts (a piece cut into many slivers takes long).
    constexpr std::size_t kStopCheckEvery = 64;
    StopPoll stop(options.should_stop, kStopCheckEvery);
    overlays_.assign(k, {});
    parallel_for(0, k, [&](std::size_t i) {
        if (over.load(std::memory_order_relaxed)) return;
        const Piece& r = scene.pieces[i];
        std::vector<Segment> segments;
        for (std::size_t at = partners->first[i]; at < partners->first[i + 1]; ++at) {
            const int j = partners->partner[at];
            const Piece& q = scene.pieces[static_cast<std::size_t>(j)];
            if (overlays(q, static_cast<std::size_t>(j), r, i, epsilon_)) overlays_[i].push_back(j);
            if (stop.stopped()) continue;
            contact_segments(r, q, epsilon_, segments);
            parallel_outline(r, q, gap, segments);
        }
        for (std::size_t n = 0; n < segments.size(); ++n) {
            if (stop(n) || over.load(std::memory_order_relaxed)) return;
            const std::size_t before = polygons_[i].size();
            split_along(polygons_[i], segments[n], r.normal, epsilon_);
            if (polygons_[i].size() == before) continue;  // most contacts split nothing
            const std::size_t now = polygons += polygons_[i].size() - before;
            if (now * kPolygonBytes + pair_bytes > max_bytes) over = true;
        }
    });
    if (over) {
        // Which thread went over first, and by how much, varies: the answer must not.
        least_bytes_ = max_bytes + 1;
        return;
    }
    // Stopped: the pieces' cuts so far are dropped too. Crossing pieces cut into slivers make
    // millions of patches, and every later step of the solve, none of which can stop halfway,
    // is linear in them (3 000 crossing shards stopped at 10 s: 928 000 patches, whose mesh,
    // element tree and first estimate took 15 s more).
    if (stop.stopped()) subdivide_all();
    count_ = count_patches(scene, polygons_);
}

PatchMesh::PatchMesh(const PreparedScene& scene, const MeshingOptions& options)
    : PatchMesh(scene, PatchPlan(scene, options)) {}

PatchMesh::PatchMesh(const PreparedScene& scene, PatchPlan plan)
    : target_edge_m_(plan.target_edge_m()) {
    // Patches in order of piece, side, polygon; their geometry is made in parallel, the mesh's
    // faces (which share vertices) one after the other.
    std::vector<std::size_t> first(scene.pieces.size() + 1, 0);
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        const bool two_sided =
            scene.materials[static_cast<std::size_t>(scene.pieces[i].material)].two_sided;
        first[i + 1] = first[i] + plan.polygons_[i].size() * (two_sided ? 2 : 1);
    }
    patches_.resize(first.back());
    const double eps = plan.epsilon_;
    parallel_for(0, scene.pieces.size(), [&](std::size_t i) {
        const Piece& piece = scene.pieces[i];
        const bool two_sided = scene.materials[static_cast<std::size_t>(piece.material)].two_sided;
        std::size_t at = first[i];
        for (int side = 0; side < (two_sided ? 2 : 1); ++side) {
            for (const Poly& p : plan.polygons_[i]) {
                PatchGeometry& g = patches_[at++];
                g.vertices = p;
                if (side == 1) std::reverse(g.vertices.begin(), g.vertices.end());
                g.normal = side == 1 ? -piece.normal : piece.normal;
                g.area_m2 = polygon_area(p);
                g.centroid = polygon_centroid(p);
                g.diameter_m = polygon_diameter(p);
                g.piece = static_cast<int>(i);
                g.surface = piece.surface;
                g.material = piece.material;
                g.back_side = side == 1;
                for (const int q : plan.overlays_[i]) {
                    const Piece& over = scene.pieces[static_cast<std::size_t>(q)];
                    g.hidden =
                        g.hidden || inside_convex(g.centroid, over.vertices, over.normal, eps);
                }
            }
        }
    });
    VertexIndex index;
    for (const PatchGeometry& g : patches_) add_face(g, index);
    for (int c = 0; c < 3; ++c) {
        mesh_.add_property(radiosity_[c]);
        mesh_.add_property(unshot_[c]);
        mesh_.add_property(irradiance_[c]);
    }
}

// Vertices are shared between the patches of coplanar pieces of one surface side only, never
// across surfaces or creases, so Gouraud shading never blends light between objects. Where sharing
// would make a vertex non-manifold (T-junctions from contact splits), the face gets its own
// vertices so that face i stays patch i.
void PatchMesh::add_face(const PatchGeometry& patch, VertexIndex& index) {
    std::vector<PolyMesh::VertexHandle> handles;
    for (const Vec3& v : patch.vertices) {
        // Pieces of one planar polygon have normals equal up to rounding: 1e-9 buckets.
        const auto plane =
            std::make_tuple(std::llround(patch.normal.x * 1e9), std::llround(patch.normal.y * 1e9),
                            std::llround(patch.normal.z * 1e9));
        const auto key = std::make_tuple(patch.surface, patch.back_side, plane, v.x, v.y, v.z);
        auto it = index.find(key);
        if (it == index.end()) {
            it = index.emplace(key, mesh_.add_vertex(PolyMesh::Point(v.x, v.y, v.z))).first;
        }
        handles.push_back(it->second);
    }
    if (mesh_.add_face(handles).is_valid()) return;
    handles.clear();
    for (const Vec3& v : patch.vertices)
        handles.push_back(mesh_.add_vertex(PolyMesh::Point(v.x, v.y, v.z)));
    mesh_.add_face(handles);
}

}  // namespace radiant
