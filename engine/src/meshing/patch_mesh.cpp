#include "meshing/patch_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "formfactor/quadrature.h"
#include "geometry/polygon_split.h"

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

void split_along(std::vector<Poly>& patches, const Segment& s, const Vec3& n, double eps) {
    const Vec3 dir = s.b - s.a;
    if (length(dir) <= eps) return;
    const Vec3 m = normalized(cross(n, dir));
    std::vector<Poly> result;
    result.reserve(patches.size() + 4);
    for (Poly& p : patches) {
        if (clipped_length(s, p, n) <= eps) {
            result.push_back(std::move(p));
            continue;
        }
        auto [pos, neg] = split_by_plane(p, s.a, m, eps);
        const double min_area = eps * eps;
        if (pos.size() >= 3 && neg.size() >= 3 && polygon_area(pos) > min_area &&
            polygon_area(neg) > min_area) {
            result.push_back(simplify_polygon(pos, 0.0));
            result.push_back(simplify_polygon(neg, 0.0));
        } else {
            result.push_back(std::move(p));
        }
    }
    patches = std::move(result);
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

struct Contacts {
    std::vector<std::vector<Segment>> segments;  // per piece: lines to split it along
    std::vector<std::vector<int>> overlays;      // per piece: pieces lying on it
};

Contacts all_contacts(const PreparedScene& scene, double eps, double near) {
    const std::size_t k = scene.pieces.size();
    std::vector<Box3> box(k);
    for (std::size_t i = 0; i < k; ++i)
        box[i] = bounds(scene.pieces[i].vertices, std::max(eps, near));
    // Sweep along x so that the candidate pairs stay near-linear for spread-out scenes.
    std::vector<std::size_t> order(k);
    for (std::size_t i = 0; i < k; ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return box[a].lo.x < box[b].lo.x; });
    Contacts contacts;
    contacts.segments.resize(k);
    contacts.overlays.resize(k);
    for (std::size_t oi = 0; oi < k; ++oi) {
        const std::size_t i = order[oi];
        for (std::size_t oj = oi + 1; oj < k && box[order[oj]].lo.x <= box[i].hi.x; ++oj) {
            const std::size_t j = order[oj];
            if (!overlap(box[i], box[j])) continue;
            const Piece& a = scene.pieces[i];
            const Piece& b = scene.pieces[j];
            contact_segments(a, b, eps, contacts.segments[i]);
            contact_segments(b, a, eps, contacts.segments[j]);
            parallel_outline(a, b, near, contacts.segments[i]);
            parallel_outline(b, a, near, contacts.segments[j]);
            if (overlays(b, j, a, i, eps)) contacts.overlays[i].push_back(static_cast<int>(j));
            if (overlays(a, i, b, j, eps)) contacts.overlays[j].push_back(static_cast<int>(i));
        }
    }
    return contacts;
}

std::vector<std::vector<Poly>> subdivide_all(const PreparedScene& scene, double h) {
    std::vector<std::vector<Poly>> out(scene.pieces.size());
    for (std::size_t i = 0; i < scene.pieces.size(); ++i)
        subdivide_piece(scene.pieces[i], h, out[i]);
    return out;
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

// The patches' polygons of every piece: subdivided to the target edge (grown until the count fits
// max_patches), then split along the lines where other surfaces touch the piece. Sets `h` to the
// edge used.
struct PatchPlan {
    std::vector<std::vector<Poly>> polygons;  ///< per piece
    Contacts contacts;
};

PatchPlan plan_patches(const PreparedScene& scene, const MeshingOptions& options, double eps,
                       double& h) {
    h = options.target_edge_m;
    PatchPlan plan;
    std::vector<std::vector<Poly>>& sub = plan.polygons;
    sub = subdivide_all(scene, h);
    for (int round = 0; round < 20 && count_patches(scene, sub) > options.max_patches; ++round) {
        const double ratio = static_cast<double>(count_patches(scene, sub)) /
                             static_cast<double>(options.max_patches);
        h *= std::max(1.05, std::sqrt(ratio) * 1.02);
        sub = subdivide_all(scene, h);
    }
    const double gap = options.shading_gap_m > 0 ? options.shading_gap_m : 0.5 * h;
    plan.contacts = all_contacts(scene, eps, gap);
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        for (const Segment& s : plan.contacts.segments[i])
            split_along(sub[i], s, scene.pieces[i].normal, eps);
    }
    return plan;
}

double mesh_epsilon(const PreparedScene& scene) {
    return 1e-7 * std::max(scene.diagonal_m, 1e-300);
}

}  // namespace

double target_patch_edge(double mean_free_path_m, double tolerance) {
    const double tol = std::clamp(tolerance, 1e-6, 0.5);
    return std::max(1.5 * mean_free_path_m * std::sqrt(tol), 1e-9);
}

std::size_t PatchMesh::count(const PreparedScene& scene, const MeshingOptions& options) {
    double h = 0;
    return count_patches(scene, plan_patches(scene, options, mesh_epsilon(scene), h).polygons);
}

PatchMesh::PatchMesh(const PreparedScene& scene, const MeshingOptions& options) {
    const double eps = mesh_epsilon(scene);
    double h = 0;
    PatchPlan plan = plan_patches(scene, options, eps, h);
    target_edge_m_ = h;
    std::vector<std::vector<Poly>>& sub = plan.polygons;
    const Contacts& contacts = plan.contacts;
    VertexIndex index;
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        const Piece& piece = scene.pieces[i];
        const bool two_sided = scene.materials[static_cast<std::size_t>(piece.material)].two_sided;
        for (int side = 0; side < (two_sided ? 2 : 1); ++side) {
            for (const Poly& p : sub[i]) {
                PatchGeometry g;
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
                for (const int q : contacts.overlays[i]) {
                    const Piece& over = scene.pieces[static_cast<std::size_t>(q)];
                    g.hidden =
                        g.hidden || inside_convex(g.centroid, over.vertices, over.normal, eps);
                }
                add_face(g, index);
                patches_.push_back(std::move(g));
            }
        }
    }
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
