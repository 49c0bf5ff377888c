// The stored mesh blob: a round trip keeps every array, float32 rounding is the only change, and
// anything that is not a blob encode() wrote is refused rather than misread.
#include "radiant/server/compact_mesh.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "radiant/proto/base64.h"

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

TEST(CompactMesh, EventArraysAreBase64OfTheLittleEndianValues) {
    const CompactMesh c = compact(triangle());
    std::string text(1, '{');
    text.append(geometry_base64_json(c)).append(",").append(radiosity_base64_json(c)).append("}");
    const auto doc = nlohmann::json::parse(text);
    const auto bytes = [&](const char* key) {
        const auto decoded = radiant::proto::decode_base64(doc[key].get<std::string>());
        EXPECT_TRUE(decoded) << key;
        return decoded ? *decoded : std::vector<unsigned char>();
    };
    const auto same = [](const std::vector<unsigned char>& b, const auto& values) {
        return b.size() == values.size() * sizeof(values[0]) &&
               std::memcmp(b.data(), values.data(), b.size()) == 0;
    };
    EXPECT_TRUE(same(bytes("vertices"), c.vertices));
    EXPECT_TRUE(same(bytes("triangles"), c.triangles));
    EXPECT_TRUE(same(bytes("triangle_surface"), c.triangle_surface));
    EXPECT_TRUE(same(bytes("triangle_radiosity"), c.triangle_radiosity));
    EXPECT_TRUE(same(bytes("vertex_radiosity"), c.vertex_radiosity));
}

TEST(CompactMesh, Base64RadiosityIsAboutHalfTheDecimalText) {
    // Radiosities as a solve leaves them: no short decimals.
    radiant::SolvedMesh mesh = triangle();
    mesh.vertex_radiosity.clear();
    for (int i = 0; i < 3000; ++i) mesh.vertex_radiosity.push_back(123.456789 + 0.37 * i);
    const CompactMesh c = compact(mesh);
    EXPECT_LT(radiosity_base64_json(c).size(), 0.6 * radiosity_json(c).size());
}

}  // namespace
