#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_set>
#include <vector>

#include "photometry/intensity_table.h"
#include "radiant/box.h"
#include "radiant/scene.h"
#include "scene/check_lighting_design.h"
#include "scene/json_pointer.h"

namespace radiant {
namespace {

// Relative tolerances: scenes come in any unit, so absolute thresholds would be wrong somewhere.
constexpr double kZeroAreaTolerance = 1e-12;  ///< area / (bounding-box diagonal)²
constexpr double kPlanarityTolerance = 1e-3;  ///< distance from the plane / polygon size

class Checker {
public:
    explicit Checker(std::vector<Problem>& problems) : problems_(problems) {}

    void report(std::string pointer, std::string message) {
        problems_.push_back({std::move(pointer), std::move(message)});
    }

    /// Reports each non-finite component; returns whether all were finite.
    bool finite(const Vec3& v, const std::string& pointer, const char* what = "coordinate") {
        bool ok = true;
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(v[c])) {
                report(at(pointer, static_cast<std::size_t>(c)),
                       std::string(what) + " must be a finite number");
                ok = false;
            }
        }
        return ok;
    }

    bool finite_all(const std::vector<Vec3>& points, const std::string& pointer) {
        bool ok = true;
        for (std::size_t k = 0; k < points.size(); ++k)
            ok = finite(points[k], at(pointer, k)) && ok;
        return ok;
    }

    void non_zero(const Vec3& v, const std::string& pointer, const char* what) {
        if (finite(v, pointer, "component") && length(v) <= 1e-300) {
            report(pointer, std::string(what) + " must not be the zero vector");
        }
    }

    void color(const Rgb& rgb, const std::string& pointer) {
        bool ok = true;
        for (std::size_t c = 0; c < 3; ++c) {
            if (!std::isfinite(rgb[c]) || rgb[c] < 0) {
                report(at(pointer, c), "color must be a finite number >= 0");
                ok = false;
            }
        }
        // A colour is normalised to luminance 1, which needs some luminance to start from.
        if (ok && 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2] <= 0) {
            report(pointer, "color must not be black");
        }
    }

    /// Area, planarity and size checks of one planar polygon (a surface or a mesh face).
    void planar_polygon(const std::vector<Vec3>& v, const std::string& pointer, const char* what) {
        const Box box = bounding_box(v);
        Vec3 newell{}, centroid{};
        for (std::size_t k = 0; k < v.size(); ++k) {
            newell += cross(v[k], v[(k + 1) % v.size()]);
            centroid += v[k];
        }
        centroid = centroid / static_cast<double>(v.size());
        // The bounding-box diagonal stands in for the diameter: O(n), and within √3 of it.
        const double size = length(box.size());
        const double area = 0.5 * length(newell);
        if (!(area > kZeroAreaTolerance * size * size)) {
            report(pointer, std::string(what) + " has zero area");
            return;
        }
        // Newell's normal through the centroid is the least-squares plane for planar-ish input.
        const Vec3 n = normalized(newell);
        double off = 0;
        for (const Vec3& p : v) off = std::max(off, std::abs(dot(p - centroid, n)));
        if (off > kPlanarityTolerance * size) {
            report(pointer, std::string(what) + " is not planar (a vertex is " +
                                std::to_string(off) +
                                " off its plane, more than 1e-3 of its size)");
        }
    }

private:
    std::vector<Problem>& problems_;
};

void check_materials(const Scene& scene, Checker& check) {
    std::unordered_set<std::string> seen;
    for (const Material& m : scene.materials) {
        const std::string base = "/materials/" + escape_pointer_token(m.name);
        if (!seen.insert(m.name).second) check.report(base, "duplicate material name");
        for (std::size_t c = 0; c < 3; ++c) {
            const double r = m.reflectance[c];
            const std::string p =
                m.rgb_reflectance ? at(base + "/reflectance", c) : base + "/reflectance";
            if (!std::isfinite(r)) {
                check.report(p, "reflectance must be a finite number");
            } else if (r < 0 || r >= 1) {
                check.report(p, "reflectance must be in [0, 1)");
            }
            if (!m.rgb_reflectance) break;
        }
        if (m.emission) {
            const bool flux = m.emission->kind == Emission::Kind::flux;
            const std::string p = base + (flux ? "/emission/flux" : "/emission/exitance");
            if (!std::isfinite(m.emission->value) || m.emission->value < 0) {
                check.report(p, "emission must be a finite number >= 0");
            }
            if (m.emission->color) check.color(*m.emission->color, base + "/emission/color");
        }
    }
}

// A polygon or face of more vertices than `limit` is refused before it is triangulated, which
// takes time in the square of its vertices (a 100 000-vertex star: 14 s).
bool within_vertex_limit(std::size_t vertices, std::size_t limit, const std::string& pointer,
                         const char* what, Checker& check) {
    if (vertices <= limit) return true;
    check.report(pointer, std::string(what) + " of " + std::to_string(vertices) +
                              " vertices, over the limit of " + std::to_string(limit) +
                              " for one; split it, or give it as a mesh of smaller faces");
    return false;
}

void check_mesh(const MeshGeometry& mesh, const std::string& base, std::size_t max_face_vertices,
                Checker& check) {
    const bool vertices_ok = check.finite_all(mesh.vertices, base + "/vertices");
    if (mesh.faces.empty()) check.report(base + "/faces", "a mesh needs at least one face");
    for (std::size_t k = 0; k < mesh.faces.size(); ++k) {
        const std::vector<int>& face = mesh.faces[k];
        const std::string p = at(base + "/faces", k);
        if (face.size() < 3) {
            check.report(p, "a face needs at least 3 vertices");
            continue;
        }
        if (!within_vertex_limit(face.size(), max_face_vertices, p, "a face", check)) continue;
        std::vector<Vec3> corners;
        for (std::size_t m = 0; m < face.size(); ++m) {
            if (face[m] < 0 || static_cast<std::size_t>(face[m]) >= mesh.vertices.size()) {
                check.report(at(p, m), "face index " + std::to_string(face[m]) +
                                           " is out of range (the mesh has " +
                                           std::to_string(mesh.vertices.size()) + " vertices)");
            } else {
                corners.push_back(mesh.vertices[static_cast<std::size_t>(face[m])]);
            }
        }
        if (vertices_ok && corners.size() == face.size()) check.planar_polygon(corners, p, "face");
    }
}

void check_surfaces(const Scene& scene, const SceneLimits& limits, Checker& check) {
    std::unordered_set<std::string> materials;
    for (const Material& m : scene.materials) materials.insert(m.name);
    if (scene.surfaces.empty()) check.report("/surfaces", "the scene has no surfaces");
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        const Surface& s = scene.surfaces[i];
        const std::string base = at("/surfaces", i);
        if (!materials.contains(s.material)) {
            check.report(base + "/material", "unknown material \"" + s.material + "\"");
        }
        if (const auto* polygon = std::get_if<Polygon>(&s.geometry)) {
            const std::string p = base + "/polygon";
            if (polygon->size() < 3) {
                check.report(p, "a polygon needs at least 3 vertices");
            } else if (within_vertex_limit(polygon->size(), limits.max_polygon_vertices, p,
                                           "a polygon", check) &&
                       check.finite_all(*polygon, p)) {
                check.planar_polygon(*polygon, p, "polygon");
            }
        } else if (const auto* mesh = std::get_if<MeshGeometry>(&s.geometry)) {
            check_mesh(*mesh, base + "/mesh", limits.max_polygon_vertices, check);
        } else {
            const auto& box = std::get<BoxGeometry>(s.geometry);
            // Both corners are checked, so that each bad one is reported.
            const bool min_ok = check.finite(box.min, base + "/box/min");
            const bool max_ok = check.finite(box.max, base + "/box/max");
            if (min_ok && max_ok &&
                !(box.min.x < box.max.x && box.min.y < box.max.y && box.min.z < box.max.z)) {
                check.report(base + "/box", "box min must be below max in every axis");
            }
        }
    }
}

void check_luminaires(const Scene& scene, Checker& check) {
    for (std::size_t i = 0; i < scene.luminaires.size(); ++i) {
        const Luminaire& l = scene.luminaires[i];
        const std::string base = at("/luminaires", i);
        check.finite(l.position, base + "/position");
        if (l.flux_lm && (!std::isfinite(*l.flux_lm) || *l.flux_lm < 0)) {
            check.report(base + "/flux", "flux must be a finite number >= 0");
        }
        if (!l.flux_lm && l.distribution != Distribution::photometric) {
            check.report(base + "/flux", "flux is required unless the distribution is a table");
        }
        if (l.distribution == Distribution::photometric) {
            const std::string problem =
                l.photometry ? photometric_table_problem(*l.photometry) : "missing table";
            if (!problem.empty()) check.report(base + "/distribution", problem);
        }
        if (!std::isfinite(l.rotation_deg)) {
            check.report(base + "/rotation", "rotation must be a finite number");
        }
        check.non_zero(l.aim, base + "/aim", "aim");
        if (l.color) check.color(*l.color, base + "/color");
    }
}

void check_workplane(const Scene& scene, const Workplane& w, const std::string& base,
                     Checker& check) {
    if (w.surfaces.empty()) check.report(base + "/surfaces", "name at least one floor surface");
    for (std::size_t k = 0; k < w.surfaces.size(); ++k) {
        const bool known = std::any_of(scene.surfaces.begin(), scene.surfaces.end(),
                                       [&](const Surface& s) { return s.name == w.surfaces[k]; });
        if (!known) {
            check.report(at(base + "/surfaces", k), "unknown surface \"" + w.surfaces[k] + "\"");
        }
    }
    if (w.height && !std::isfinite(*w.height)) {
        check.report(base + "/height", "height must be a finite number");
    }
    if (w.border && !(std::isfinite(*w.border) && *w.border >= 0)) {
        check.report(base + "/border", "border must be a finite number >= 0");
    }
    if (w.spacing && !(std::isfinite(*w.spacing) && *w.spacing > 0)) {
        check.report(base + "/spacing", "spacing must be a finite number > 0");
    }
}

void check_sensors(const Scene& scene, Checker& check) {
    for (std::size_t i = 0; i < scene.sensors.size(); ++i) {
        const SensorSet& s = scene.sensors[i];
        const std::string base = at("/sensors", i);
        if (s.workplane) {
            check_workplane(scene, *s.workplane, base + "/workplane", check);
        } else if (s.points.empty()) {
            check.report(base + "/points", "a sensor set needs at least one point");
        }
        check.finite_all(s.points, base + "/points");
        check.non_zero(s.normal, base + "/normal", "normal");
    }
}

void check_settings(const Settings& settings, Checker& check) {
    if (!(settings.tolerance > 0 && settings.tolerance < 1)) {
        check.report("/settings/tolerance", "tolerance must be in (0, 1)");
    }
    if (settings.max_seconds &&
        !(std::isfinite(*settings.max_seconds) && *settings.max_seconds > 0)) {
        check.report("/settings/max_seconds", "max_seconds must be a finite number > 0");
    }
}

void check_limits(const Scene& scene, const SceneLimits& limits, Checker& check) {
    auto over = [&](const char* pointer, std::size_t count, std::size_t limit,
                    const std::string& what) {
        if (count > limit) {
            check.report(pointer, std::to_string(count) + " " + what + ", over the limit of " +
                                      std::to_string(limit));
        }
    };
    std::size_t vertices = 0, large = 0;  // large: of polygons and faces of many vertices
    auto count_large = [&](std::size_t n) {
        if (n > limits.large_polygon_vertices) large += n;
    };
    for (const Surface& s : scene.surfaces) {
        if (const auto* polygon = std::get_if<Polygon>(&s.geometry)) {
            vertices += polygon->size();
            count_large(polygon->size());
        } else if (const auto* mesh = std::get_if<MeshGeometry>(&s.geometry)) {
            vertices += mesh->vertices.size();
            for (const std::vector<int>& face : mesh->faces) count_large(face.size());
        } else {
            vertices += 8;
        }
    }
    std::size_t points = 0;
    for (const SensorSet& s : scene.sensors) points += s.points.size();
    over("/surfaces", scene.surfaces.size(), limits.max_surfaces, "surfaces");
    over("/surfaces", vertices, limits.max_vertices, "vertices");
    over("/surfaces", large, limits.max_large_polygon_vertices,
         "vertices in polygons and faces of over " + std::to_string(limits.large_polygon_vertices) +
             " vertices each");
    over("/luminaires", scene.luminaires.size(), limits.max_luminaires, "luminaires");
    over("/sensors", points, limits.max_sensor_points, "sensor points");
}

}  // namespace

std::vector<Problem> check_scene(const Scene& scene, const SceneLimits& limits) {
    std::vector<Problem> problems;
    Checker check(problems);
    check_limits(scene, limits, check);
    check_materials(scene, check);
    check_surfaces(scene, limits, check);
    check_luminaires(scene, check);
    check_sensors(scene, check);
    check_settings(scene.settings, check);
    check_lighting_design(scene, limits, problems);
    return problems;
}

}  // namespace radiant
