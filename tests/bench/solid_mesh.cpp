#include "solid_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace radiant::bench {
namespace {

// Steps of the grid per metre. Dividing the rounded count (rather than multiplying by 1e-4)
// gives the double nearest the decimal, which prints as "3.804", not "3.8040000000000003".
constexpr double kStepsPerM = 1e4;

int add_vertex(MeshGeometry& mesh, Vec3 p) {
    mesh.vertices.push_back(snapped(p));
    return static_cast<int>(mesh.vertices.size()) - 1;
}

void add_triangle(MeshGeometry& mesh, int a, int b, int c) { mesh.faces.push_back({a, b, c}); }

// Two triangles of the quad a b c d (counter-clockwise seen from its front).
void add_quad(MeshGeometry& mesh, int a, int b, int c, int d) {
    add_triangle(mesh, a, b, c);
    add_triangle(mesh, a, c, d);
}

// Two unit vectors that make a right-handed frame (u, v, w) with w along `axis`.
std::pair<Vec3, Vec3> frame_around(Vec3 axis) {
    const Vec3 w = normalized(axis);
    const Vec3 helper = std::abs(w.z) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0};
    const Vec3 u = normalized(cross(helper, w));
    return {u, cross(w, u)};
}

}  // namespace

Vec3 snapped(Vec3 p) {
    for (int k = 0; k < 3; ++k) p[k] = std::round(p[k] * kStepsPerM) / kStepsPerM;
    return p;
}

void add_parallelepiped(MeshGeometry& mesh, Vec3 origin, Vec3 a, Vec3 b, Vec3 c) {
    // With a left-handed a, b, c the same corner order would face in.
    if (dot(cross(a, b), c) < 0) std::swap(a, b);
    std::array<int, 8> v{};  // corner i = origin + bit0·a + bit1·b + bit2·c
    for (int i = 0; i < 8; ++i) {
        v[i] = add_vertex(mesh, origin + a * (i & 1) + b * ((i >> 1) & 1) + c * ((i >> 2) & 1));
    }
    add_quad(mesh, v[0], v[2], v[3], v[1]);  // −c
    add_quad(mesh, v[4], v[5], v[7], v[6]);  // +c
    add_quad(mesh, v[0], v[1], v[5], v[4]);  // −b
    add_quad(mesh, v[2], v[6], v[7], v[3]);  // +b
    add_quad(mesh, v[0], v[4], v[6], v[2]);  // −a
    add_quad(mesh, v[1], v[3], v[7], v[5]);  // +a
}

void add_box(MeshGeometry& mesh, Vec3 lo, Vec3 hi) {
    add_parallelepiped(mesh, lo, {hi.x - lo.x, 0, 0}, {0, hi.y - lo.y, 0}, {0, 0, hi.z - lo.z});
}

void add_turned_box(MeshGeometry& mesh, Vec3 base_centre, Vec3 size, double yaw_rad) {
    const Vec3 along{std::cos(yaw_rad), std::sin(yaw_rad), 0};
    const Vec3 across{-along.y, along.x, 0};
    const Vec3 a = along * size.x, b = across * size.y;
    add_parallelepiped(mesh, base_centre - a * 0.5 - b * 0.5, a, b, {0, 0, size.z});
}

void add_frustum(MeshGeometry& mesh, Vec3 base, Vec3 axis, double base_radius, double top_radius,
                 int sides, double phase_rad) {
    const auto [u, v] = frame_around(axis);
    const int first = static_cast<int>(mesh.vertices.size());
    for (const auto& [centre, radius] : {std::pair{base, base_radius}, {base + axis, top_radius}}) {
        for (int k = 0; k < sides; ++k) {
            const double t = phase_rad + 2 * std::numbers::pi * k / sides;
            add_vertex(mesh, centre + u * (radius * std::cos(t)) + v * (radius * std::sin(t)));
        }
    }
    // Ring points run counter-clockwise about the axis: the top cap keeps their order, the
    // bottom reverses it, and each side quad runs bottom k, bottom k+1, top k+1, top k.
    const auto bottom = [&](int k) { return first + (k % sides); };
    const auto top = [&](int k) { return first + sides + (k % sides); };
    for (int k = 1; k + 1 < sides; ++k) {
        add_triangle(mesh, bottom(0), bottom(k + 1), bottom(k));
        add_triangle(mesh, top(0), top(k), top(k + 1));
    }
    for (int k = 0; k < sides; ++k) add_quad(mesh, bottom(k), bottom(k + 1), top(k + 1), top(k));
}

void add_leaf(MeshGeometry& mesh, const LeafShape& leaf) {
    const Vec3 d = normalized(leaf.direction);
    // The blade's side direction: horizontal across the midrib, turned by the roll.
    Vec3 side = normalized(cross(Vec3{0, 0, 1}, d));
    if (length(side) == 0) side = {1, 0, 0};
    const Vec3 lift = cross(d, side);
    const Vec3 s = side * std::cos(leaf.roll_rad) + lift * std::sin(leaf.roll_rad);
    const Vec3 n = cross(d, s);
    const auto midrib = [&](double t) {
        return leaf.base + d * (leaf.length_m * t) - Vec3{0, 0, leaf.droop * leaf.length_m * t * t};
    };
    const int n_seg = std::max(2, leaf.segments);
    const int base = add_vertex(mesh, leaf.base);
    std::array<int, 3> previous{base, base, base};  // left, middle, right
    for (int k = 1; k < n_seg; ++k) {
        const double t = static_cast<double>(k) / n_seg;
        // Widest a little before the middle, like most leaves.
        const double half = 0.5 * leaf.width_m * std::pow(std::sin(std::numbers::pi * t), 0.7);
        const Vec3 m = midrib(t);
        const Vec3 across = s * (half * std::cos(leaf.fold_rad));
        const Vec3 up = n * (half * std::sin(leaf.fold_rad));
        const std::array<int, 3> ring{add_vertex(mesh, m - across + up), add_vertex(mesh, m),
                                      add_vertex(mesh, m + across + up)};
        if (k == 1) {
            add_triangle(mesh, base, ring[1], ring[0]);
            add_triangle(mesh, base, ring[2], ring[1]);
        } else {
            add_quad(mesh, previous[0], previous[1], ring[1], ring[0]);
            add_quad(mesh, previous[1], previous[2], ring[2], ring[1]);
        }
        previous = ring;
    }
    const int tip = add_vertex(mesh, midrib(1));
    add_triangle(mesh, previous[0], previous[1], tip);
    add_triangle(mesh, previous[1], previous[2], tip);
}

}  // namespace radiant::bench
