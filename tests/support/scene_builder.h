// Test helpers: build small radiant::Scene values in code (rooms, panels, luminaires, sensors).
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant::testing {

inline Material gray(const std::string& name, double reflectance, double exitance = 0) {
    Material m;
    m.name = name;
    m.reflectance = {reflectance, reflectance, reflectance};
    if (exitance > 0) {
        Emission e;
        e.kind = Emission::Kind::exitance;
        e.value = exitance;
        m.emission = e;
    }
    return m;
}

/// Rectangle origin, origin+u, origin+u+v, origin+v; its front faces along u × v.
inline Polygon rect(Vec3 origin, Vec3 u, Vec3 v) {
    return {origin, origin + u, origin + u + v, origin + v};
}

inline Surface polygon_surface(const std::string& name, const std::string& material,
                               Polygon polygon) {
    Surface s;
    s.name = name;
    s.material = material;
    s.geometry = std::move(polygon);
    return s;
}

inline Surface box_surface(const std::string& name, const std::string& material, Vec3 min, Vec3 max,
                           bool facing_in) {
    Surface s;
    s.name = name;
    s.material = material;
    s.geometry = BoxGeometry{min, max, facing_in};
    return s;
}

/// Floor and four walls of the inward-facing room [0,X] × [0,Y] × [0,Z] as polygons (no
/// ceiling), named floor, wall-south, wall-north, wall-west, wall-east.
inline std::vector<Surface> room_without_ceiling(double x, double y, double z,
                                                 const std::string& material) {
    return {
        polygon_surface("floor", material, rect({0, 0, 0}, {x, 0, 0}, {0, y, 0})),
        polygon_surface("wall-south", material, rect({0, 0, 0}, {0, 0, z}, {x, 0, 0})),
        polygon_surface("wall-north", material, rect({0, y, 0}, {x, 0, 0}, {0, 0, z})),
        polygon_surface("wall-west", material, rect({0, 0, 0}, {0, y, 0}, {0, 0, z})),
        polygon_surface("wall-east", material, rect({x, 0, 0}, {0, 0, z}, {0, y, 0})),
    };
}

/// Downward-facing ceiling rectangle [x0,x1] × [y0,y1] at height z.
inline Polygon ceiling_rect(double x0, double x1, double y0, double y1, double z) {
    return rect({x0, y0, z}, {0, y1 - y0, 0}, {x1 - x0, 0, 0});
}

/// nx × ny square ceiling tiles of side `side`, facing down at height z, the first at (x0, y0)
/// and the others `pitch` apart; named PREFIX-i-j.
inline std::vector<Surface> ceiling_tiles(const std::string& prefix, const std::string& material,
                                          int nx, int ny, double x0, double y0, double pitch,
                                          double side, double z) {
    std::vector<Surface> tiles;
    for (int i = 0; i < nx; ++i) {
        for (int j = 0; j < ny; ++j) {
            const double x = x0 + pitch * i, y = y0 + pitch * j;
            tiles.push_back(
                polygon_surface(prefix + "-" + std::to_string(i) + "-" + std::to_string(j),
                                material, ceiling_rect(x, x + side, y, y + side, z)));
        }
    }
    return tiles;
}

/// The closed room [0,X] × [0,Y] × [0,Z]: room_without_ceiling's surfaces, then its `ceiling`.
inline std::vector<Surface> closed_room(double x, double y, double z, const std::string& material) {
    std::vector<Surface> surfaces = room_without_ceiling(x, y, z, material);
    surfaces.push_back(polygon_surface("ceiling", material, ceiling_rect(0, x, 0, y, z)));
    return surfaces;
}

/// A closed 4 × 4 × 3 m room whose ceiling has a flush 1 × 1 m emitting panel in the middle
/// (the ceiling is cut around it). Every surface has `reflectance`; the panel emits `exitance`.
inline Scene room_with_ceiling_panel(double reflectance, double exitance) {
    Scene scene;
    scene.name = "room-ceiling-panel";
    scene.materials = {gray("wall", reflectance), gray("panel", reflectance, exitance)};
    scene.surfaces = room_without_ceiling(4, 4, 3, "wall");
    scene.surfaces.push_back(polygon_surface("ceiling-1", "wall", ceiling_rect(0, 4, 0, 1.5, 3)));
    scene.surfaces.push_back(polygon_surface("ceiling-2", "wall", ceiling_rect(0, 4, 2.5, 4, 3)));
    scene.surfaces.push_back(
        polygon_surface("ceiling-3", "wall", ceiling_rect(0, 1.5, 1.5, 2.5, 3)));
    scene.surfaces.push_back(
        polygon_surface("ceiling-4", "wall", ceiling_rect(2.5, 4, 1.5, 2.5, 3)));
    scene.surfaces.push_back(
        polygon_surface("panel", "panel", ceiling_rect(1.5, 2.5, 1.5, 2.5, 3)));
    return scene;
}

inline Luminaire luminaire(const std::string& name, Vec3 position, double flux,
                           Distribution distribution = Distribution::isotropic,
                           Vec3 aim = {0, 0, -1}) {
    Luminaire l;
    l.name = name;
    l.position = position;
    l.flux_lm = flux;
    l.distribution = distribution;
    l.aim = aim;
    return l;
}

inline SensorSet sensor_points(const std::string& name, std::vector<Vec3> points,
                               Vec3 normal = {0, 0, 1}) {
    SensorSet s;
    s.name = name;
    s.points = std::move(points);
    s.normal = normal;
    return s;
}

/// nu × nv cell centres of the rectangle origin + [0,1]u + [0,1]v, u fastest.
inline SensorSet sensor_grid(const std::string& name, Vec3 origin, Vec3 u, Vec3 v, int nu, int nv,
                             Vec3 normal = {0, 0, 1}) {
    std::vector<Vec3> points;
    for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
            points.push_back(origin + u * ((i + 0.5) / nu) + v * ((j + 0.5) / nv));
        }
    }
    return sensor_points(name, std::move(points), normal);
}

/// The six faces of the box [min, max], normals inward (a room) or outward (an object).
inline std::vector<Polygon> box_faces(Vec3 lo, Vec3 hi, bool facing_in) {
    const Vec3 d = hi - lo;
    std::vector<Polygon> faces{
        rect(lo, {d.x, 0, 0}, {0, d.y, 0}),                  // z = lo, normal +z
        rect({lo.x, lo.y, hi.z}, {0, d.y, 0}, {d.x, 0, 0}),  // z = hi, normal −z
        rect(lo, {0, 0, d.z}, {d.x, 0, 0}),                  // y = lo, normal +y
        rect({lo.x, hi.y, lo.z}, {d.x, 0, 0}, {0, 0, d.z}),  // y = hi, normal −y
        rect(lo, {0, d.y, 0}, {0, 0, d.z}),                  // x = lo, normal +x
        rect({hi.x, lo.y, lo.z}, {0, 0, d.z}, {0, d.y, 0}),  // x = hi, normal −x
    };
    if (!facing_in) {
        for (auto& f : faces) std::reverse(f.begin(), f.end());
    }
    return faces;
}

/// A sphere of `rings` × `segments` faces about `centre`, facing out (a bulb): quads between
/// rings of latitude, triangles at the poles.
inline Surface sphere_surface(const std::string& name, const std::string& material, Vec3 centre,
                              double radius, int rings, int segments) {
    MeshGeometry mesh;
    const double pi = 3.14159265358979323846;
    mesh.vertices.push_back(centre + Vec3{0, 0, -radius});
    for (int r = 1; r < rings; ++r) {
        const double polar = pi * r / rings;
        for (int k = 0; k < segments; ++k) {
            const double a = 2 * pi * k / segments;
            mesh.vertices.push_back(centre + radius * Vec3{std::sin(polar) * std::cos(a),
                                                           std::sin(polar) * std::sin(a),
                                                           -std::cos(polar)});
        }
    }
    mesh.vertices.push_back(centre + Vec3{0, 0, radius});
    const int top = static_cast<int>(mesh.vertices.size()) - 1;
    const auto at = [&](int ring, int k) { return 1 + (ring - 1) * segments + (k % segments); };
    for (int k = 0; k < segments; ++k) {
        mesh.faces.push_back({0, at(1, k + 1), at(1, k)});
        for (int r = 1; r + 1 < rings; ++r)
            mesh.faces.push_back({at(r, k), at(r, k + 1), at(r + 1, k + 1), at(r + 1, k)});
        mesh.faces.push_back({at(rings - 1, k), at(rings - 1, k + 1), top});
    }
    Surface s;
    s.name = name;
    s.material = material;
    s.geometry = std::move(mesh);
    return s;
}

/// §2.2 furnace: a closed unit cube whose every face emits E = 1 and reflects ρ: B = 1/(1 − ρ).
inline Scene furnace_cube(double rho) {
    Scene scene;
    scene.name = "furnace-cube";
    scene.materials = {gray("glow", rho, 1.0)};
    scene.surfaces = {box_surface("box", "glow", {0, 0, 0}, {1, 1, 1}, true)};
    return scene;
}

/// Replaces every box surface by six polygon surfaces named "<name>/0" … "<name>/5".
inline Scene boxes_as_polygons(Scene scene) {
    std::vector<Surface> out;
    for (auto& s : scene.surfaces) {
        if (const auto* box = std::get_if<BoxGeometry>(&s.geometry)) {
            const auto faces = box_faces(box->min, box->max, box->facing_in);
            for (std::size_t k = 0; k < faces.size(); ++k) {
                out.push_back(
                    polygon_surface(s.name + "/" + std::to_string(k), s.material, faces[k]));
            }
        } else {
            out.push_back(s);
        }
    }
    scene.surfaces = std::move(out);
    return scene;
}

/// The scene rotated by `degrees` about the vertical axis through `centre` (boxes become
/// polygons first); luminaire aims and sensor normals turn with it.
inline Scene rotated_about_z(Scene scene, double degrees, Vec3 centre) {
    scene = boxes_as_polygons(std::move(scene));
    const double a = degrees * 3.14159265358979323846 / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    auto turn = [&](const Vec3& v) { return Vec3{c * v.x - s * v.y, s * v.x + c * v.y, v.z}; };
    auto move = [&](const Vec3& p) { return centre + turn(p - centre); };
    for (auto& surf : scene.surfaces) {
        if (auto* poly = std::get_if<Polygon>(&surf.geometry)) {
            for (auto& p : *poly) p = move(p);
        } else if (auto* mesh = std::get_if<MeshGeometry>(&surf.geometry)) {
            for (auto& p : mesh->vertices) p = move(p);
        }
    }
    for (auto& l : scene.luminaires) {
        l.position = move(l.position);
        l.aim = turn(l.aim);
    }
    for (auto& set : scene.sensors) {
        for (auto& p : set.points) p = move(p);
        set.normal = turn(set.normal);
    }
    return scene;
}

/// Area-weighted mean radiosity over the surfaces whose names start with `prefix`.
inline double mean_radiosity_of(const Result& r, const std::string& prefix) {
    double sum = 0, area = 0;
    for (const auto& s : r.surfaces) {
        if (s.name.rfind(prefix, 0) != 0) continue;
        sum += s.area_m2 * s.average_radiosity;
        area += s.area_m2;
    }
    return area > 0 ? sum / area : 0;
}

/// `count` random triangles ("shard-0", …) inside a cube of edge `size` about `centre`, crossing
/// each other: a radiosity mesh cuts each along every crossing (600 in 0.3 m make 1.65 million
/// slivers). Deterministic in `seed`.
inline std::vector<Surface> crossing_shards(int count, Vec3 centre, double size,
                                            const std::string& material, unsigned seed = 7) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> at(-size / 2, size / 2);
    std::vector<Surface> shards;
    for (int i = 0; i < count; ++i) {
        Polygon triangle;
        for (int v = 0; v < 3; ++v) triangle.push_back(centre + Vec3{at(rng), at(rng), at(rng)});
        shards.push_back(polygon_surface("shard-" + std::to_string(i), material, triangle));
    }
    return shards;
}

/// Area-weighted mean radiosity over all surfaces of a result.
inline double mean_radiosity(const Result& r) {
    double sum = 0, area = 0;
    for (const auto& s : r.surfaces) {
        sum += s.area_m2 * s.average_radiosity;
        area += s.area_m2;
    }
    return area > 0 ? sum / area : 0;
}

}  // namespace radiant::testing
