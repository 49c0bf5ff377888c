// The stored mesh blob: a round trip keeps every array, float32 rounding is the only change, and
// anything that is not a blob encode() wrote is refused rather than misread.
#include "radiant/server/compact_mesh.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include <nlohmann/json.hpp>

namespace {

using namespace radiant::server;

radiant::SolvedMesh triangle() {
    radiant::SolvedMesh mesh;
    mesh.vertices = {{0, 0, 0}, {1.5, 0, 0}, {0, 2.25, 1e-3}};
    mesh.triangles = {{0, 1, 2}};
    mesh.triangle_surface = {3};
    mesh.triangle_radiosity = {0.1};  // not exact in float32
    mesh.vertex_radiosity = {1, 2, 3};
    return mesh;
}

TEST(CompactMesh, BlobRoundTrip) {
    const CompactMesh mesh = compact(triangle());
    EXPECT_EQ(mesh.vertices.size(), 9u);
    EXPECT_EQ(mesh.triangle_radiosity[0], 0.1f);
    const auto back = decode(encode(mesh));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->vertices, mesh.vertices);
    EXPECT_EQ(back->triangles, mesh.triangles);
    EXPECT_EQ(back->triangle_surface, mesh.triangle_surface);
    EXPECT_EQ(back->triangle_radiosity, mesh.triangle_radiosity);
    EXPECT_EQ(back->vertex_radiosity, mesh.vertex_radiosity);
}

TEST(CompactMesh, DamagedBlobsAreRefused) {
    const std::string blob = encode(compact(triangle()));
    EXPECT_FALSE(decode(""));
    EXPECT_FALSE(decode(blob.substr(0, blob.size() - 1)));
    EXPECT_FALSE(decode(blob + "x"));
    std::string wrong_magic = blob;
    wrong_magic[0] = 'X';
    EXPECT_FALSE(decode(wrong_magic));
}

TEST(CompactMesh, JsonIsShortestFloatTextAndNeverNaN) {
    radiant::SolvedMesh mesh = triangle();
    mesh.vertex_radiosity[1] = std::numeric_limits<double>::quiet_NaN();
    const CompactMesh c = compact(mesh);
    std::string text = "{";
    text += geometry_json(c);
    text += ',';
    text += radiosity_json(c);
    text += '}';
    const auto doc = nlohmann::json::parse(text);
    EXPECT_EQ(doc["triangles"], nlohmann::json::parse("[[0,1,2]]"));
    EXPECT_EQ(doc["triangle_surface"], nlohmann::json::parse("[3]"));
    EXPECT_EQ(doc["vertices"][2][1], 2.25);
    EXPECT_NE(radiosity_json(c).find("[0.1]"), std::string::npos) << radiosity_json(c);
    EXPECT_EQ(doc["vertex_radiosity"][1], 0);
}

}  // namespace
