// Test helpers: build small radiant::Scene values in code (rooms, panels, luminaires, sensors).
#pragma once

#include <cmath>
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
