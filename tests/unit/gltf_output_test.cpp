// `radiant solve --gltf`: every written .glb passes the Khronos glTF validator (tools/, from npm)
// with zero errors, and carries the colours, raw values and extras it documents.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <tiny_gltf.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "gltf_validator.h"
#include "radiant/proto/result_gltf.h"
#include "scene_files.h"
#include "test_files.h"

namespace radiant::proto {
namespace {

namespace fs = std::filesystem;

fs::path temp_file(const std::string& name) {
    return fs::temp_directory_path() / ("radiant_gltf_" + std::to_string(getpid()) + "_" + name);
}

void expect_valid(const fs::path& file) { test::expect_valid_gltf(file); }

tinygltf::Model read_glb(const fs::path& file) {
    tinygltf::Model model;
    std::string error, warning;
    tinygltf::TinyGLTF loader;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, file.string())) << error;
    return model;
}

Result solve_file(const fs::path& path, Scene& scene) {
    scene = testing::load_scene(path);
    SolveOptions options;
    options.tolerance = 0.1;
    options.want_mesh = true;
    return solve(scene, options);
}

TEST(GltfOutput, SolvedRoomIsValidAndCarriesRadiosityAndSensors) {
    Scene scene;
    const Result result =
        solve_file(fs::path(RADIANT_SOURCE_DIR) / "proto/examples/simple-room.json", scene);
    ASSERT_NE(result.status, SolveStatus::failed) << result.error;
    const fs::path file = temp_file("room.glb");
    {
        std::ofstream out(file, std::ios::binary);
        out << result_to_glb(result, scene);
    }
    expect_valid(file);
    const tinygltf::Model model = read_glb(file);
    fs::remove(file);
    ASSERT_EQ(model.meshes.size(), 2u);
    const auto& surfaces = model.meshes[0].primitives.at(0);
    EXPECT_EQ(surfaces.mode, TINYGLTF_MODE_TRIANGLES);
    ASSERT_TRUE(surfaces.attributes.contains("COLOR_0"));
    ASSERT_TRUE(surfaces.attributes.contains("_RADIOSITY"));
    const auto& radiosity =
        model.accessors[static_cast<std::size_t>(surfaces.attributes.at("_RADIOSITY"))];
    EXPECT_EQ(radiosity.count, result.mesh->vertices.size());
    double max_radiosity = 0;
    for (const double b : result.mesh->vertex_radiosity) max_radiosity = std::max(max_radiosity, b);
    const auto& points = model.meshes[1].primitives.at(0);
    EXPECT_EQ(points.mode, TINYGLTF_MODE_POINTS);
    ASSERT_TRUE(points.attributes.contains("_ILLUMINANCE"));
    EXPECT_EQ(model.accessors[static_cast<std::size_t>(points.attributes.at("_ILLUMINANCE"))].count,
              81u);
    const auto& extras = model.scenes.at(0).extras;
    EXPECT_EQ(extras.Get("scene").Get<std::string>(), "simple-room");
    EXPECT_EQ(extras.Get("units").Get<std::string>(), "m");
    EXPECT_NEAR(extras.Get("color_scale_radiosity").GetNumberAsDouble(), max_radiosity, 1e-9);
    // The room stands upright in glTF's y-up frame: 3 m high along +y.
    const auto& position =
        model.accessors[static_cast<std::size_t>(surfaces.attributes.at("POSITION"))];
    EXPECT_NEAR(position.maxValues.at(1), 3.0, 1e-6);
    EXPECT_NEAR(position.minValues.at(2), -4.0, 1e-6);
}

TEST(GltfOutput, ImportedModelInCentimetresAndAnEmptyResultAreValid) {
    Scene scene;
    const Result result = solve_file(testing::data_path("good/import-gltf.json"), scene);
    ASSERT_NE(result.status, SolveStatus::failed) << result.error;
    const fs::path imported = temp_file("imported.glb"), empty = temp_file("empty.glb");
    std::ofstream(imported, std::ios::binary) << result_to_glb(result, scene);
    std::ofstream(empty, std::ios::binary) << result_to_glb(Result{}, Scene{});
    expect_valid(imported);
    expect_valid(empty);
    const tinygltf::Model model = read_glb(imported);
    fs::remove(imported);
    fs::remove(empty);
    EXPECT_EQ(model.scenes.at(0).extras.Get("scene_units").Get<std::string>(), "cm");
    const auto& position = model.accessors[static_cast<std::size_t>(
        model.meshes.at(0).primitives.at(0).attributes.at("POSITION"))];
    EXPECT_NEAR(position.maxValues.at(0), 4.0, 1e-6) << "metres, not centimetres";
}

TEST(GltfOutput, CliWritesTheGlbBesideTheResult) {
    const fs::path glb = temp_file("cli.glb"), out = temp_file("cli.json");
    const std::string command =
        std::string(RADIANT_BIN_DIR) + "/radiant solve '" +
        (fs::path(RADIANT_SOURCE_DIR) / "proto/examples/simple-room.json").string() +
        "' --tolerance 0.1 --gltf '" + glb.string() + "' --out '" + out.string() + "'";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_EQ(test::read_text(out).find("\"mesh\""), std::string::npos)
        << "--gltf alone adds no mesh";
    expect_valid(glb);
    fs::remove(glb);
    fs::remove(out);
}

}  // namespace
}  // namespace radiant::proto
