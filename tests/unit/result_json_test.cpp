#include "radiant/proto/result_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "radiant/proto/result_reader.h"

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
    wp.points = {{0.5, 0.25, 0.8}, {1.5, 0.25, 0.8}};
    wp.normal = {0, 0, 1};
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
    EXPECT_EQ(j["sensors"][0]["ud"], 0.3333);  // four significant digits
    EXPECT_EQ(j["sensors"][0]["normal"], nlohmann::json({0.0, 0.0, 1.0}));
    EXPECT_EQ(j["sensors"][0]["points"][1], nlohmann::json({1.5, 0.25, 0.8}));
    EXPECT_EQ(j["units"]["illuminance"], "lx");
    EXPECT_EQ(j["units"]["length"], "m");
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

TEST(ResultJson, ValuesCarryTheDigitsAskedFor) {
    Result r = converged();
    r.sensors[0].illuminance = {278.43219, 0.000123456789, 16234.9};
    r.surfaces[0].average_irradiance = 24.999999;
    r.stats.seconds = 0.8312345;
    const nlohmann::json four = result_to_json(r);
    EXPECT_EQ(four["sensors"][0]["illuminance"], nlohmann::json({278.4, 0.0001235, 16230.0}));
    EXPECT_EQ(four["surfaces"][0]["average_irradiance"], 25.0);
    EXPECT_EQ(four["stats"]["seconds"], 0.8312);
    EXPECT_EQ(four["sensors"][0]["illuminance"].dump(), "[278.4,0.0001235,16230.0]");
    const nlohmann::json two = result_to_json(r, 2);
    EXPECT_EQ(two["sensors"][0]["illuminance"], nlohmann::json({280.0, 0.00012, 16000.0}));
    // 17 digits: the engine's doubles, unchanged.
    const nlohmann::json all = result_to_json(r, kMaxDigits);
    EXPECT_EQ(all["sensors"][0]["illuminance"][0].get<double>(), 278.43219);
    EXPECT_EQ(all["surfaces"][0]["average_irradiance"].get<double>(), 24.999999);
}

TEST(ResultJson, ErrorEstimatesAreRoundedUpToThreeDigits) {
    Result r = converged();
    r.stats.error_estimate = 0.0123401;
    r.stats.error_parts.photon_noise = 0.00987654;
    r.stats.unshot_fraction = 0.5;
    const nlohmann::json j = result_to_json(r, kMaxDigits);
    EXPECT_EQ(j["stats"]["error_estimate"], 0.0124);  // a bound stays a bound
    EXPECT_EQ(j["stats"]["error_parts"]["photon_noise"], 0.00988);
    EXPECT_EQ(j["stats"]["unshot_fraction"], 0.5);
    // Under the tolerance before rounding, under it after.
    r.stats.error_estimate = 0.0099996;
    EXPECT_LE(result_to_json(r)["stats"]["error_estimate"].get<double>(), 0.01);
}

TEST(ResultJson, LengthsAreRoundedToMicrometres) {
    Result r = converged();
    r.sensors[0].points = {{0.1 + 0.2, 1234.56789012, -1e-9}};
    r.sensors[0].illuminance = {5};
    const nlohmann::json j = result_to_json(r);
    EXPECT_EQ(j["sensors"][0]["points"][0].dump(), "[0.3,1234.56789,0.0]");
}

/// converged() with what a lighting-design solve adds: a task area's compliance, a surrounding
/// band, an observer and one group's contribution.
Result designed() {
    Result r = converged();
    Compliance c;
    c.status = Check::Status::fail;
    c.requirement = {"table", "5.26.2 Writing", 500.0, 0.6, 19.0, std::nullopt};
    c.checks = {{"em_lx", 500, 2, Check::Status::fail, "", ""},
                {"ugr_l", 19, 12.5, Check::Status::pass, "east", ""}};
    r.sensors[0].compliance = c;
    r.sensors[0].kind = SensorKind::vertical;
    SensorResult band = r.sensors[0];
    band.name = "wp surrounding";
    band.compliance.reset();
    band.surrounding_of = "wp";
    r.sensors.push_back(band);
    r.observers.push_back({"east", {4, 1, 1.2}, {-1, 0, 0}, "wp", true, 12.5, 30, 2e5, 0.1});
    GroupContribution g;
    g.name = "down";
    g.ra = 80;
    for (const SensorResult& s : r.sensors) g.sensors.push_back({s.name, s.illuminance, {}, 0.02});
    g.observers.push_back({"east", 30, 2e5, 0.1});
    r.groups.push_back(g);
    return r;
}

ResultReadOutcome read_back(const nlohmann::json& doc) { return read_result(doc.dump()); }

TEST(ResultReader, ReadsBackTheLightingDesignMembers) {
    const ResultReadOutcome read = read_back(result_to_json(designed()));
    ASSERT_TRUE(read.ok()) << read.problems[0].pointer << ": " << read.problems[0].message;
    const Result& r = *read.result;
    ASSERT_EQ(r.sensors.size(), 2u);
    ASSERT_TRUE(r.sensors[0].compliance);
    const Compliance& c = *r.sensors[0].compliance;
    EXPECT_EQ(c.status, Check::Status::fail);
    EXPECT_EQ(c.requirement.activity, "5.26.2 Writing");
    EXPECT_EQ(c.requirement.em_lx, 500.0);
    EXPECT_FALSE(c.requirement.ra);
    ASSERT_EQ(c.checks.size(), 2u);
    EXPECT_EQ(c.checks[1].observer, "east");
    EXPECT_EQ(c.checks[1].status, Check::Status::pass);
    EXPECT_EQ(r.sensors[0].kind, SensorKind::vertical);
    EXPECT_EQ(r.sensors[1].surrounding_of, "wp");
    ASSERT_EQ(r.observers.size(), 1u);
    EXPECT_EQ(r.observers[0].task, "wp");
    EXPECT_TRUE(r.observers[0].standard);
    ASSERT_EQ(r.groups.size(), 1u);
    EXPECT_EQ(r.groups[0].ra, 80.0);
    EXPECT_EQ(r.groups[0].sensors[1].illuminance, (std::vector<double>{1, 3}));
    EXPECT_EQ(r.groups[0].observers[0].glare_sum, 2e5);
}

// A damaged document is refused at the value at fault, never read half: light scenes index
// the groups' values by the sets' points, and the plan draws the checks it reads.
TEST(ResultReader, RefusesDamagedDesignMembersAtTheirPointer) {
    const nlohmann::json good = result_to_json(designed());
    const auto refused_at = [&](const std::string& pointer, const nlohmann::json& value) {
        nlohmann::json doc = good;
        doc[nlohmann::json::json_pointer(pointer)] = value;
        const ResultReadOutcome read = read_back(doc);
        EXPECT_FALSE(read.result) << pointer;
        return read.problems.empty() ? std::string() : read.problems[0].pointer;
    };
    EXPECT_EQ(refused_at("/groups/0/sensors/1/illuminance", {1.0}),
              "/groups/0/sensors/1/illuminance");
    EXPECT_EQ(refused_at("/groups/0/observers", nlohmann::json::array()), "/groups/0/observers");
    EXPECT_EQ(refused_at("/sensors/0/compliance/checks/0/status", "maybe"),
              "/sensors/0/compliance/checks/0/status");
    EXPECT_EQ(refused_at("/sensors/0/compliance/requirement/em_lx", "500"),
              "/sensors/0/compliance/requirement/em_lx");
    EXPECT_EQ(refused_at("/sensors/0/kind", "oblique"), "/sensors/0/kind");
    EXPECT_EQ(refused_at("/observers/0/position", {1, 2}), "/observers/0/position");
    EXPECT_EQ(refused_at("/observers/0/standard", "yes"), "/observers/0/standard");
    // A result from before lighting design has none of them, and reads.
    nlohmann::json old = good;
    for (const char* key : {"observers", "groups", "maintenance"}) old.erase(key);
    for (auto& set : old["sensors"]) {
        for (const char* key : {"kind", "compliance", "surrounding_of", "error_estimate"})
            set.erase(key);
    }
    EXPECT_TRUE(read_back(old).ok());
}

TEST(SignificantDigits, RoundsInDecimal) {
    EXPECT_EQ(round_significant(278.45, 4), 278.4);  // 278.45 is 278.44999… in binary
    EXPECT_EQ(round_significant(-0.000123456, 3), -0.000123);
    EXPECT_EQ(round_significant(99999, 4), 100000);
    EXPECT_EQ(round_significant(0, 4), 0);
    EXPECT_EQ(round_up_significant(0.0100001, 3), 0.0101);
    EXPECT_EQ(round_up_significant(0.01, 3), 0.01);
    EXPECT_EQ(round_up_significant(9.991, 3), 10);
    EXPECT_EQ(round_up_significant(-2.341, 2), -2.4);
    EXPECT_EQ(round_decimals(2.0000004, 6), 2);
    EXPECT_FALSE(std::signbit(round_decimals(-1e-9, 6)));
}

}  // namespace
}  // namespace radiant::proto