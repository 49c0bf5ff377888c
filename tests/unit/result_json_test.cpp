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
    SensorResult wp;
    wp.name = "wp";
    wp.illuminance = {1, 3};
    wp.min = 1;
    wp.max = 3;
    wp.average = 2;
    wp.uniformity = wp.u0 = 0.5;
    wp.ud = 1.0 / 3;
    r.sensors.push_back(wp);
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
    EXPECT_EQ(j["sensors"][0]["u0"], 0.5);
    EXPECT_EQ(j["sensors"][0]["ud"], 1.0 / 3);
    EXPECT_FALSE(j["sensors"][0].contains("grid"));
    EXPECT_EQ(j["surfaces"][0]["area"], 16.0);
}

TEST(ResultJson, WorkPlaneGrid) {
    Result r = converged();
    SensorGrid grid;
    grid.nu = 2;
    grid.nv = 1;
    grid.spacing = 0.5;
    grid.origin = {0, 0, 0.8};
    grid.u = {1, 0, 0};
    grid.v = {0, 0.5, 0};
    grid.cells = {{0, 0}, {1, 0}};
    grid.points = {{0.25, 0.25, 0.8}, {0.75, 0.25, 0.8}};
    r.sensors[0].grid = grid;
    const nlohmann::json j = result_to_json(r)["sensors"][0]["grid"];
    EXPECT_EQ(j["nu"], 2);
    EXPECT_EQ(j["nv"], 1);
    EXPECT_EQ(j["spacing"], 0.5);
    EXPECT_EQ(j["origin"], nlohmann::json({0.0, 0.0, 0.8}));
    EXPECT_EQ(j["cells"], nlohmann::json::parse("[[0,0],[1,0]]"));
    EXPECT_EQ(j["points"][1], nlohmann::json({0.75, 0.25, 0.8}));
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
