#include "office_scene.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

#include "scene_builder.h"

namespace radiant::bench {
namespace {

constexpr double kRoom = 32.0;  // square plan, metres
constexpr double kHeight = 3.0;
constexpr int kPanelsPerSide = 8;  // 4 m spacing
constexpr double kPanel = 0.6;
// About 500 lx on the work plane with the furniture of 64 groups (measured: 380–620 lx).
constexpr double kPanelExitance = 30000.0;
constexpr double kWorkPlane = 0.8;
constexpr int kSensorsPerSide = 32;

// Appends the 12 outward-facing triangles of the box [lo, hi] to `mesh`.
void add_box(MeshGeometry& mesh, Vec3 lo, Vec3 hi) {
    for (const Polygon& face : testing::box_faces(lo, hi, false)) {
        const int base = static_cast<int>(mesh.vertices.size());
        mesh.vertices.insert(mesh.vertices.end(), face.begin(), face.end());
        mesh.faces.push_back({base, base + 1, base + 2});
        mesh.faces.push_back({base, base + 2, base + 3});
    }
}

// A 1.6 × 0.8 m desk centred on x = cx over y ∈ [y0, y0 + 0.8]: a 3 cm top at 0.70 m on four
// legs.
void add_desk(MeshGeometry& mesh, double cx, double y0) {
    add_box(mesh, {cx - 0.8, y0, 0.70}, {cx + 0.8, y0 + 0.8, 0.73});
    for (const double x : {cx - 0.77, cx + 0.72}) {
        for (const double y : {y0 + 0.03, y0 + 0.72}) {
            add_box(mesh, {x, y, 0}, {x + 0.05, y + 0.05, 0.70});
        }
    }
}

// A chair whose 0.45 m seat is centred at (cx, cy), on four legs, with its backrest on the side
// of −y when `back_sign` is −1, of +y when +1.
void add_chair(MeshGeometry& mesh, double cx, double cy, double back_sign) {
    add_box(mesh, {cx - 0.225, cy - 0.225, 0.42}, {cx + 0.225, cy + 0.225, 0.47});
    const double back_y0 = back_sign < 0 ? cy - 0.225 : cy + 0.175;
    add_box(mesh, {cx - 0.225, back_y0, 0.47}, {cx + 0.225, back_y0 + 0.05, 0.92});
    for (const double x : {cx - 0.2, cx + 0.16}) {
        for (const double y : {cy - 0.2, cy + 0.16}) {
            add_box(mesh, {x, y, 0}, {x + 0.04, y + 0.04, 0.42});
        }
    }
}

// A 0.4 m deep, 1.8 m wide, 1.8 m high open shelf along y at x ∈ [x0, x0 + 0.4]: two sides, a
// back, and five boards (bottom, three shelves, top), each a closed box.
void add_shelf(MeshGeometry& mesh, double x0, double cy) {
    const double y0 = cy - 0.9, y1 = cy + 0.9, x1 = x0 + 0.4;
    add_box(mesh, {x0, y0, 0}, {x1, y0 + 0.02, 1.8});
    add_box(mesh, {x0, y1 - 0.02, 0}, {x1, y1, 1.8});
    add_box(mesh, {x1 - 0.02, y0 + 0.02, 0}, {x1, y1 - 0.02, 1.8});
    for (const double z : {0.0, 0.44, 0.88, 1.32, 1.78}) {
        add_box(mesh, {x0, y0 + 0.02, z}, {x1 - 0.02, y1 - 0.02, z + 0.02});
    }
}

Surface mesh_surface(const std::string& name, const std::string& material, MeshGeometry mesh) {
    Surface s;
    s.name = name;
    s.material = material;
    s.geometry = std::move(mesh);
    return s;
}

}  // namespace

Scene furnished_office(int units) {
    const int side = static_cast<int>(std::lround(std::sqrt(units)));
    if (units < 1 || side * side != units || (side & (side - 1)) != 0) {
        throw std::invalid_argument("furniture units must be a power of four");
    }
    Scene scene;
    scene.name = "office-x" + std::to_string(units);
    scene.materials = {testing::gray("floor", 0.2),
                       testing::gray("wall", 0.5),
                       testing::gray("ceiling", 0.8),
                       testing::gray("desk", 0.45),
                       testing::gray("chair", 0.3),
                       testing::gray("shelf", 0.6),
                       testing::gray("panel", 0.0, kPanelExitance)};
    scene.surfaces = testing::room_without_ceiling(kRoom, kRoom, kHeight, "wall");
    scene.surfaces[0].material = "floor";
    scene.surfaces.push_back(testing::polygon_surface(
        "ceiling", "ceiling", testing::ceiling_rect(0, kRoom, 0, kRoom, kHeight)));
    const double spacing = kRoom / kPanelsPerSide;
    for (int j = 0; j < kPanelsPerSide; ++j) {
        for (int i = 0; i < kPanelsPerSide; ++i) {
            const double x = (i + 0.5) * spacing, y = (j + 0.5) * spacing;
            // 1 cm below the ceiling: a surface-mounted panel, not a coplanar overlay.
            scene.surfaces.push_back(testing::polygon_surface(
                "panel-" + std::to_string(j * kPanelsPerSide + i), "panel",
                testing::ceiling_rect(x - kPanel / 2, x + kPanel / 2, y - kPanel / 2,
                                      y + kPanel / 2, kHeight - 0.01)));
        }
    }
    MeshGeometry desks, chairs, shelves;
    const double cell = kRoom / side;
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            // Group centre, shifted off the panel grid so desks are not all right under a panel.
            const double cx = (i + 0.5) * cell - 0.5, cy = (j + 0.5) * cell;
            add_desk(desks, cx, cy - 0.825);  // back to back, 5 cm apart
            add_desk(desks, cx, cy + 0.025);
            add_chair(chairs, cx, cy - 1.15, -1);
            add_chair(chairs, cx, cy + 1.15, +1);
            add_shelf(shelves, cx + 1.2, cy);
        }
    }
    scene.surfaces.push_back(mesh_surface("desks", "desk", std::move(desks)));
    scene.surfaces.push_back(mesh_surface("chairs", "chair", std::move(chairs)));
    scene.surfaces.push_back(mesh_surface("shelves", "shelf", std::move(shelves)));
    scene.sensors = {testing::sensor_grid("workplane", {0, 0, kWorkPlane}, {kRoom, 0, 0},
                                          {0, kRoom, 0}, kSensorsPerSide, kSensorsPerSide)};
    return scene;
}

std::size_t input_triangles(const Scene& scene) {
    std::size_t n = 0;
    for (const auto& s : scene.surfaces) {
        if (const auto* poly = std::get_if<Polygon>(&s.geometry)) {
            n += poly->size() - 2;
        } else if (const auto* mesh = std::get_if<MeshGeometry>(&s.geometry)) {
            for (const auto& f : mesh->faces) n += f.size() - 2;
        } else {
            n += 12;
        }
    }
    return n;
}

}  // namespace radiant::bench
