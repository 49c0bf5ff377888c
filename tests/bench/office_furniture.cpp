#include "office_furniture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "solid_mesh.h"

namespace radiant::bench {
namespace {

constexpr double kPi = std::numbers::pi;

// Book covers: saturated and dull, light and dark, as on a real shelf.
constexpr std::array<Rgb, 12> kBookColours{{{0.55, 0.08, 0.07},
                                            {0.08, 0.14, 0.42},
                                            {0.10, 0.32, 0.14},
                                            {0.75, 0.70, 0.60},
                                            {0.06, 0.06, 0.07},
                                            {0.70, 0.45, 0.08},
                                            {0.35, 0.12, 0.30},
                                            {0.20, 0.40, 0.55},
                                            {0.80, 0.78, 0.74},
                                            {0.45, 0.30, 0.18},
                                            {0.62, 0.60, 0.15},
                                            {0.30, 0.30, 0.32}}};

std::string book_material(std::size_t colour) { return "book-" + std::to_string(colour); }

Material material(const std::string& name, Rgb reflectance, bool two_sided = false) {
    Material m;
    m.name = name;
    m.reflectance = reflectance;
    m.rgb_reflectance = !(reflectance[0] == reflectance[1] && reflectance[1] == reflectance[2]);
    m.two_sided = two_sided;
    return m;
}

// A new surface for the leaves of one more plant.
MeshGeometry& new_leaves(MaterialMeshes& meshes) {
    int plants = 0;
    for (const auto& [name, mesh] : meshes) plants += material_of(name) == "leaf";
    std::string name = "leaf/plant-";
    name += std::to_string(plants + 1);
    return meshes[name];
}

// The piece-local box [lo, hi] (a box in the piece's own axes) in room coordinates.
void local_box(MeshGeometry& mesh, const Placement& at, Vec3 lo, Vec3 hi) {
    add_parallelepiped(mesh, at.at(lo), at.direction({hi.x - lo.x, 0, 0}),
                       at.direction({0, hi.y - lo.y, 0}), {0, 0, hi.z - lo.z});
}

// A placement `local` (a point and turn in the piece's frame) within the piece's placement.
Placement within(const Placement& piece, Vec3 local, double yaw_rad) {
    return {piece.at(local), piece.yaw_rad + yaw_rad};
}

// A monitor facing −y of `at` (the middle of its base plate): plate, neck and a screen tilted
// back a little, which clears the neck.
void add_monitor(MaterialMeshes& meshes, const Placement& at, double width, SeededRandom& random) {
    MeshGeometry& black = meshes["plastic-black"];
    local_box(black, at, {-0.11, -0.08, 0}, {0.11, 0.08, 0.012});
    local_box(black, at, {-0.025, 0.05, 0.012}, {0.025, 0.075, 0.29});
    const double tilt = random.uniform(0, 0.1), height = 0.58 * width;
    add_parallelepiped(black, at.at({-width / 2, -0.01, 0.09}), at.direction({width, 0, 0}),
                       at.direction({0, 0.035, 0}),
                       at.direction({0, height * std::sin(tilt), height * std::cos(tilt)}));
}

// A laptop opened toward −y of `at` (the middle of its base).
void add_laptop(MaterialMeshes& meshes, const Placement& at) {
    MeshGeometry& gray = meshes["plastic-gray"];
    local_box(gray, at, {-0.165, -0.115, 0}, {0.165, 0.115, 0.018});
    const double back = 0.26;  // the lid leans back from vertical, radians
    add_parallelepiped(gray, at.at({-0.165, 0.105, 0.018}), at.direction({0.33, 0, 0}),
                       at.direction({0, 0.008, 0}),
                       at.direction({0, 0.22 * std::sin(back), 0.22 * std::cos(back)}));
}

// Up to `count` books lying on each other at `at`, each turned and shifted a little, the stack
// no higher than `max_height`. Returns how many there are.
int add_book_stack(MaterialMeshes& meshes, const Placement& at, int count, double max_length,
                   double max_height, SeededRandom& random) {
    double z = 0;
    int i = 0;
    for (; i < count; ++i) {
        const double length = random.uniform(0.7, 1.0) * max_length;
        const double depth = length * random.uniform(0.65, 0.8);
        const double thickness = random.uniform(0.015, 0.05);
        if (z + thickness > max_height) break;
        const Placement book =
            within(at, {random.uniform(-0.01, 0.01), 0, z}, random.uniform(-0.08, 0.08));
        add_turned_box(meshes[book_material(random.index(kBookColours.size()))], book.origin,
                       {length, depth, thickness}, book.yaw_rad);
        z += thickness;
    }
    return i;
}

}  // namespace

std::string material_of(const std::string& name) { return name.substr(0, name.find('/')); }

Vec3 Placement::direction(Vec3 local) const {
    const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
    return {c * local.x - s * local.y, s * local.x + c * local.y, local.z};
}

Vec3 Placement::at(Vec3 local) const { return origin + direction(local); }

std::vector<Material> furniture_materials() {
    std::vector<Material> out{
        material("desk-top", {0.62, 0.48, 0.33}),      material("metal", {0.55, 0.55, 0.55}),
        material("metal-light", {0.65, 0.65, 0.63}),   material("fabric", {0.10, 0.12, 0.20}),
        material("plastic-black", {0.05, 0.05, 0.05}), material("plastic-gray", {0.35, 0.35, 0.36}),
        material("paper", {0.80, 0.80, 0.78}),         material("ceramic", {0.75, 0.72, 0.68}),
        material("shelf-wood", {0.55, 0.42, 0.28}),    material("terracotta", {0.45, 0.24, 0.14}),
        material("stem", {0.18, 0.14, 0.08}),          material("leaf", {0.09, 0.22, 0.06}, true),
        material("cardboard", {0.50, 0.38, 0.24})};
    for (std::size_t c = 0; c < kBookColours.size(); ++c) {
        out.push_back(material(book_material(c), kBookColours[c]));
    }
    return out;
}

void add_desk(MaterialMeshes& meshes, const Placement& at) {
    constexpr double kBoard = 0.025;
    local_box(meshes["desk-top"], at, {-0.8, -0.4, kDeskTopM - kBoard}, {0.8, 0.4, kDeskTopM});
    MeshGeometry& metal = meshes["metal"];
    for (const double x : {-0.74, 0.74}) {
        for (const double y : {-0.34, 0.34}) {
            add_frustum(metal, at.at({x, y, 0}), {0, 0, kDeskTopM - kBoard}, 0.02, 0.02, 8,
                        at.yaw_rad);
        }
    }
    local_box(metal, at, {-0.7, 0.355, 0.36}, {0.7, 0.37, 0.70});
}

void add_desk_clutter(MaterialMeshes& meshes, const Placement& desk, SeededRandom& random) {
    constexpr double z = kDeskTopM;
    const double kind = random.unit();
    bool free_back_right = false;
    if (kind < 0.2) {  // a laptop, sometimes beside a monitor
        add_laptop(meshes, within(desk, {random.uniform(0.05, 0.3), -0.05, z},
                                  random.uniform(-0.15, 0.15)));
        if (random.chance(0.5)) {
            add_monitor(meshes, within(desk, {-0.45, 0.2, z}, random.uniform(0, 0.2)), 0.52,
                        random);
        }
    } else {
        if (kind < 0.55) {  // two monitors turned toward the sitter
            for (const double side : {-1.0, 1.0}) {
                add_monitor(
                    meshes,
                    within(desk, {0.29 * side, 0.2, z}, -0.2 * side + random.uniform(-0.05, 0.05)),
                    random.uniform(0.52, 0.56), random);
            }
        } else {
            add_monitor(
                meshes,
                within(desk, {random.uniform(-0.1, 0.1), 0.2, z}, random.uniform(-0.1, 0.1)),
                random.uniform(0.5, 0.62), random);
            free_back_right = true;
        }
        const double kx = random.uniform(-0.1, 0.1);
        add_turned_box(meshes["plastic-black"], desk.at({kx, -0.17, z}), {0.44, 0.14, 0.022},
                       desk.yaw_rad + random.uniform(-0.08, 0.08));
        add_turned_box(meshes["plastic-gray"], desk.at({kx + 0.32, -0.17, z}), {0.06, 0.1, 0.03},
                       desk.yaw_rad + random.uniform(-0.3, 0.3));
    }
    if (random.chance(0.6)) {
        add_frustum(meshes["ceramic"], desk.at({0.64, random.uniform(-0.12, 0.0), z}),
                    {0, 0, 0.095}, 0.04, 0.04, 10);
    }
    if (random.chance(0.7)) {
        const Placement papers = within(desk, {-0.55, -0.15, z}, random.uniform(-0.3, 0.3));
        add_turned_box(meshes["paper"], papers.origin, {0.21, 0.297, random.uniform(0.006, 0.03)},
                       papers.yaw_rad);
    }
    if (free_back_right && random.chance(0.4)) {
        add_book_stack(meshes, within(desk, {0.6, 0.22, z}, random.uniform(-0.15, 0.15)),
                       random.integer(2, 4), 0.28, 0.15, random);
    }
}

void add_office_chair(MaterialMeshes& meshes, const Placement& at, SeededRandom& random) {
    MeshGeometry& metal = meshes["metal"];
    MeshGeometry& black = meshes["plastic-black"];
    MeshGeometry& fabric = meshes["fabric"];
    // The star turns freely under the seat.
    const double spin = random.uniform(0, 2 * kPi / 5);
    for (int k = 0; k < 5; ++k) {
        const double a = spin + 2 * kPi * k / 5;
        const Vec3 out{std::cos(a), std::sin(a), 0}, across{-out.y, out.x, 0};
        add_turned_box(metal, at.origin + out * 0.175 + Vec3{0, 0, 0.05}, {0.27, 0.04, 0.03}, a);
        add_frustum(black, at.origin + out * 0.30 + Vec3{0, 0, 0.025} - across * 0.01,
                    across * 0.02, 0.024, 0.024, 6);
    }
    add_frustum(metal, at.origin + Vec3{0, 0, 0.04}, {0, 0, 0.05}, 0.055, 0.05, 10);
    add_frustum(metal, at.origin + Vec3{0, 0, 0.09}, {0, 0, 0.31}, 0.025, 0.025, 8);
    local_box(black, at, {-0.1, -0.1, 0.40}, {0.1, 0.1, 0.44});
    local_box(fabric, at, {-0.25, -0.22, 0.44}, {0.25, 0.26, 0.51});
    // The back's support: under the seat to its rear edge, then up.
    local_box(black, at, {-0.03, -0.24, 0.40}, {0.03, -0.1, 0.43});
    local_box(black, at, {-0.03, -0.27, 0.40}, {0.03, -0.24, 0.66});
    const double recline = random.uniform(0.1, 0.25);
    add_parallelepiped(fabric, at.at({-0.23, -0.32, 0.56}), at.direction({0.46, 0, 0}),
                       at.direction({0, 0.05 * std::cos(recline), 0.05 * std::sin(recline)}),
                       at.direction({0, -0.5 * std::sin(recline), 0.5 * std::cos(recline)}));
    if (random.chance(0.7)) {
        for (const double side : {-1.0, 1.0}) {
            const double x0 = side < 0 ? -0.27 : 0.24;
            local_box(black, at, {x0, -0.05, 0.51}, {x0 + 0.03, 0.0, 0.70});
            local_box(black, at, {x0 - 0.02, -0.15, 0.70}, {x0 + 0.05, 0.12, 0.73});
        }
    }
}

void add_visitor_chair(MaterialMeshes& meshes, const Placement& at) {
    MeshGeometry& metal = meshes["metal"];
    MeshGeometry& fabric = meshes["fabric"];
    local_box(fabric, at, {-0.22, -0.21, 0.43}, {0.22, 0.21, 0.47});
    for (const double x : {-0.19, 0.19}) {
        for (const double y : {-0.18, 0.18}) {
            add_frustum(metal, at.at({x, y, 0}), {0, 0, 0.43}, 0.012, 0.012, 6, at.yaw_rad);
        }
        local_box(metal, at, {x - 0.01, -0.2, 0.47}, {x + 0.01, -0.18, 0.86});
    }
    local_box(fabric, at, {-0.18, -0.21, 0.60}, {0.18, -0.19, 0.85});
}

int add_bookshelf(MaterialMeshes& meshes, const Placement& at, SeededRandom& random) {
    constexpr double kHalfWidth = 0.45, kDepth = 0.36, kHeight = 2.0, kSide = 0.018;
    constexpr double kBack = 0.008, kBoard = 0.018, kPlinth = 0.05;
    constexpr int kCompartments = 5;
    MeshGeometry& wood = meshes["shelf-wood"];
    const double inner = kHalfWidth - kSide;
    local_box(wood, at, {-kHalfWidth, 0, 0}, {-inner, kDepth, kHeight});
    local_box(wood, at, {inner, 0, 0}, {kHalfWidth, kDepth, kHeight});
    local_box(wood, at, {-inner, 0, 0}, {inner, kBack, kHeight});
    local_box(wood, at, {-inner, kDepth - 0.02, 0}, {inner, kDepth, kPlinth});
    const double pitch = (kHeight - kBoard - kPlinth) / kCompartments;
    for (int k = 0; k <= kCompartments; ++k) {
        const double z = kPlinth + k * pitch;
        local_box(wood, at, {-inner, kBack, z}, {inner, kDepth, z + kBoard});
    }
    int books = 0;
    for (int k = 0; k < kCompartments; ++k) {
        const double floor = kPlinth + k * pitch + kBoard;
        const double clearance = pitch - kBoard;
        const double left = -inner + 0.002, right = inner - 0.002;
        double x = left;
        double last_height = 0;  // of the upright book just left of x; 0 when there is none
        while (true) {
            const double pick = random.unit();
            if (pick < 0.05 && x + 0.36 < right) {  // a few books lying on each other
                books += add_book_stack(meshes, within(at, {x + 0.18, kDepth - 0.14, floor}, 0),
                                        random.integer(2, 5), random.uniform(0.22, 0.3),
                                        clearance - 0.03, random);
                x += 0.36;
                last_height = 0;
            } else if (pick < 0.10) {  // a gap where books were taken out
                x += random.uniform(0.03, 0.12);
                last_height = 0;
            } else {
                const double t = random.uniform(0.012, 0.06);
                const double h = random.uniform(0.17, std::min(0.34, clearance - 0.03));
                const double d = std::min(kDepth - kBack - 0.01, h * random.uniform(0.65, 0.8));
                if (x + t > right) break;
                const double front = kDepth - random.uniform(0.005, 0.03);
                local_box(meshes[book_material(random.index(kBookColours.size()))], at,
                          {x, front - d, floor}, {x + t, front, floor + h});
                ++books;
                x += t + random.uniform(0, 0.002);
                last_height = h;
            }
            // Now and then a shorter book leans on the last upright one, and the row ends.
            if (last_height > 0 && right - x > 0.08 && random.chance(0.03)) {
                const double lean = random.uniform(0.15, 0.45);
                const double t = random.uniform(0.012, 0.04);
                const double h = last_height * random.uniform(0.6, 0.98);
                const double d = std::min(kDepth - kBack - 0.01, h * random.uniform(0.65, 0.8));
                // Pivoting on its lower left edge, its top left edge touches the upright book.
                const double pivot = x + 0.001 + h * std::sin(lean);
                if (pivot + t * std::cos(lean) > right) break;
                const double front = kDepth - random.uniform(0.005, 0.03);
                add_parallelepiped(meshes[book_material(random.index(kBookColours.size()))],
                                   at.at({pivot, front - d, floor}),
                                   at.direction({t * std::cos(lean), 0, t * std::sin(lean)}),
                                   at.direction({0, d, 0}),
                                   at.direction({-h * std::sin(lean), 0, h * std::cos(lean)}));
                ++books;
                break;
            }
        }
    }
    return books;
}

void add_floor_plant(MaterialMeshes& meshes, Vec3 base, int triangles, SeededRandom& random) {
    constexpr double kPot = 0.36;
    constexpr int kPotSides = 16, kStemSides = 5, kLeafSegments = 4;
    add_frustum(meshes["terracotta"], base, {0, 0, kPot}, 0.13, 0.17, kPotSides);
    MeshGeometry& leaves_mesh = new_leaves(meshes);
    const int stems = random.integer(3, 5);
    struct Stem {
        Vec3 start, axis;
    };
    std::vector<Stem> stem;
    for (int i = 0; i < stems; ++i) {
        const double r = random.uniform(0, 0.07), a = random.uniform(0, 2 * kPi);
        const double tilt = random.uniform(0.05, 0.25), azimuth = random.uniform(0, 2 * kPi);
        const double height = random.uniform(0.6, 1.1);
        const Vec3 start = base + Vec3{r * std::cos(a), r * std::sin(a), kPot};
        const Vec3 axis = Vec3{std::sin(tilt) * std::cos(azimuth),
                               std::sin(tilt) * std::sin(azimuth), std::cos(tilt)} *
                          (height / std::cos(tilt));
        add_frustum(meshes["stem"], start, axis, 0.012, 0.005, kStemSides);
        stem.push_back({start, axis});
    }
    const int fixed = frustum_triangles(kPotSides) + stems * frustum_triangles(kStemSides);
    const int leaves = std::max(0, (triangles - fixed) / leaf_triangles(kLeafSegments));
    for (int i = 0; i < leaves; ++i) {
        const Stem& s = stem[static_cast<std::size_t>(i % stems)];
        const double along = random.uniform(0.3, 1.0);
        const double azimuth = random.uniform(0, 2 * kPi), elevation = random.uniform(-0.25, 0.7);
        LeafShape leaf;
        leaf.base = s.start + s.axis * along;
        leaf.direction = {std::cos(elevation) * std::cos(azimuth),
                          std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
        leaf.length_m = random.uniform(0.12, 0.2);
        leaf.width_m = leaf.length_m * random.uniform(0.35, 0.5);
        leaf.droop = random.uniform(0.15, 0.45);
        leaf.fold_rad = random.uniform(0.1, 0.5);
        leaf.roll_rad = random.uniform(-0.4, 0.4);
        leaf.segments = kLeafSegments;
        add_leaf(leaves_mesh, leaf);
    }
}

void add_small_plant(MaterialMeshes& meshes, Vec3 base, int triangles, SeededRandom& random) {
    constexpr double kPot = 0.11, kPotRadius = 0.07;
    constexpr int kPotSides = 12, kLeafSegments = 5;
    add_frustum(meshes["terracotta"], base, {0, 0, kPot}, 0.055, kPotRadius, kPotSides);
    MeshGeometry& leaves_mesh = new_leaves(meshes);
    const int leaves =
        std::max(0, (triangles - frustum_triangles(kPotSides)) / leaf_triangles(kLeafSegments));
    for (int i = 0; i < leaves; ++i) {
        const double r = random.uniform(0, 0.03), a = random.uniform(0, 2 * kPi);
        const double azimuth = random.uniform(0, 2 * kPi), elevation = random.uniform(0.35, 1.3);
        LeafShape leaf;
        leaf.base = base + Vec3{r * std::cos(a), r * std::sin(a), kPot};
        leaf.direction = {std::cos(elevation) * std::cos(azimuth),
                          std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
        leaf.length_m = random.uniform(0.08, 0.16);
        leaf.width_m = leaf.length_m * random.uniform(0.1, 0.18);
        // Long leaves arch over the rim; none dips into the pot or below the surface.
        const double reach = leaf.length_m * std::cos(elevation);
        double droop = random.uniform(0.3, 0.9);
        if (reach < 0.12) droop = std::min(droop, std::sin(elevation));
        droop = std::min(droop, std::sin(elevation) + (kPot - 0.01) / leaf.length_m);
        leaf.droop = droop;
        leaf.fold_rad = random.uniform(0.2, 0.6);
        leaf.roll_rad = random.uniform(-0.3, 0.3);
        leaf.segments = kLeafSegments;
        add_leaf(leaves_mesh, leaf);
    }
}

void add_bin(MaterialMeshes& meshes, Vec3 base) {
    add_frustum(meshes["plastic-gray"], base, {0, 0, 0.32}, 0.12, 0.14, 12);
}

void add_cardboard_boxes(MaterialMeshes& meshes, const Placement& at, SeededRandom& random) {
    const int n = random.integer(2, 4);
    double z = 0, length = 0.6, width = 0.45;
    for (int i = 0; i < n; ++i) {
        length = random.uniform(0.7, 1.0) * length;
        width = random.uniform(0.7, 1.0) * width;
        const double height = random.uniform(0.22, 0.38);
        const Placement box =
            within(at, {random.uniform(-0.03, 0.03), random.uniform(-0.03, 0.03), z},
                   random.uniform(-0.15, 0.15));
        add_turned_box(meshes["cardboard"], box.origin, {length, width, height}, box.yaw_rad);
        z += height;
    }
}

void add_filing_cabinet(MaterialMeshes& meshes, const Placement& at) {
    local_box(meshes["metal-light"], at, {-0.4, 0, 0}, {0.4, 0.45, 1.1});
    for (const double z : {0.3, 0.65, 1.0}) {
        local_box(meshes["metal"], at, {-0.08, 0.45, z}, {0.08, 0.47, z + 0.02});
    }
}

std::size_t triangle_count(const MaterialMeshes& meshes) {
    std::size_t n = 0;
    for (const auto& [name, mesh] : meshes) {
        for (const auto& f : mesh.faces) n += f.size() - 2;
    }
    return n;
}

}  // namespace radiant::bench
