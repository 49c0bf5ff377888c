#include "scene/floor_plan.h"

#include <algorithm>
#include <cmath>

#include "formfactor/quadrature.h"
#include "radiant/box.h"

namespace radiant {
namespace {

// A face counts as a horizontal floor when its normal is this close to straight up.
constexpr double kUpwardCosine = 1 - 1e-6;

using Point2 = std::pair<double, double>;  // (u, v)

struct Edge {
    Vec3 a, b;
};

std::vector<std::vector<Vec3>> faces_of(const Surface& s) {
    if (const auto* polygon = std::get_if<Polygon>(&s.geometry)) return {*polygon};
    if (const auto* mesh = std::get_if<MeshGeometry>(&s.geometry)) {
        std::vector<std::vector<Vec3>> out;
        for (const auto& face : mesh->faces) {
            auto& corners = out.emplace_back();
            for (const int k : face) corners.push_back(mesh->vertices[static_cast<std::size_t>(k)]);
        }
        return out;
    }
    // A room's floor faces up from its bottom, an object's top from its lid.
    const auto& box = std::get<BoxGeometry>(s.geometry);
    const double z = box.facing_in ? box.min.z : box.max.z;
    return {{{box.min.x, box.min.y, z},
             {box.max.x, box.min.y, z},
             {box.max.x, box.max.y, z},
             {box.min.x, box.max.y, z}}};
}

bool same_point(const Vec3& a, const Vec3& b, double tolerance) {
    return length_squared(a - b) <= tolerance * tolerance;
}

/// Edges of `faces` that no other face shares in the opposite direction: the outline. Edges
/// are sorted by their end's x, so each looks only at those whose end is within `tolerance` of
/// its start in x (a plant of 3,000 triangles: 9,000 edges, not 81 million pairs).
std::vector<Edge> outline(const std::vector<std::vector<Vec3>>& faces, double tolerance) {
    std::vector<Edge> edges;
    for (const auto& f : faces) {
        for (std::size_t k = 0; k < f.size(); ++k) edges.push_back({f[k], f[(k + 1) % f.size()]});
    }
    std::vector<Edge> by_end = edges;
    std::sort(by_end.begin(), by_end.end(),
              [](const Edge& p, const Edge& q) { return p.b.x < q.b.x; });
    std::vector<Edge> out;
    for (const Edge& e : edges) {
        auto o = std::lower_bound(by_end.begin(), by_end.end(), e.a.x - tolerance,
                                  [](const Edge& p, double x) { return p.b.x < x; });
        bool shared = false;
        for (; o != by_end.end() && o->b.x <= e.a.x + tolerance && !shared; ++o) {
            shared = same_point(e.a, o->b, tolerance) && same_point(e.b, o->a, tolerance);
        }
        if (!shared) out.push_back(e);
    }
    return out;
}

bool inside_polygon(const std::vector<Point2>& polygon, Point2 p) {
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Point2 a = polygon[i], b = polygon[j];
        if ((a.second > p.second) != (b.second > p.second) &&
            p.first <
                (b.first - a.first) * (p.second - a.second) / (b.second - a.second) + a.first) {
            inside = !inside;
        }
    }
    return inside;
}

double distance_to_segment(Point2 p, Point2 a, Point2 b) {
    const double du = b.first - a.first, dv = b.second - a.second;
    const double length2 = du * du + dv * dv;
    const double t =
        length2 > 0 ? std::clamp(((p.first - a.first) * du + (p.second - a.second) * dv) / length2,
                                 0.0, 1.0)
                    : 0.0;
    return std::hypot(p.first - a.first - t * du, p.second - a.second - t * dv);
}

double signed_volume(const std::vector<std::vector<Vec3>>& faces) {
    double v = 0;
    for (const auto& f : faces) {
        for (std::size_t k = 1; k + 1 < f.size(); ++k) v += dot(f[0], cross(f[k], f[k + 1])) / 6;
    }
    return v;
}

/// Parity of the faces crossed by the upward ray from x.
bool inside_mesh(const std::vector<std::vector<Vec3>>& faces, const Vec3& x) {
    bool inside = false;
    for (const auto& f : faces) {
        const Vec3 n = polygon_normal(f);
        if (std::abs(n.z) < 1e-12) continue;
        const double z = f[0].z - ((x.x - f[0].x) * n.x + (x.y - f[0].y) * n.y) / n.z;
        if (z <= x.z) continue;
        std::vector<Point2> flat;
        for (const Vec3& c : f) flat.emplace_back(c.x, c.y);
        if (inside_polygon(flat, {x.x, x.y})) inside = !inside;
    }
    return inside;
}

}  // namespace

std::variant<FloorPlan, std::string> FloorPlan::of(const Scene& scene,
                                                   const std::vector<std::string>& surfaces) {
    FloorPlan plan;
    std::vector<std::vector<Vec3>> floors;
    double extent = 0;
    for (const Surface& s : scene.surfaces) {
        if (std::find(surfaces.begin(), surfaces.end(), s.name) == surfaces.end()) continue;
        for (auto& f : faces_of(s)) {
            if (f.size() < 3 || polygon_normal(f).z < kUpwardCosine) continue;
            for (const Vec3& c : f) extent = std::max({extent, std::abs(c.x), std::abs(c.y)});
            floors.push_back(std::move(f));
        }
    }
    if (floors.empty())
        return std::string("the named surfaces have no upward-facing horizontal face");
    plan.tolerance_ = 1e-9 * std::max(1.0, extent);
    const std::vector<Edge> edges = outline(floors, plan.tolerance_);
    // The grid runs along the floor's longest outline edge, so a turned room gets a turned grid.
    double longest = 0;
    for (const Edge& e : edges) {
        const Vec3 d{e.b.x - e.a.x, e.b.y - e.a.y, 0};
        if (length(d) > longest) {
            longest = length(d);
            plan.u_axis_ = normalized(d);
        }
    }
    plan.v_axis_ = cross(Vec3{0, 0, 1}, plan.u_axis_);
    const auto flat = [&](const Vec3& x) {
        return Point2{dot(x, plan.u_axis_), dot(x, plan.v_axis_)};
    };
    plan.u0_ = plan.v0_ = 1e300;
    plan.u1_ = plan.v1_ = -1e300;
    for (const auto& f : floors) {
        Face& face = plan.faces_.emplace_back();
        face.z = f[0].z;
        for (const Vec3& c : f) {
            const Point2 p = flat(c);
            face.corners.push_back(p);
            plan.u0_ = std::min(plan.u0_, p.first), plan.u1_ = std::max(plan.u1_, p.first);
            plan.v0_ = std::min(plan.v0_, p.second), plan.v1_ = std::max(plan.v1_, p.second);
        }
    }
    plan.z_ = plan.faces_.front().z;
    for (const Edge& e : edges) plan.outline_.emplace_back(flat(e.a), flat(e.b));
    for (const Surface& s : scene.surfaces) {
        if (const auto* box = std::get_if<BoxGeometry>(&s.geometry)) {
            // A box is its own bounds: no faces needed.
            if (!box->facing_in) plan.solids_.push_back({{}, box->min, box->max});
            continue;
        }
        if (!std::holds_alternative<MeshGeometry>(s.geometry)) continue;
        auto faces = faces_of(s);
        if (!outline(faces, plan.tolerance_).empty() || !(signed_volume(faces) > 0)) continue;
        Box bounds;
        for (const auto& f : faces) bounds.add(f);
        plan.solids_.push_back({std::move(faces), bounds.lo, bounds.hi});
    }
    return plan;
}

std::optional<double> FloorPlan::height_at(double u, double v) const {
    for (const Face& f : faces_) {
        if (inside_polygon(f.corners, {u, v})) return f.z;
    }
    return std::nullopt;
}

bool FloorPlan::near_outline(double u, double v, double distance) const {
    return std::any_of(outline_.begin(), outline_.end(), [&](const auto& e) {
        return distance_to_segment({u, v}, e.first, e.second) < distance - tolerance_;
    });
}

bool FloorPlan::in_furniture(const Vec3& x) const {
    return std::any_of(solids_.begin(), solids_.end(), [&](const Solid& s) {
        if (s.faces.empty()) {
            return x.x > s.lo.x && x.x < s.hi.x && x.y > s.lo.y && x.y < s.hi.y && x.z > s.lo.z &&
                   x.z < s.hi.z;
        }
        const bool outside = x.x < s.lo.x || x.x > s.hi.x || x.y < s.lo.y || x.y > s.hi.y ||
                             x.z < s.lo.z || x.z > s.hi.z;
        return !outside && inside_mesh(s.faces, x);
    });
}

}  // namespace radiant
