// Surfaces imported from OBJ and glTF models: materials, units, axes, transforms, winding, and
// refusals that name the key and the line or face.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "glb_writer.h"
#include "radiant/proto/scene_json.h"
#include "scene_files.h"
#include "test_files.h"

namespace radiant::proto {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

Json scene_with(const Json& surface, const char* units = "m") {
    return {{"format", "radiant-scene/1"},
            {"units", units},
            {"materials", {{"wall", {{"reflectance", 0.5}}}}},
            {"surfaces", Json::array({surface})}};
}

const Surface* find(const Scene& scene, const std::string& name) {
    for (const Surface& s : scene.surfaces)
        if (s.name == name) return &s;
    return nullptr;
}

const Material* find_material(const Scene& scene, const std::string& name) {
    for (const Material& m : scene.materials)
        if (m.name == name) return &m;
    return nullptr;
}

Vec3 face_normal(const MeshGeometry& mesh, std::size_t face) {
    const auto& f = mesh.faces[face];
    const Vec3 a = mesh.vertices[static_cast<std::size_t>(f[0])];
    const Vec3 b = mesh.vertices[static_cast<std::size_t>(f[1])];
    const Vec3 c = mesh.vertices[static_cast<std::size_t>(f[2])];
    return normalized(cross(b - a, c - a));
}

TEST(ModelImport, ObjWithInlineMtlGivesOneSurfacePerMaterial) {
    const ParseOutcome outcome = load_scene_file(testing::data_path("good/import-obj-inline.json"));
    ASSERT_TRUE(outcome.ok()) << outcome.problems[0].pointer << ": " << outcome.problems[0].message;
    const Scene& scene = *outcome.scene;
    ASSERT_EQ(scene.surfaces.size(), 3u);
    const Surface* oak = find(scene, "desk/oak");
    ASSERT_NE(oak, nullptr);
    EXPECT_EQ(oak->material, "desk/oak");
    const auto& mesh = std::get<MeshGeometry>(oak->geometry);
    ASSERT_EQ(mesh.faces.size(), 1u);
    EXPECT_EQ(mesh.faces[0].size(), 4u) << "polygons are kept, not triangulated";
    EXPECT_EQ(face_normal(mesh, 0), (Vec3{0, 0, 1}));
    const Material* m = find_material(scene, "desk/oak");
    ASSERT_NE(m, nullptr);
    EXPECT_TRUE(m->rgb_reflectance);
    for (std::size_t c = 0; c < 3; ++c)
        EXPECT_NEAR(m->reflectance[c], (Rgb{0.45, 0.35, 0.25})[c], 1e-12);
    const Material* dark = find_material(scene, "desk/dark");
    ASSERT_NE(dark, nullptr);
    EXPECT_FALSE(dark->rgb_reflectance);
}

TEST(ModelImport, SurfaceMaterialOverridesTheModelsAndMergesParts) {
    const ParseOutcome outcome = load_scene_file(testing::data_path("good/import-obj-file.json"));
    ASSERT_TRUE(outcome.ok()) << outcome.problems[0].pointer << ": " << outcome.problems[0].message;
    const Surface* desk = find(*outcome.scene, "desk");
    ASSERT_NE(desk, nullptr);
    EXPECT_EQ(desk->material, "wall");
    EXPECT_EQ(std::get<MeshGeometry>(desk->geometry).faces.size(), 2u);
    EXPECT_EQ(outcome.scene->materials.size(), 1u);
}

TEST(ModelImport, GltfIsConvertedToZUpSceneUnits) {
    const ParseOutcome outcome = load_scene_file(testing::data_path("good/import-gltf.json"));
    ASSERT_TRUE(outcome.ok()) << outcome.problems[0].pointer << ": " << outcome.problems[0].message;
    const Scene& scene = *outcome.scene;
    const Surface* white = find(scene, "table/white");
    ASSERT_NE(white, nullptr);
    const auto& mesh = std::get<MeshGeometry>(white->geometry);
    ASSERT_EQ(mesh.faces.size(), 2u);
    for (const Vec3& v : mesh.vertices) {
        EXPECT_NEAR(v.z, 75.0, 1e-4) << "0.75 m node translation along glTF's y, in cm";
        EXPECT_TRUE(v.x > -1e-4 && v.x < 100 + 1e-4 && v.y > -1e-4 && v.y < 100 + 1e-4);
    }
    EXPECT_NEAR(face_normal(mesh, 0).z, 1.0, 1e-9);
    const Material* red = find_material(scene, "table/red");
    ASSERT_NE(red, nullptr);
    EXPECT_NEAR(red->reflectance[0], 0.6, 1e-6);
    EXPECT_TRUE(red->rgb_reflectance);
    const Surface* file = find(scene, "table-file");
    ASSERT_NE(file, nullptr);
    EXPECT_EQ(std::get<MeshGeometry>(file->geometry).faces.size(), 3u) << "indexed + non-indexed";
}

/// A one-primitive glTF written with tinygltf: a unit square at height 0 (y-up), as a triangle
/// strip, under a node with `scale`.
fs::path write_strip_glb(const std::vector<double>& scale) {
    const fs::path path = fs::temp_directory_path() / ("radiant_strip_" + std::to_string(getpid()) +
                                                       "_" + std::to_string(scale[0] < 0) + ".glb");
    std::ofstream(path, std::ios::binary) << test::single_primitive_glb(
        {0, 0, 0, 1, 0, 0, 0, 0, -1, 1, 0, -1}, {}, TINYGLTF_MODE_TRIANGLE_STRIP, scale);
    return path;
}

TEST(ModelImport, StripsAndMirroredNodesKeepTheFrontFace) {
    for (const double sx : {1.0, -1.0}) {
        const fs::path file = write_strip_glb({sx, 1, 1});
        const Json doc = scene_with(
            {{"name", "floor"}, {"material", "wall"}, {"gltf_file", file.filename().string()}});
        const ParseOutcome outcome = parse_scene(doc.dump(), {}, file.parent_path());
        fs::remove(file);
        ASSERT_TRUE(outcome.ok()) << outcome.problems[0].message;
        const auto& mesh = std::get<MeshGeometry>(outcome.scene->surfaces[0].geometry);
        ASSERT_EQ(mesh.faces.size(), 2u);
        for (std::size_t f = 0; f < 2; ++f) {
            EXPECT_NEAR(face_normal(mesh, f).z, 1.0, 1e-9) << "scale x " << sx << " face " << f;
        }
    }
}

// A glTF material that is doubleSided is lit and reflects on its back (a plant's leaves, a
// sheet of paper); read as one-sided, every leaf's back would be black and absorb.
TEST(ModelImport, GltfDoubleSidedMaterialsAreTwoSided) {
    for (const bool double_sided : {false, true}) {
        const std::string square = test::single_primitive_glb(
            {0, 0, 0, 1, 0, 0, 0, 0, -1, 1, 0, -1}, {}, TINYGLTF_MODE_TRIANGLE_STRIP);
        tinygltf::Model model;
        tinygltf::TinyGLTF reader;
        std::string error, warning;
        ASSERT_TRUE(reader.LoadBinaryFromMemory(
            &model, &error, &warning, reinterpret_cast<const unsigned char*>(square.data()),
            static_cast<unsigned>(square.size())))
            << error;
        tinygltf::Material leaf;
        leaf.name = "leaf";
        leaf.doubleSided = double_sided;
        leaf.pbrMetallicRoughness.baseColorFactor = {0.1, 0.3, 0.1, 1};
        model.materials.push_back(leaf);
        model.meshes[0].primitives[0].material = 0;
        const Json doc =
            scene_with({{"name", "plant"}, {"gltf", test::base64(test::glb_of(model))}});
        const ParseOutcome outcome = parse_scene(doc.dump());
        ASSERT_TRUE(outcome.ok()) << outcome.problems[0].message;
        const Material* m = find_material(*outcome.scene, "plant/leaf");
        ASSERT_NE(m, nullptr);
        EXPECT_EQ(m->two_sided, double_sided);
    }
}

TEST(ModelImport, BrokenModelsNameTheKeyAndTheLine) {
    const ParseOutcome bad_vertex =
        load_scene_file(testing::data_path("bad/import-obj-bad-vertex.json"));
    ASSERT_EQ(bad_vertex.problems.size(), 1u);
    EXPECT_EQ(bad_vertex.problems[0].pointer, "/surfaces/1/obj");
    EXPECT_EQ(bad_vertex.problems[0].message, "line 3: \"x\" is not a finite number");

    const ParseOutcome face = parse_scene(
        scene_with({{"name", "d"}, {"material", "wall"}, {"obj", "v 0 0 0\nv 1 0 0\nf 1 2 0\n"}})
            .dump());
    ASSERT_EQ(face.problems.size(), 1u);
    EXPECT_EQ(face.problems[0].pointer, "/surfaces/0/obj");
    EXPECT_EQ(face.problems[0].message.rfind("line 3: ", 0), 0u) << face.problems[0].message;

    const ParseOutcome zero =
        load_scene_file(testing::data_path("bad/import-obj-zero-area-face.json"));
    ASSERT_EQ(zero.problems.size(), 1u);
    EXPECT_EQ(zero.problems[0].pointer, "/surfaces/1/obj");
    EXPECT_EQ(zero.problems[0].message.rfind("surface \"desk\" face 1: ", 0), 0u)
        << zero.problems[0].message;
}

TEST(ModelImport, FileReferencesNeedASceneFile) {
    const ParseOutcome outcome =
        parse_scene(scene_with({{"name", "d"}, {"obj_file", "/etc/hostname"}}).dump());
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "/surfaces/0/obj_file");
    EXPECT_NE(outcome.problems[0].message.find("needs a scene file"), std::string::npos);
}

TEST(ModelImport, HostileInputIsRefusedNotCrashed) {
    const std::vector<Json> surfaces = {
        {{"name", "d"}, {"obj", "f 1 2 3\n"}, {"material", "wall"}},
        {{"name", "d"}, {"obj", ""}, {"material", "wall"}},
        {{"name", "d"}, {"obj", "v 1e999 0 0\n"}, {"material", "wall"}},
        {{"name", "d"}, {"obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}, {"mtl", 5}},
        {{"name", "d"}, {"gltf", ""}},
        {{"name", "d"}, {"gltf", "Z2xURgIAAAA="}},  // "glTF" + version 2, nothing else
        {{"name", "d"}, {"gltf", 7}},
        {{"name", "d"}, {"gltf", "e30="}, {"mtl", "x"}},  // "{}"
    };
    for (const Json& s : surfaces) {
        const ParseOutcome outcome = parse_scene(scene_with(s).dump());
        EXPECT_FALSE(outcome.ok()) << s.dump();
        for (const Problem& p : outcome.problems) {
            EXPECT_EQ(p.pointer.rfind("/surfaces/0/", 0), 0u) << s.dump() << " " << p.pointer;
        }
    }
}

TEST(ModelImport, ImportedSceneSolves) {
    const Scene scene = testing::load_scene(testing::data_path("good/import-obj-inline.json"));
    SolveOptions options;
    options.tolerance = 0.1;
    const Result result = solve(scene, options);
    ASSERT_NE(result.status, SolveStatus::failed) << result.error;
    const SurfaceResult* oak = testing::find_surface(result, "desk/oak");
    ASSERT_NE(oak, nullptr);
    EXPECT_NEAR(oak->area_m2, 1.2 * 0.6, 1e-9);
    EXPECT_GT(oak->average_irradiance, 0);
}

}  // namespace
}  // namespace radiant::proto
