// What a lighting designer signs off: maintenance factors, EN 12464-1 task areas and their
// checks, sensor kinds against closed forms, UGR's parts, and light scenes evaluated from a
// stored solve.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "design/glare.h"
#include "radiant/lighting.h"
#include "radiant/proto/lighting_json.h"
#include "radiant/proto/result_json.h"
#include "radiant/proto/result_reader.h"
#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"
#include "solve_with.h"

namespace radiant {
namespace {

using Json = nlohmann::json;
constexpr double kPi = std::numbers::pi;

/// A 4 × 4 × 3 m room of reflectance 0.5 with a downlight and a 2 × 2 m desk area.
Json office() {
    return Json::parse(R"({
      "format": "radiant-scene/1", "name": "office",
      "materials": { "wall": { "reflectance": 0.5 } },
      "surfaces": [ { "name": "room", "material": "wall",
                      "box": { "min": [0, 0, 0], "max": [4, 4, 3], "facing": "in" } } ],
      "luminaires": [ { "name": "L1", "position": [2, 2, 2.9], "flux": 3000,
                        "distribution": "lambertian",
                        "luminous_area": { "length": 0.6, "width": 0.6 } } ],
      "sensors": [ { "name": "desk", "normal": [0, 0, 1],
                     "grid": { "origin": [1, 1, 0.8], "u": [2, 0, 0], "v": [0, 2, 0],
                               "nu": 6, "nv": 6 } } ],
      "settings": { "tolerance": 0.02 }
    })");
}

Scene parsed(const Json& doc) {
    const proto::ParseOutcome outcome = proto::parse_scene(doc.dump());
    if (!outcome.ok()) {
        ADD_FAILURE() << outcome.problems[0].pointer << ": " << outcome.problems[0].message;
        return {};
    }
    return *outcome.scene;
}

std::vector<Problem> problems_of(const Json& doc) {
    return proto::parse_scene(doc.dump()).problems;
}

bool has_pointer(const std::vector<Problem>& problems, const std::string& pointer) {
    return std::any_of(problems.begin(), problems.end(),
                       [&](const Problem& p) { return p.pointer == pointer; });
}

Result solved(const Json& doc, const std::string& method = "auto") {
    const Scene scene = parsed(doc);
    SolveOptions options = options_from(scene.settings);
    options.method = method;
    return solve(scene, options);
}

const SensorResult& set_named(const std::vector<SensorResult>& sets, const std::string& name) {
    const auto it = std::find_if(sets.begin(), sets.end(),
                                 [&](const SensorResult& s) { return s.name == name; });
    EXPECT_NE(it, sets.end()) << name;
    return *it;
}

TEST(MaintenanceFactor, SettingsScaleEveryValueAndTheInitialOnesStayBeside) {
    Json doc = office();
    doc["settings"]["maintenance_factor"] = 0.8;
    for (const char* method : {"monte-carlo", "hierarchical"}) {
        SCOPED_TRACE(method);
        const Result r = solved(doc, method);
        ASSERT_NE(r.status, SolveStatus::failed) << r.error;
        const SensorResult& desk = r.sensors[0];
        ASSERT_TRUE(desk.initial.has_value());
        for (std::size_t i = 0; i < desk.illuminance.size(); ++i)
            EXPECT_NEAR(desk.illuminance[i], 0.8 * desk.initial->illuminance[i], 1e-9);
        EXPECT_NEAR(desk.average, 0.8 * desk.initial->average, 1e-9);
        ASSERT_EQ(r.maintenance.size(), 1u);
        EXPECT_EQ(r.maintenance[0].from, "settings");
        EXPECT_EQ(r.maintenance[0].factor, 0.8);
        EXPECT_EQ(r.maintenance[0].luminaires, 1u);
    }
    // Without a factor there are no initial values to show: they are the values.
    const Result plain = solved(office());
    EXPECT_FALSE(plain.sensors[0].initial.has_value());
    ASSERT_EQ(plain.maintenance.size(), 1u);
    EXPECT_EQ(plain.maintenance[0].from, "default");
}

TEST(MaintenanceFactor, PerLuminaireFactorsWeighTheirOwnLight) {
    Json doc = office();
    Json second = doc["luminaires"][0];
    second["name"] = "L2";
    second["position"] = {1, 1, 2.9};
    second["maintenance_factor"] = 0.5;
    doc["luminaires"][0]["maintenance_factor"] = 0.9;
    doc["luminaires"].push_back(second);
    const Result r = solved(doc);
    ASSERT_EQ(r.status, SolveStatus::converged) << testing::describe(r);
    ASSERT_EQ(r.maintenance.size(), 2u);
    EXPECT_EQ(r.maintenance[0].from, "luminaire");
    const SensorResult& desk = r.sensors[0];
    ASSERT_TRUE(desk.initial);
    const double ratio = desk.average / desk.initial->average;
    EXPECT_GT(ratio, 0.5 + 0.05);
    EXPECT_LT(ratio, 0.9 - 0.05);
    // A point under L2 gets more of its light from it: its ratio is nearer L2's factor.
    const double near_l2 = desk.illuminance[0] / desk.initial->illuminance[0];
    const double near_l1 = desk.illuminance[21] / desk.initial->illuminance[21];
    EXPECT_LT(near_l2, near_l1);
}

TEST(TaskArea, GetsItsSurroundingBandAndTheStandardsLowerRequirement) {
    Json doc = office();
    doc["sensors"][0]["requirement"] = {{"activity", "5.26.2"}, {"ugr_l", 22}};
    const Scene scene = parsed(doc);
    ASSERT_EQ(scene.sensors.size(), 2u);
    const SensorSet& band = scene.sensors[1];
    EXPECT_EQ(band.surrounding_of, std::optional<std::size_t>(0));
    ASSERT_TRUE(band.grid);
    EXPECT_FALSE(band.points.empty());
    for (const Vec3& x : band.points) {
        const bool in_task = x.x > 1 && x.x < 3 && x.y > 1 && x.y < 3;
        EXPECT_FALSE(in_task) << x.x << ", " << x.y;
        EXPECT_TRUE(x.x > 0.5 && x.x < 3.5 && x.y > 0.5 && x.y < 3.5) << x.x << ", " << x.y;
        EXPECT_DOUBLE_EQ(x.z, 0.8);
    }
    // No observer was given, the requirement limits UGR: the standard four, 1.2 m above the
    // grid's floor (0.8 m below it), looking across the task area.
    ASSERT_EQ(scene.observers.size(), 4u);
    for (const Observer& o : scene.observers) {
        EXPECT_TRUE(o.standard);
        EXPECT_NEAR(o.position.z, 1.2, 1e-12);
        EXPECT_EQ(o.task, std::optional<std::string>("desk"));
    }

    const Result r = solved(doc);
    ASSERT_EQ(r.status, SolveStatus::converged) << testing::describe(r);
    const SensorResult& desk = set_named(r.sensors, "desk");
    const SensorResult& around = set_named(r.sensors, "desk surrounding");
    ASSERT_TRUE(desk.compliance && around.compliance);
    EXPECT_EQ(around.surrounding_of, std::optional<std::string>("desk"));
    // 5.26.2: 500 lx, U₀ 0.6, UGR 19 (overridden: 22), Ra 80; its band 300 lx, U₀ 0.4.
    const AppliedRequirement& q = desk.compliance->requirement;
    EXPECT_EQ(q.source, "table");
    EXPECT_EQ(q.em_lx, 500);
    EXPECT_EQ(q.ugr_l, 22);
    EXPECT_EQ(around.compliance->requirement.em_lx, 300);
    EXPECT_EQ(around.compliance->requirement.u0, 0.4);
    for (const Check& c : desk.compliance->checks) {
        if (c.criterion == "em_lx") {
            EXPECT_EQ(c.value, desk.average);
            EXPECT_EQ(c.status == Check::Status::pass, desk.average >= 500);
        } else if (c.criterion == "ugr_l") {
            double worst = 0;
            for (const ObserverResult& o : r.observers) worst = std::max(worst, o.ugr);
            EXPECT_EQ(c.value, worst);
            EXPECT_EQ(c.status == Check::Status::pass, worst <= 22);
        } else if (c.criterion == "ra") {
            // The luminaire gives no Ra: nothing to check it by.
            EXPECT_EQ(c.status, Check::Status::unknown);
        }
    }
    // With an unknown criterion the verdict is at best unknown, never a pass.
    EXPECT_NE(desk.compliance->status, Check::Status::pass);
}

TEST(TaskArea, BadRequirementsAreRefusedWithTheirPointer) {
    Json doc = office();
    doc["sensors"][0]["requirement"] = {{"activity", "1.2.3"}};
    EXPECT_TRUE(has_pointer(problems_of(doc), "/sensors/0/requirement/activity"));
    doc["sensors"][0]["requirement"] = {{"u0", 1.5}};
    EXPECT_TRUE(has_pointer(problems_of(doc), "/sensors/0/requirement/u0"));
    doc["sensors"][0] = {{"name", "p"},
                         {"normal", {0, 0, 1}},
                         {"points", {{1, 1, 1}}},
                         {"requirement", {{"em_lx", 200}}}};
    EXPECT_TRUE(has_pointer(problems_of(doc), "/sensors/0/requirement"));
}

TEST(ActivityTable, OfficesAreThere) {
    const std::span<const Activity> table = en12464_activities();
    const auto it = std::find_if(table.begin(), table.end(),
                                 [](const Activity& a) { return a.reference == "5.26.2"; });
    ASSERT_NE(it, table.end());
    EXPECT_EQ(it->em_lx, 500);
    EXPECT_EQ(it->u0, 0.6);
    EXPECT_EQ(it->ugr_l, 19);
    EXPECT_EQ(it->ra, 80);
}

// A closed box whose walls all emit M and reflect ρ is filled with radiance M / (π (1 − ρ))
// from every direction: every kind of sensor reads π L = M / (1 − ρ).
TEST(SensorKinds, InAUniformDiffuseFieldEveryKindReadsThePlanarValue) {
    Json doc = Json::parse(R"({
      "format": "radiant-scene/1",
      "materials": { "glow": { "reflectance": 0.5, "emission": { "exitance": 100 } } },
      "surfaces": [ { "name": "box", "material": "glow",
                      "box": { "min": [0, 0, 0], "max": [2, 2, 2], "facing": "in" } } ],
      "sensors": [], "settings": { "tolerance": 0.01 } })");
    for (const char* kind : {"planar", "vertical", "cylindrical", "semi-cylindrical"}) {
        doc["sensors"].push_back({{"name", kind},
                                  {"kind", kind},
                                  {"normal", {1, 0, std::string(kind) == "planar" ? 1 : 0}},
                                  {"points", {{1, 1, 1}, {0.6, 1.3, 0.7}}}});
    }
    const Result r = solved(doc);
    ASSERT_EQ(r.status, SolveStatus::converged) << testing::describe(r);
    for (const SensorResult& s : r.sensors) {
        EXPECT_EQ(to_string(s.kind), s.name);
        for (const double e : s.illuminance) EXPECT_NEAR(e, 200, 200 * 0.02) << s.name;
    }
}

// An isotropic point source I in a black room: planar I·cos/d², vertical I·(n·ω)/d²,
// cylindrical I·sinθ/(π d²), semi-cylindrical I·sinθ·(1 + cos β)/(π d²) — θ the direction's
// angle from the vertical, β its horizontal angle from the facing.
TEST(SensorKinds, UnderAPointSourceTheyMatchTheirClosedForms) {
    Json doc = Json::parse(R"({
      "format": "radiant-scene/1",
      "materials": { "black": { "reflectance": 0 } },
      "surfaces": [ { "name": "box", "material": "black",
                      "box": { "min": [-10, -10, -10], "max": [10, 10, 10], "facing": "in" } } ],
      "luminaires": [ { "name": "bulb", "position": [2, 1, 3], "flux": 4000,
                        "distribution": "isotropic" } ],
      "sensors": [], "settings": { "tolerance": 0.01 } })");
    const Vec3 x{0, 0, 1};
    const Vec3 d = Vec3{2, 1, 3} - x;
    const double d2 = length_squared(d), intensity = 4000 / (4 * kPi);
    const Vec3 w = d / std::sqrt(d2);
    const double sin_theta = std::hypot(w.x, w.y);
    const Vec3 facing = normalized(Vec3{1, -0.5, 0});
    const double cos_beta = (w.x * facing.x + w.y * facing.y) / sin_theta;
    const std::pair<const char*, double> expected[] = {
        {"planar", intensity * w.z / d2},
        {"vertical", intensity * dot(w, facing) / d2},
        {"cylindrical", intensity * sin_theta / (kPi * d2)},
        {"semi-cylindrical", intensity * sin_theta * (1 + cos_beta) / (kPi * d2)}};
    for (const auto& [kind, value] : expected) {
        // The vertical kinds face the horizontal part of their normal.
        const Json normal =
            std::string(kind) == "planar" ? Json{0, 0, 1} : Json{facing.x, facing.y, 0.3};
        doc["sensors"].push_back(
            {{"name", kind}, {"kind", kind}, {"normal", normal}, {"points", {{x.x, x.y, x.z}}}});
    }
    const Result r = solved(doc);
    ASSERT_EQ(r.status, SolveStatus::converged) << testing::describe(r);
    for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_NEAR(r.sensors[k].illuminance[0], expected[k].second, 1e-9 * expected[k].second)
            << expected[k].first;
    }
}

TEST(SensorKinds, OtherMethodsRefuseThemClearly) {
    Json doc = office();
    doc["sensors"][0]["kind"] = "cylindrical";
    const Result r = solved(doc, "hierarchical");
    EXPECT_EQ(r.status, SolveStatus::failed);
    EXPECT_NE(r.error.find("monte-carlo"), std::string::npos) << r.error;
    EXPECT_EQ(solved(doc).stats.method, "monte-carlo");  // auto chooses it, even for one box
}

TEST(Glare, GuthIndexIsOneOnTheLineOfSightAndGrowsAwayFromIt) {
    EXPECT_NEAR(guth_position_index(1, 0, 0), 1, 1e-12);
    EXPECT_LT(guth_position_index(10, 0, 1), guth_position_index(10, 0, 3));
    EXPECT_LT(guth_position_index(10, 1, 1), guth_position_index(10, 3, 1));
    EXPECT_GT(guth_position_index(1, 0, 1), 5);  // 45° above the line of sight
}

TEST(Glare, ProjectedAreaFollowsTheShape) {
    const LuminousShape square{0.6, 0.3, 0, false, false};
    EXPECT_NEAR(projected_area_m2(square, 0, 0, 1), 0.18, 1e-15);
    EXPECT_NEAR(projected_area_m2(square, 0.8, 0, 0.6), 0.18 * 0.6, 1e-15);
    EXPECT_EQ(projected_area_m2(square, 0, 0, -1), 0);  // seen from above: nothing
    const LuminousShape box{0.6, 0.3, 0.1, false, false};
    EXPECT_NEAR(projected_area_m2(box, 1, 0, 0), 0.3 * 0.1, 1e-15);
    EXPECT_NEAR(projected_area_m2(box, 0, 1, 0), 0.6 * 0.1, 1e-15);
    const LuminousShape disc{0.2, 0.2, 0, true, false};
    EXPECT_NEAR(projected_area_m2(disc, 0, 0, 1), kPi * 0.01, 1e-15);
}

TEST(Glare, ALuminaireBehindTheObserverAddsNothing) {
    Json doc = office();
    doc["observers"] = {{{"name", "eye"}, {"position", {2, 3.5, 1.2}}, {"view", {0, 1, 0}}}};
    // L1 at y = 2 is behind an eye at y = 3.5 looking toward +y.
    Result r = solved(doc);
    ASSERT_EQ(r.status, SolveStatus::converged) << testing::describe(r);
    ASSERT_EQ(r.observers.size(), 1u);
    EXPECT_EQ(r.observers[0].glare_sum, 0);
    EXPECT_EQ(r.observers[0].ugr, 0);
    EXPECT_GT(r.observers[0].background_luminance, 0);
    // Turned round, it looks at the luminaire.
    doc["observers"][0]["view"] = {0, -1, 0};
    r = solved(doc);
    EXPECT_GT(r.observers[0].glare_sum, 0);
    EXPECT_GT(r.observers[0].ugr, 10);
}

// The radiosity methods read the background from rays into their solved mesh, the Monte Carlo
// method gathers it at the eye: the same room gives the same UGR either way, and a scene with
// observers and no sensors is rated too.
TEST(Glare, RadiosityMethodsRateItFromTheSolvedMesh) {
    Json doc = office();
    doc["observers"] = {{{"name", "eye"}, {"position", {2, 0.5, 1.2}}, {"view", {0, 1, 0}}}};
    const Result mc = solved(doc, "monte-carlo");
    ASSERT_EQ(mc.status, SolveStatus::converged) << testing::describe(mc);
    doc.erase("sensors");
    for (const char* method : {"hierarchical", "direct"}) {
        SCOPED_TRACE(method);
        const Result r = solved(doc, method);
        ASSERT_EQ(r.status, SolveStatus::converged) << testing::describe(r);
        ASSERT_EQ(r.observers.size(), 1u);
        const ObserverResult& o = r.observers[0];
        EXPECT_NEAR(o.glare_sum, mc.observers[0].glare_sum, 1e-9 * o.glare_sum);
        EXPECT_NEAR(o.background_luminance, mc.observers[0].background_luminance,
                    0.05 * o.background_luminance);
        EXPECT_NEAR(o.ugr, mc.observers[0].ugr, 0.3);
        EXPECT_GT(o.ugr_error_estimate, 0);
        EXPECT_LT(o.ugr_error_estimate, 0.2);
    }
}

TEST(Glare, ALuminaireWithoutALuminousAreaIsRefusedWhereGlareIsRated) {
    Json doc = office();
    doc["luminaires"][0].erase("luminous_area");
    EXPECT_TRUE(problems_of(doc).empty());  // no glare rated: no area needed
    doc["observers"] = {{{"name", "eye"}, {"position", {2, 0.5, 1.2}}, {"view", {0, 1, 0}}}};
    const auto problems = problems_of(doc);
    ASSERT_TRUE(has_pointer(problems, "/luminaires/0"));
    EXPECT_NE(problems[0].message.find("luminous_area"), std::string::npos);
    // A requirement that limits UGR rates glare too (at the standard observers).
    doc.erase("observers");
    doc["sensors"][0]["requirement"] = {{"ugr_l", 19}};
    EXPECT_TRUE(has_pointer(problems_of(doc), "/luminaires/0"));
}

/// Two groups of sources — downlights and a glowing panel — and two light scenes.
Json two_groups() {
    Json doc = office();
    doc["materials"]["glow"] = {{"reflectance", 0.2},
                                {"emission", {{"exitance", 2000}, {"group", "panel"}}}};
    doc["surfaces"].push_back(
        {{"name", "panel"},
         {"material", "glow"},
         {"polygon", {{0.5, 3, 2.99}, {0.5, 3.5, 2.99}, {3.5, 3.5, 2.99}, {3.5, 3, 2.99}}}});
    doc["luminaires"][0]["group"] = "down";
    doc["light_scenes"] = {{{"name", "mix"}, {"dimming", {{"down", 0.3}, {"panel", 0.8}}}},
                           {{"name", "panel only"}, {"dimming", {{"panel", 1}}}}};
    doc["settings"]["tolerance"] = 0.01;
    return doc;
}

double rms_relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double sum = 0, mean = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sum += (a[i] - b[i]) * (a[i] - b[i]);
        mean += b[i];
    }
    return std::sqrt(sum / static_cast<double>(a.size())) / (mean / static_cast<double>(a.size()));
}

// Each light component is solved apart and each group and light scene kept per sensor point:
// their counts are limited before any work, the excess pointed at.
TEST(LightScenes, LimitsAreEnforcedOnTheTotalsWithTheirPointers) {
    const auto refused = [](const Json& doc, const SceneLimits& limits) {
        proto::ParseLimits parse;
        parse.scene = limits;
        return proto::parse_scene(doc.dump(), parse).problems;
    };
    Json doc = two_groups();  // two groups of one source each, two light scenes, 36 points
    EXPECT_TRUE(refused(doc, {}).empty());
    SceneLimits limits;
    limits.max_light_components = 1;
    // The panel's material opens the second component.
    EXPECT_TRUE(has_pointer(refused(doc, limits), "/materials/glow/emission"));
    limits = {};
    limits.max_light_scenes = 1;
    EXPECT_TRUE(has_pointer(refused(doc, limits), "/light_scenes"));
    limits = {};
    limits.max_observers = 0;
    doc["observers"] = {{{"name", "eye"}, {"position", {2, 0.5, 1.2}}, {"view", {0, 1, 0}}}};
    EXPECT_TRUE(has_pointer(refused(doc, limits), "/observers"));
    // 36 desk points and, from the requirement, its band: kept once and per group and scene.
    limits = {};
    limits.max_kept_sensor_values = 5 * 36;
    EXPECT_TRUE(refused(doc, limits).empty());
    doc["sensors"][0]["requirement"] = {{"em_lx", 300}};
    const auto band = refused(doc, limits);
    ASSERT_TRUE(has_pointer(band, "/sensors"));
    EXPECT_NE(band[0].message.find("(1 + 2 groups + 2 light scenes)"), std::string::npos)
        << band[0].message;
    // Each point takes a shadow ray to each luminaire (one here): 36 points fit 36 pairs, and
    // the band the requirement adds does not.
    limits = {};
    limits.max_luminaire_sensor_pairs = 36;
    EXPECT_TRUE(refused(two_groups(), limits).empty());
    const auto rays = refused(doc, limits);
    ASSERT_TRUE(has_pointer(rays, "/sensors"));
    EXPECT_NE(rays[0].message.find("1 luminaires (a shadow ray each)"), std::string::npos)
        << rays[0].message;
    // A hundred thousand luminaires, each its own group: refused, quickly (sorting the sources
    // into components by linear search took minutes).
    Scene many = parsed(office());
    const Luminaire downlight = many.luminaires[0];
    many.luminaires.clear();
    for (int i = 0; i < 100000; ++i) {
        Luminaire l = downlight;
        l.design.group = std::to_string(i);
        many.luminaires.push_back(std::move(l));
    }
    const auto start = std::chrono::steady_clock::now();
    EXPECT_TRUE(has_pointer(check_scene(many), "/luminaires/32"));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5);
}

TEST(LightScenes, ACombinationEqualsAFreshSolveOfTheCombinedScene) {
    const Json doc = two_groups();
    const Result r = solved(doc);
    ASSERT_EQ(r.status, SolveStatus::converged) << testing::describe(r);
    ASSERT_EQ(r.groups.size(), 2u);
    ASSERT_EQ(r.light_scenes.size(), 2u);
    // The scene dimmed by hand: 30 % of the downlight's flux, 80 % of the panel's exitance.
    Json fresh = doc;
    fresh.erase("light_scenes");
    fresh["luminaires"][0].erase("group");
    fresh["materials"]["glow"]["emission"] = {{"exitance", 0.8 * 2000}};
    fresh["luminaires"][0]["flux"] = 0.3 * 3000;
    // The same method: `auto` would solve seven polygons without groups by radiosity.
    const Result f = solved(fresh, "monte-carlo");
    ASSERT_EQ(f.status, SolveStatus::converged) << testing::describe(f);
    const LightSceneResult& mix = r.light_scenes[0];
    EXPECT_EQ(mix.name, "mix");
    const double difference =
        rms_relative_difference(mix.sensors[0].illuminance, f.sensors[0].illuminance);
    EXPECT_LE(difference, doc["settings"]["tolerance"].get<double>());
    // The combination's estimate follows from the groups' and bounds what it claims.
    EXPECT_GT(mix.error_estimate, 0);
    EXPECT_LE(mix.error_estimate, doc["settings"]["tolerance"].get<double>());
    EXPECT_LE(difference, mix.error_estimate + f.stats.error_estimate);
    // Every group at full output is the result itself.
    const std::vector<double>& all = r.sensors[0].illuminance;
    for (std::size_t i = 0; i < all.size(); ++i) {
        EXPECT_NEAR(r.groups[0].sensors[0].illuminance[i] + r.groups[1].sensors[0].illuminance[i],
                    all[i], 1e-9 * all[i]);
    }
}

// Two luminaire groups, as in the issue: every dimming, off and full included, equals a fresh
// solve of the room with each luminaire's flux scaled by hand.
TEST(LightScenes, TwoLuminaireGroupsGiveAnyCombinationOfAFreshSolve) {
    Json doc = office();
    Json window = doc["luminaires"][0];
    window["name"] = "W";
    window["position"] = {1, 1, 2.9};
    window["group"] = "window";
    doc["luminaires"][0]["group"] = "middle";
    doc["luminaires"].push_back(window);
    doc["settings"]["tolerance"] = 0.01;
    const std::pair<double, double> combinations[] = {{1, 0}, {0.25, 0.75}, {0.6, 0.1}};
    for (const auto& [middle, side] : combinations) {
        doc["light_scenes"].push_back(
            {{"name", std::to_string(middle) + "/" + std::to_string(side)},
             {"dimming", {{"middle", middle}, {"window", side}}}});
    }
    const Result r = solved(doc);
    ASSERT_EQ(r.status, SolveStatus::converged) << testing::describe(r);
    ASSERT_EQ(r.light_scenes.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        const auto& [middle, side] = combinations[k];
        SCOPED_TRACE(r.light_scenes[k].name);
        Json fresh = doc;
        fresh.erase("light_scenes");
        fresh["luminaires"] = Json::array();
        for (const auto& [luminaire, dimming] :
             {std::pair{doc["luminaires"][0], middle}, {doc["luminaires"][1], side}}) {
            if (dimming == 0) continue;  // off: as if it were not there
            Json l = luminaire;
            l.erase("group");
            l["flux"] = dimming * 3000;
            fresh["luminaires"].push_back(l);
        }
        const Result f = solved(fresh, "monte-carlo");
        ASSERT_EQ(f.status, SolveStatus::converged) << testing::describe(f);
        const double difference = rms_relative_difference(r.light_scenes[k].sensors[0].illuminance,
                                                          f.sensors[0].illuminance);
        EXPECT_LE(difference, r.light_scenes[k].error_estimate + f.stats.error_estimate);
        EXPECT_LE(r.light_scenes[k].error_estimate, 0.01);
    }
}

TEST(LightScenes, HierarchicalRefusesGroupsWithAClearError) {
    const Result r = solved(two_groups(), "hierarchical");
    EXPECT_EQ(r.status, SolveStatus::failed);
    EXPECT_NE(r.error.find("monte-carlo"), std::string::npos) << r.error;
}

TEST(LightScenes, TheStoredResultEvaluatesAnyCombinationAgain) {
    const Result r = solved(two_groups());
    ASSERT_EQ(r.status, SolveStatus::converged) << testing::describe(r);
    // Through the result document, as the service stores it.
    proto::ResultReadOutcome read = proto::read_result(proto::result_to_json(r).dump());
    ASSERT_TRUE(read.ok()) << read.problems.front().pointer << ": "
                           << read.problems.front().message;
    const Result& stored = *read.result;
    LightScene mix{"mix", {{"down", 0.3}, {"panel", 0.8}}};
    const auto evaluated = evaluate_light_scene(stored, mix);
    ASSERT_TRUE(std::holds_alternative<LightSceneResult>(evaluated));
    const LightSceneResult& e = std::get<LightSceneResult>(evaluated);
    for (std::size_t i = 0; i < e.sensors[0].illuminance.size(); ++i) {
        EXPECT_NEAR(e.sensors[0].illuminance[i], r.light_scenes[0].sensors[0].illuminance[i],
                    1e-12 * r.light_scenes[0].sensors[0].illuminance[i] + 1e-9);
    }
    EXPECT_NEAR(e.error_estimate, r.light_scenes[0].error_estimate, 1e-12);
    // A group the solve does not have, a dimming outside [0, 1]: refused with a pointer.
    const auto bad = evaluate_light_scene(stored, {"x", {{"nope", 1}, {"down", 1.5}}});
    ASSERT_TRUE(std::holds_alternative<std::vector<Problem>>(bad));
    const auto& problems = std::get<std::vector<Problem>>(bad);
    EXPECT_TRUE(has_pointer(problems, "/dimming/nope"));
    EXPECT_TRUE(has_pointer(problems, "/dimming/down"));
    // More names than the solve has groups: one problem, however many names.
    LightScene crowded{"crowded", {}};
    for (int i = 0; i < 1000; ++i) crowded.dimming.emplace_back(std::to_string(i), 1);
    const auto crowd = evaluate_light_scene(stored, crowded);
    ASSERT_TRUE(std::holds_alternative<std::vector<Problem>>(crowd));
    EXPECT_EQ(std::get<std::vector<Problem>>(crowd).size(), 1u);
    EXPECT_EQ(std::get<std::vector<Problem>>(crowd)[0].pointer, "/dimming");
}

TEST(LightScenes, TenThousandSensorPointsTakeUnderFiftyMilliseconds) {
    Result solved_result;
    SensorResult shape;
    shape.name = "floor";
    shape.illuminance.assign(10000, 0.0);
    solved_result.sensors.push_back(shape);
    for (const char* name : {"a", "b", "c"}) {
        GroupContribution g;
        g.name = name;
        GroupContribution::Sensors s;
        s.name = "floor";
        for (int i = 0; i < 10000; ++i) s.illuminance.push_back(100 + i % 37);
        s.error_lx = 1;
        g.sensors.push_back(std::move(s));
        solved_result.groups.push_back(std::move(g));
    }
    const auto start = std::chrono::steady_clock::now();
    const auto r = evaluate_light_scene(solved_result, {"half", {{"a", 0.5}, {"c", 1}}});
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(std::holds_alternative<LightSceneResult>(r));
    const auto& values = std::get<LightSceneResult>(r).sensors[0].illuminance;
    EXPECT_DOUBLE_EQ(values[1], 1.5 * 101);
    EXPECT_LT(seconds, 0.05);
}

}  // namespace
}  // namespace radiant
