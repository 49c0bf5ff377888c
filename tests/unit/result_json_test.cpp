#include "radiant/proto/result_json.h"

#include <gtest/gtest.h>

#include <limits>

namespace radiant::proto {
namespace {

Result converged() {
    Result r;
    r.scene = "room";
    r.status = SolveStatus::converged;
    r.stats.method = "jacobi";
    r.stats.patches = 12;
    r.sensors.push_back({"wp", {1, 3}, 1, 3, 2, 0.5});
    r.surfaces.push_back({"floor", 16, 500, 100});
    return r;
}

TEST(ResultJson, MapsEveryField) {
    const nlohmann::json j = result_to_json(converged());
    EXPECT_EQ(j["format"], "radiant-result/1");
    EXPECT_EQ(j["scene"], "room");
    EXPECT_EQ(j["status"], "converged");
    EXPECT_FALSE(j.contains("error"));
    EXPECT_FALSE(j.contains("mesh"));
    EXPECT_EQ(j["stats"]["patches"], 12);
    EXPECT_EQ(j["sensors"][0]["illuminance"], nlohmann::json({1.0, 3.0}));
    EXPECT_EQ(j["sensors"][0]["uniformity"], 0.5);
    EXPECT_EQ(j["surfaces"][0]["area"], 16.0);
}

TEST(ResultJson, MeshIsOptional) {
    Result r = converged();
    r.mesh = SolvedMesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {0}, {5.0}, {5, 5, 5}};
    const nlohmann::json j = result_to_json(r);
    EXPECT_EQ(j["mesh"]["triangles"], nlohmann::json::parse("[[0,1,2]]"));
    EXPECT_EQ(j["mesh"]["vertex_radiosity"].size(), 3u);
}

TEST(ResultJson, FailedCarriesError) {
    Result r;
    r.status = SolveStatus::failed;
    r.error = "boom";
    const nlohmann::json j = result_to_json(r);
    EXPECT_EQ(j["status"], "failed");
    EXPECT_EQ(j["error"], "boom");
}

TEST(ResultJson, NonFiniteValueGivesAFailedDocument) {
    Result r = converged();
    r.sensors[0].illuminance[1] = std::numeric_limits<double>::quiet_NaN();
    const nlohmann::json j = result_to_json(r);
    EXPECT_EQ(j["status"], "failed");
    EXPECT_NE(j["error"].get<std::string>().find("/sensors/0/illuminance/1"), std::string::npos);
    EXPECT_EQ(j.dump().find("null"), std::string::npos);
}

}  // namespace
}  // namespace radiant::proto
