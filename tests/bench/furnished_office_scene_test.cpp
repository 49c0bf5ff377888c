// Properties of the generated furnished office (furnished_office_scene.h): its size, that a seed
// fixes it, that every solid is closed and faces out, that no triangle is degenerate, that the
// work-plane points lie in the rooms and outside furniture, that the floors grow with their
// rooms, and that the written scene reads back to the same scene.
#include "furnished_office_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <numeric>
#include <set>
#include <span>
#include <sstream>
#include <variant>

#include "office_furniture.h"
#include "office_scene.h"
#include "photometry/ies_reader.h"
#include "radiant/box.h"
#include "radiant/proto/scene_json.h"
#include "scene_export.h"

namespace radiant::bench {
namespace {

using Triangle = std::array<Vec3, 3>;

PhotometricTable downlight() {
    std::ifstream in(RADIANT_DOWNLIGHT_IES);
    std::ostringstream text;
    text << in.rdbuf();
    auto table = proto::read_ies(text.str());
    EXPECT_TRUE(std::holds_alternative<PhotometricTable>(table));
    return std::get<PhotometricTable>(table);
}

bool two_sided(const Scene& scene, const std::string& material) {
    for (const Material& m : scene.materials) {
        if (m.name == material) return m.two_sided;
    }
    return false;
}

/// The faces of `mesh` grouped by connected vertices: one group per solid (the generator never
/// shares a vertex between two solids).
std::vector<std::vector<std::vector<int>>> components(const MeshGeometry& mesh) {
    std::vector<int> parent(mesh.vertices.size());
    std::iota(parent.begin(), parent.end(), 0);
    const auto root = [&](int v) {
        while (parent[static_cast<std::size_t>(v)] != v) {
            v = parent[static_cast<std::size_t>(v)] =
                parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
        }
        return v;
    };
    for (const auto& f : mesh.faces) {
        for (const int v : f) parent[static_cast<std::size_t>(root(v))] = root(f[0]);
    }
    std::map<int, std::vector<std::vector<int>>> groups;
    for (const auto& f : mesh.faces) groups[root(f[0])].push_back(f);
    std::vector<std::vector<std::vector<int>>> out;
    for (auto& [r, faces] : groups) out.push_back(std::move(faces));
    return out;
}

std::vector<Triangle> triangles_of(const MeshGeometry& mesh,
                                   const std::vector<std::vector<int>>& faces) {
    std::vector<Triangle> out;
    for (const auto& f : faces) {
        for (std::size_t k = 1; k + 1 < f.size(); ++k) {
            out.push_back({mesh.vertices[static_cast<std::size_t>(f[0])],
                           mesh.vertices[static_cast<std::size_t>(f[k])],
                           mesh.vertices[static_cast<std::size_t>(f[k + 1])]});
        }
    }
    return out;
}

/// Every directed edge of a closed, consistently oriented surface is matched by its reverse.
bool closed(const std::vector<std::vector<int>>& faces) {
    std::map<std::pair<int, int>, int> edges;
    for (const auto& f : faces) {
        for (std::size_t k = 0; k < f.size(); ++k) ++edges[{f[k], f[(k + 1) % f.size()]}];
    }
    return std::all_of(edges.begin(), edges.end(), [&](const auto& e) {
        const auto reverse = edges.find({e.first.second, e.first.first});
        return e.second == 1 && reverse != edges.end() && reverse->second == 1;
    });
}

double signed_volume(const std::vector<Triangle>& triangles) {
    double v = 0;
    for (const auto& t : triangles) v += dot(t[0], cross(t[1], t[2])) / 6;
    return v;
}

/// Generalised winding number of a closed triangle surface at `p` (Van Oosterom & Strackee
/// 1983's solid angles over 4π): 1 inside a solid facing out, 0 outside.
double winding_number(const std::vector<Triangle>& triangles, Vec3 p) {
    double sum = 0;
    for (const auto& t : triangles) {
        const Vec3 a = t[0] - p, b = t[1] - p, c = t[2] - p;
        const double la = length(a), lb = length(b), lc = length(c);
        const double numerator = dot(a, cross(b, c));
        const double denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
        sum += 2 * std::atan2(numerator, denominator);
    }
    return sum / (4 * std::numbers::pi);
}

struct Solid {
    std::string surface;
    std::vector<Triangle> triangles;
    Box box;
};

std::vector<Solid> solids_of(const Scene& scene) {
    std::vector<Solid> out;
    for (const Surface& s : scene.surfaces) {
        const auto* mesh = std::get_if<MeshGeometry>(&s.geometry);
        if (mesh == nullptr || two_sided(scene, s.material)) continue;
        for (const auto& faces : components(*mesh)) {
            Solid solid{s.name, triangles_of(*mesh, faces), {}};
            for (const auto& t : solid.triangles) solid.box.add(std::span<const Vec3>(t));
            out.push_back(std::move(solid));
        }
    }
    return out;
}

const Scene& office() {
    static const Scene scene = furnished_office_clutter();
    return scene;
}

const Scene& floor4() {
    static const Scene scene = furnished_floor(4);
    return scene;
}

TEST(FurnishedOffice, HasTenToThirtyThousandTriangles) {
    const std::size_t n = input_triangles(office());
    EXPECT_GE(n, 10000u);
    EXPECT_LE(n, 30000u);
    EXPECT_TRUE(check_scene(office()).empty());
}

TEST(FurnishedOffice, PlantsHaveOneToThreeThousandTriangles) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        SeededRandom random(seed);
        MaterialMeshes floor_plant, small_plant;
        add_floor_plant(floor_plant, {}, random.integer(2000, 3000), random);
        add_small_plant(small_plant, {}, random.integer(1200, 1600), random);
        for (const auto* plant : {&floor_plant, &small_plant}) {
            EXPECT_GE(triangle_count(*plant), 1000u);
            EXPECT_LE(triangle_count(*plant), 3000u);
            EXPECT_GT(plant->at("leaf/plant-1").faces.size(), 900u) << "mostly leaves";
        }
    }
}

TEST(FurnishedOffice, HasHundredsOfBooks) {
    SeededRandom random(7);
    MaterialMeshes shelf;
    int books = 0;
    for (int k = 0; k < 4; ++k) books += add_bookshelf(shelf, {{2.0 * k, 0, 0}, 0}, random);
    EXPECT_GE(books, 250);
}

TEST(FurnishedOffice, IsFixedBySeed) {
    EXPECT_EQ(scene_document(furnished_office_clutter(5)),
              scene_document(furnished_office_clutter(5)));
    EXPECT_NE(scene_document(furnished_office_clutter(5)),
              scene_document(furnished_office_clutter(6)));
    EXPECT_EQ(scene_document(furnished_floor(4, 9)), scene_document(furnished_floor(4, 9)));
}

TEST(FurnishedOffice, SolidsAreClosedAndFaceOut) {
    for (const auto& [scene, rooms] : {std::pair{&office(), 1}, std::pair{&floor4(), 4}}) {
        std::size_t solids = 0;
        for (const Surface& s : scene->surfaces) {
            const auto* mesh = std::get_if<MeshGeometry>(&s.geometry);
            if (mesh == nullptr || two_sided(*scene, s.material)) continue;
            for (const auto& faces : components(*mesh)) {
                ++solids;
                ASSERT_TRUE(closed(faces)) << s.name;
                EXPECT_GT(signed_volume(triangles_of(*mesh, faces)), 1e-9) << s.name;
            }
        }
        EXPECT_GT(solids, 500u * rooms);
    }
}

TEST(FurnishedOffice, RoomShellFacesIn) {
    const Vec3 centre{kRoomWidthM / 2, kRoomDepthM / 2, kRoomHeightM / 2};
    for (const Surface& s : office().surfaces) {
        const auto* polygon = std::get_if<Polygon>(&s.geometry);
        if (polygon == nullptr) continue;
        const Vec3 n = cross((*polygon)[1] - (*polygon)[0], (*polygon)[2] - (*polygon)[0]);
        EXPECT_GT(dot(n, centre - (*polygon)[0]), 0) << s.name;
    }
}

TEST(FurnishedOffice, HasNoDegenerateTriangles) {
    for (const Surface& s : office().surfaces) {
        const auto* mesh = std::get_if<MeshGeometry>(&s.geometry);
        if (mesh == nullptr) continue;
        for (const auto& t : triangles_of(*mesh, mesh->faces)) {
            const double area = 0.5 * length(cross(t[1] - t[0], t[2] - t[0]));
            const double longest =
                std::max({length(t[1] - t[0]), length(t[2] - t[1]), length(t[0] - t[2])});
            EXPECT_GT(area, 1e-7) << s.name;
            EXPECT_GT(area / (longest * longest), 1e-3) << s.name << " has a sliver";
        }
    }
}

// Points of `scene`'s work plane: in a room, 0.8 m up, 0.5 m from its walls, and outside every
// solid (a point may be above a desk board, or below one, but not inside it).
void expect_work_plane_in_rooms(const Scene& scene, int side) {
    const auto& points = scene.sensors.at(0).points;
    const std::vector<Solid> solids = solids_of(scene);
    const double pitch_x = kRoomWidthM + 0.12, pitch_y = kRoomDepthM + 0.12;
    for (const Vec3& p : points) {
        EXPECT_NEAR(p.z, 0.8, 1e-9);
        const double i = std::floor(p.x / pitch_x), j = std::floor(p.y / pitch_y);
        ASSERT_LT(i, side);
        ASSERT_LT(j, side);
        const double x = p.x - i * pitch_x, y = p.y - j * pitch_y;
        EXPECT_TRUE(x >= 0.5 && x <= kRoomWidthM - 0.5 && y >= 0.5 && y <= kRoomDepthM - 0.5)
            << p.x << ", " << p.y;
        for (const Solid& solid : solids) {
            if (p.x < solid.box.lo.x || p.x > solid.box.hi.x || p.y < solid.box.lo.y ||
                p.y > solid.box.hi.y || p.z < solid.box.lo.z || p.z > solid.box.hi.z) {
                continue;
            }
            EXPECT_LT(std::abs(winding_number(solid.triangles, p)), 0.5)
                << "(" << p.x << ", " << p.y << ", " << p.z << ") is inside " << solid.surface;
        }
    }
}

TEST(FurnishedOffice, WorkPlaneLiesInTheRoomOutsideFurniture) {
    const auto& points = office().sensors.at(0).points;
    EXPECT_GE(points.size(), 150u);
    EXPECT_LE(points.size(), 200u);
    expect_work_plane_in_rooms(office(), 1);
}

TEST(FurnishedOffice, IesVariantHasDownlightsInsteadOfPanels) {
    const Scene ies = furnished_office_ies(downlight());
    EXPECT_TRUE(check_scene(ies).empty());
    EXPECT_EQ(ies.luminaires.size(), 6u);
    for (const Luminaire& l : ies.luminaires) {
        EXPECT_EQ(l.distribution, Distribution::photometric);
        EXPECT_LT(l.position.z, kRoomHeightM);
    }
    for (const Material& m : ies.materials) EXPECT_FALSE(m.emission) << m.name;
    EXPECT_EQ(input_triangles(ies) + 12, input_triangles(office()));
    EXPECT_EQ(ies.sensors.at(0).points, office().sensors.at(0).points);
}

TEST(FurnishedFloor, GrowsWithItsRooms) {
    const double one = static_cast<double>(input_triangles(office()));
    const double points = static_cast<double>(office().sensors.at(0).points.size());
    for (const int rooms : {4, 16}) {
        const Scene floor = rooms == 4 ? floor4() : furnished_floor(rooms);
        EXPECT_TRUE(check_scene(floor).empty());
        const double n = static_cast<double>(input_triangles(floor));
        EXPECT_NEAR(n / (rooms * one), 1.0, 0.15) << rooms;
        const double p = static_cast<double>(floor.sensors.at(0).points.size());
        EXPECT_NEAR(p / (rooms * points), 1.0, 0.1) << rooms;
    }
    expect_work_plane_in_rooms(floor4(), 2);
}

TEST(FurnishedFloor, FurnishesEachRoomFromItsOwnSeed) {
    std::map<std::string, std::size_t> books_faces;
    for (const Surface& s : floor4().surfaces) {
        if (s.name.ends_with("/book-0")) {
            books_faces[s.name] = std::get<MeshGeometry>(s.geometry).faces.size();
        }
    }
    ASSERT_EQ(books_faces.size(), 4u);
    std::set<std::size_t> distinct;
    for (const auto& [name, n] : books_faces) distinct.insert(n);
    EXPECT_GT(distinct.size(), 1u);
}

TEST(SceneExport, ReadsBackToTheSameScene) {
    for (const Scene& scene : {office(), furnished_office_ies(downlight())}) {
        const std::string text = scene_document(scene);
        const auto outcome = proto::parse_scene(text);
        ASSERT_TRUE(outcome.ok()) << outcome.problems.at(0).pointer << ": "
                                  << outcome.problems.at(0).message;
        const Scene& back = *outcome.scene;
        EXPECT_EQ(scene_document(back), text);
        EXPECT_EQ(back.sensors.at(0).points, scene.sensors.at(0).points);
        EXPECT_EQ(input_triangles(back), input_triangles(scene));
        ASSERT_EQ(back.luminaires.size(), scene.luminaires.size());
        for (std::size_t k = 0; k < back.luminaires.size(); ++k) {
            EXPECT_EQ(back.luminaires[k].photometry->candela,
                      scene.luminaires[k].photometry->candela);
        }
    }
}

TEST(SceneExport, ExampleIsWhatTheGeneratorMakes) {
    // Regenerate with: radiant-bench --export proto/examples/furnished-office-clutter
    //                  --scenes furnished-office
    std::ifstream in(RADIANT_CLUTTER_EXAMPLE);
    std::ostringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), scene_document(office()));
}

}  // namespace
}  // namespace radiant::bench
