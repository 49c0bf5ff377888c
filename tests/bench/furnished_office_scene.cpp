#include "furnished_office_scene.h"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "office_furniture.h"
#include "scene_builder.h"
#include "seeded_random.h"
#include "solid_mesh.h"

namespace radiant::bench {
namespace {

constexpr double kPi = std::numbers::pi;

// Six panels in a 3 × 2 grid; 4000 lm each, like a 1200 × 600 LED panel.
constexpr double kPanelLengthM = 1.2, kPanelWidthM = 0.6, kPanelFluxLm = 4000;
constexpr std::array<double, 3> kPanelX{kRoomWidthM / 6, kRoomWidthM / 2, 5 * kRoomWidthM / 6};
constexpr std::array<double, 2> kPanelY{kRoomDepthM / 4, 3 * kRoomDepthM / 4};
// A surface-mounted panel hangs 1 cm below the ceiling, not coplanar with it.
constexpr double kPanelDropM = 0.01, kDownlightDropM = 0.02;

constexpr double kWorkPlaneM = 0.8, kWorkPlaneBorderM = 0.5, kWorkPlaneSpacingM = 0.45;

// Door openings (every wall of a room in the floor has one; the single room keeps the space in
// front of them free too): in the west and east walls over y ∈ [kSideDoorY, + width], in the
// south and north walls over x ∈ [kEndDoorX, + width].
constexpr double kDoorWidthM = 0.9, kDoorHeightM = 2.1;
constexpr double kSideDoorY = 4.3, kEndDoorX = 3.7;
constexpr double kPartitionM = 0.12;

std::vector<Material> room_materials(bool panels) {
    std::vector<Material> out{testing::gray("floor", 0.2), testing::gray("wall", 0.5),
                              testing::gray("ceiling", 0.8)};
    if (panels) {
        out.push_back(testing::gray("panel", 0.5, kPanelFluxLm / (kPanelLengthM * kPanelWidthM)));
    }
    for (Material& m : furniture_materials()) out.push_back(std::move(m));
    return out;
}

// Everything in one room but its shell, in room coordinates. The layout is fixed (desk blocks
// in the middle, shelves on the north wall, plants in the corners, nothing in front of a door);
// what stands where within it, and every piece's details, come from the seed.
MaterialMeshes furnish_room(std::uint64_t seed) {
    SeededRandom random(seed);
    MaterialMeshes meshes;
    // Desks: a block of four back to back, and a pair turned across the room; each desk's user
    // sits on its −y side.
    std::vector<Placement> desks{{{1.7, 2.595, 0}, 0},        {{3.3, 2.595, 0}, 0},
                                 {{1.7, 3.405, 0}, kPi},      {{3.3, 3.405, 0}, kPi},
                                 {{5.795, 2.4, 0}, -kPi / 2}, {{6.605, 2.4, 0}, kPi / 2}};
    for (const Placement& desk : desks) {
        add_desk(meshes, desk);
        add_desk_clutter(meshes, desk, random);
        const Vec3 seat{random.uniform(-0.15, 0.15), -(0.78 + random.uniform(0, 0.15)), 0};
        add_office_chair(meshes, {desk.at(seat), desk.yaw_rad + random.uniform(-0.35, 0.35)},
                         random);
        if (random.chance(0.5)) add_bin(meshes, desk.at({0.55, 0.15, 0}));
    }
    // Bookshelves against the north wall, facing into the room.
    for (const double x : {0.75, 1.655, 2.56, 5.45}) {
        add_bookshelf(meshes, {{x, kRoomDepthM - 0.02, 0}, kPi}, random);
    }
    add_bookshelf(meshes, {{0.02, 3.05, 0}, -kPi / 2}, random);  // on the west wall
    add_small_plant(meshes, {5.45, kRoomDepthM - 0.2, 2.0}, random.integer(1200, 1600), random);
    add_filing_cabinet(meshes, {{7.45, kRoomDepthM - 0.02, 0}, kPi});
    add_small_plant(meshes, {7.45, kRoomDepthM - 0.245, 1.1}, random.integer(1200, 1600), random);
    add_floor_plant(meshes, {0.6, 0.6, 0}, random.integer(2000, 3000), random);
    add_floor_plant(meshes, {kRoomWidthM - 0.6, 0.6, 0}, random.integer(2000, 3000), random);
    // Visitor chairs against the west wall, facing east.
    for (const double y : {1.55, 2.15}) {
        add_visitor_chair(meshes, {{0.35, y, 0}, -kPi / 2 + random.uniform(-0.1, 0.1)});
    }
    add_cardboard_boxes(meshes, {{5.9, 0.4, 0}, random.uniform(-0.3, 0.3)}, random);
    if (random.chance(0.5)) {
        add_cardboard_boxes(meshes, {{2.6, 0.4, 0}, random.uniform(-0.3, 0.3)}, random);
    }
    return meshes;
}

// stem + n, appended: GCC 12's -Wrestrict misfires on "literal" + std::to_string(n).
std::string numbered(std::string stem, int n) {
    stem += std::to_string(n);
    return stem;
}

Surface mesh_surface(std::string name, std::string material, MeshGeometry mesh) {
    Surface s;
    s.name = std::move(name);
    s.material = std::move(material);
    s.geometry = std::move(mesh);
    return s;
}

MeshGeometry moved(MeshGeometry mesh, Vec3 offset) {
    for (Vec3& v : mesh.vertices) v = snapped(v + offset);
    return mesh;
}

Polygon moved(Polygon polygon, Vec3 offset) {
    for (Vec3& v : polygon) v = v + offset;
    return polygon;
}

Polygon floor_polygon() {
    return testing::rect({0, 0, 0}, {kRoomWidthM, 0, 0}, {0, kRoomDepthM, 0});
}

// The floor, ceiling, panels (when `panels`) and furniture of a room at `offset`, names prefixed.
void add_room(std::vector<Surface>& surfaces, const MaterialMeshes& meshes, bool panels,
              Vec3 offset, const std::string& prefix) {
    surfaces.push_back(
        testing::polygon_surface(prefix + "floor", "floor", moved(floor_polygon(), offset)));
    surfaces.push_back(testing::polygon_surface(
        prefix + "ceiling", "ceiling",
        moved(testing::ceiling_rect(0, kRoomWidthM, 0, kRoomDepthM, kRoomHeightM), offset)));
    if (panels) {
        int n = 0;
        for (const double y : kPanelY) {
            for (const double x : kPanelX) {
                surfaces.push_back(testing::polygon_surface(
                    numbered(prefix + "panel-", ++n), "panel",
                    moved(testing::ceiling_rect(x - kPanelLengthM / 2, x + kPanelLengthM / 2,
                                                y - kPanelWidthM / 2, y + kPanelWidthM / 2,
                                                kRoomHeightM - kPanelDropM),
                          offset)));
            }
        }
    }
    for (const auto& [name, mesh] : meshes) {
        if (!mesh.faces.empty()) {
            surfaces.push_back(mesh_surface(prefix + name, material_of(name), moved(mesh, offset)));
        }
    }
}

/// The sensor set "workplane": the floor's work plane, facing up.
SensorSet work_plane_set() {
    Workplane w;
    w.surfaces = {"floor"};
    w.height = kWorkPlaneM;
    w.border = kWorkPlaneBorderM;
    w.spacing = kWorkPlaneSpacingM;
    SensorSet set;
    set.name = "workplane";
    set.normal = {0, 0, 1};
    set.workplane = w;
    return set;
}

void require_valid(const std::vector<Problem>& problems, const std::string& scene) {
    if (problems.empty()) return;
    throw std::logic_error("generated scene " + scene + " is invalid: " + problems[0].pointer +
                           ": " + problems[0].message);
}

// The work-plane points of a furnished room in room coordinates: the room's floor and
// furniture alone, expanded by the scene format's own rule.
std::vector<Vec3> work_plane_points(const MaterialMeshes& meshes) {
    Scene room;
    room.name = "room";
    room.materials = room_materials(false);
    add_room(room.surfaces, meshes, false, {}, "");
    room.sensors.push_back(work_plane_set());
    require_valid(expand_workplanes(room), "room");
    return room.sensors[0].points;
}

Scene office(const std::string& name, std::uint64_t seed, bool panels) {
    Scene scene;
    scene.name = name;
    scene.materials = room_materials(panels);
    const MaterialMeshes meshes = furnish_room(seed);
    // Floor first: room_without_ceiling's walls face in.
    std::vector<Surface> shell =
        testing::room_without_ceiling(kRoomWidthM, kRoomDepthM, kRoomHeightM, "wall");
    add_room(scene.surfaces, meshes, panels, {}, "");
    scene.surfaces.insert(scene.surfaces.begin() + 2, shell.begin() + 1, shell.end());
    scene.sensors.push_back(work_plane_set());
    require_valid(check_scene(scene), name);
    require_valid(expand_workplanes(scene), name);
    return scene;
}

}  // namespace

Scene furnished_office_clutter(std::uint64_t seed) {
    return office("furnished-office", seed, true);
}

Scene furnished_office_ies(const PhotometricTable& downlight, std::uint64_t seed) {
    Scene scene = office("furnished-office-ies", seed, false);
    int n = 0;
    for (const double y : kPanelY) {
        for (const double x : kPanelX) {
            Luminaire l;
            l.name = numbered("downlight-", ++n);
            l.position = {x, y, kRoomHeightM - kDownlightDropM};
            l.flux_lm = kPanelFluxLm;
            l.distribution = Distribution::photometric;
            l.aim = {0, 0, -1};
            l.photometry = downlight;
            scene.luminaires.push_back(std::move(l));
        }
    }
    require_valid(check_scene(scene), scene.name);
    return scene;
}

Scene furnished_floor(int rooms, std::uint64_t seed) {
    const int side = static_cast<int>(std::lround(std::sqrt(rooms)));
    if (rooms < 1 || side * side != rooms) {
        throw std::invalid_argument("a furnished floor needs a square number of rooms");
    }
    Scene scene;
    scene.name = numbered("furnished-floor-x", rooms);
    scene.materials = room_materials(true);
    const double pitch_x = kRoomWidthM + kPartitionM, pitch_y = kRoomDepthM + kPartitionM;
    const double width = side * pitch_x - kPartitionM, depth = side * pitch_y - kPartitionM;
    // The outer walls face in; the floor and ceiling are the rooms' own.
    std::vector<Surface> shell = testing::room_without_ceiling(width, depth, kRoomHeightM, "wall");
    scene.surfaces.assign(shell.begin() + 1, shell.end());
    // Partitions: closed boxes on either side of each door and a lintel over it; the walls
    // along x also fill the corner between four rooms. Each door has a floor strip.
    MeshGeometry partitions;
    SensorSet sensors;
    sensors.name = "workplane";
    int sill = 0;
    const auto add_sill = [&](Vec3 origin, Vec3 u, Vec3 v) {
        scene.surfaces.push_back(testing::polygon_surface(numbered("door-sill-", ++sill), "floor",
                                                          testing::rect(origin, u, v)));
    };
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            const double x0 = i * pitch_x, y0 = j * pitch_y;
            if (i + 1 < side) {  // the wall to the east
                const double x1 = x0 + kRoomWidthM, x2 = x1 + kPartitionM;
                const double d0 = y0 + kSideDoorY, d1 = d0 + kDoorWidthM;
                add_box(partitions, {x1, y0, 0}, {x2, d0, kRoomHeightM});
                add_box(partitions, {x1, d1, 0}, {x2, y0 + kRoomDepthM, kRoomHeightM});
                add_box(partitions, {x1, d0, kDoorHeightM}, {x2, d1, kRoomHeightM});
                add_sill({x1, d0, 0}, {kPartitionM, 0, 0}, {0, kDoorWidthM, 0});
            }
            if (j + 1 < side) {  // the wall to the north
                const double y1 = y0 + kRoomDepthM, y2 = y1 + kPartitionM;
                const double d0 = x0 + kEndDoorX, d1 = d0 + kDoorWidthM;
                const double x_end = x0 + kRoomWidthM + (i + 1 < side ? kPartitionM : 0);
                add_box(partitions, {x0, y1, 0}, {d0, y2, kRoomHeightM});
                add_box(partitions, {d1, y1, 0}, {x_end, y2, kRoomHeightM});
                add_box(partitions, {d0, y1, kDoorHeightM}, {d1, y2, kRoomHeightM});
                add_sill({d0, y1, 0}, {kDoorWidthM, 0, 0}, {0, kPartitionM, 0});
            }
        }
    }
    if (!partitions.faces.empty()) {
        scene.surfaces.push_back(mesh_surface("partitions", "wall", std::move(partitions)));
    }
    SeededRandom seeds(seed);
    for (int j = 0; j < side; ++j) {
        for (int i = 0; i < side; ++i) {
            const int k = j * side + i;
            const Vec3 offset{i * pitch_x, j * pitch_y, 0};
            const MaterialMeshes meshes = furnish_room(seeds.next_bits());
            add_room(scene.surfaces, meshes, true, offset, numbered("r", k) + "/");
            for (const Vec3& p : work_plane_points(meshes)) sensors.points.push_back(p + offset);
        }
    }
    scene.sensors.push_back(std::move(sensors));
    require_valid(check_scene(scene), scene.name);
    return scene;
}

}  // namespace radiant::bench
