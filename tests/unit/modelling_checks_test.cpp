// The modelling checks (radiant/warnings.h): each mistake of tests/data/warnings gives its
// warning, naming what it is about; strict solves refuse them before solving; and no validation
// scene or example gives any warning at all.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "checks/solve_outcome.h"
#include "radiant/proto/honeybee.h"
#include "radiant/proto/result_json.h"
#include "radiant/proto/scene_json.h"
#include "radiant/solve.h"
#include "radiant/warnings.h"
#include "scene_builder.h"
#include "test_files.h"

namespace radiant {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path warnings_dir() { return fs::path(RADIANT_TEST_DATA) / "warnings"; }

Scene load(const fs::path& file) {
    proto::ParseOutcome outcome = proto::load_scene_file(file);
    EXPECT_TRUE(outcome.ok()) << file << ": " << (outcome.ok() ? "" : outcome.problems[0].message);
    return outcome.ok() ? std::move(*outcome.scene) : Scene{};
}

std::set<std::pair<std::string, std::string>> codes_and_pointers(const std::vector<Warning>& ws) {
    std::set<std::pair<std::string, std::string>> out;
    for (const Warning& w : ws) out.insert({w.code, w.pointer});
    return out;
}

std::string listed(const std::vector<Warning>& warnings) {
    return warnings.empty() ? "none" : describe_warnings(warnings);
}

/// The scenes that model rooms as meant: the validation scenes, the box rooms, the RADIANCE
/// comparison room, the picture scene and every example.
std::vector<fs::path> validation_scenes_and_examples() {
    const fs::path data = RADIANT_TEST_DATA,
                   examples = fs::path(RADIANT_SOURCE_DIR) / "proto/examples";
    std::vector<fs::path> files;
    for (const fs::path& dir :
         {data / "scenes", data / "box_rooms", data / "radiance", data / "pictures", examples,
          examples / "furnished-office", examples / "furnished-office-clutter"}) {
        const auto more = test::json_files(dir);
        files.insert(files.end(), more.begin(), more.end());
    }
    return files;
}

TEST(ModellingChecks, EachMistakeGivesItsWarningNamingWhatItIsAbout) {
    const json expected = json::parse(test::read_text(warnings_dir() / "expected.json"));
    const auto files = test::json_files(warnings_dir());
    ASSERT_EQ(files.size(), expected.size()) << "every mistake scene needs an expectation";
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.filename().string());
        const std::vector<Warning> got = check_modelling(load(file));
        std::set<std::pair<std::string, std::string>> want;
        for (const json& w : expected.at(file.filename().string())) {
            const std::string code = w.at("code"), pointer = w.at("pointer");
            want.insert({code, pointer});
            const auto it = std::find_if(got.begin(), got.end(), [&](const Warning& g) {
                return g.code == code && g.pointer == pointer;
            });
            if (it == got.end()) continue;  // reported by the comparison below
            for (const std::string name : w.at("names")) {
                EXPECT_NE(it->message.find(name), std::string::npos)
                    << it->message << " does not name " << name;
            }
        }
        EXPECT_EQ(codes_and_pointers(got), want) << listed(got);
    }
}

TEST(ModellingChecks, ValidationScenesAndExamplesGiveNoWarning) {
    const auto files = validation_scenes_and_examples();
    ASSERT_GE(files.size(), 20u);
    for (const fs::path& file : files) {
        EXPECT_TRUE(check_modelling(load(file)).empty())
            << file << ": " << listed(check_modelling(load(file)));
    }
}

TEST(ModellingChecks, ValidationScenesAlsoInTheSharedDirectoryGiveNoWarning) {
    // The validation scenes as the project shares them outside the repository, where present.
    const fs::path shared = "/work/shared/validation/scenes";
    if (!fs::is_directory(shared)) GTEST_SKIP() << shared << " is not on this machine";
    for (const fs::path& file : test::json_files(shared)) {
        EXPECT_TRUE(check_modelling(load(file)).empty()) << file;
    }
}

TEST(ModellingChecks, AHoneybeeImportHasNoLight) {
    const proto::HoneybeeOutcome imported = proto::honeybee_to_scene(
        test::read_text(fs::path(RADIANT_TEST_DATA) / "honeybee/office-window.hbjson"));
    ASSERT_TRUE(imported.scene);
    const proto::ParseOutcome parsed = proto::parse_scene(imported.scene->dump());
    ASSERT_TRUE(parsed.ok());
    const std::vector<Warning> got = check_modelling(*parsed.scene);
    EXPECT_EQ(codes_and_pointers(got),
              (std::set<std::pair<std::string, std::string>>{{"no_light", "/luminaires"}}))
        << listed(got);
}

// Luminaires near the ceiling as meant are no mistake: a downlight 3 cm under it aimed down, a
// bare lamp 1 cm under it (a third of its light meets the ceiling at once, and would aimed any
// way), an uplighter 30 cm under it. The same downlight aimed up, or a lamp on the ceiling
// plane itself, is (tests/data/warnings).
TEST(ModellingChecks, LuminairesNearTheCeilingAsMeantAreNotWarnedAbout) {
    const Scene aimed_up = load(warnings_dir() / "luminaire-aimed-up.json");
    struct Case {
        const char* what;
        double below_ceiling;
        Distribution distribution;
        Vec3 aim;
    };
    for (const Case& c : {Case{"downlight aimed down", 0.03, Distribution::lambertian, {0, 0, -1}},
                          Case{"bare lamp", 0.01, Distribution::isotropic, {0, 0, -1}},
                          Case{"uplighter", 0.3, Distribution::lambertian, {0, 0, 1}}}) {
        SCOPED_TRACE(c.what);
        Scene scene = aimed_up;
        for (Luminaire& l : scene.luminaires) {
            l.position.z = 3 - c.below_ceiling;
            l.distribution = c.distribution;
            l.aim = c.aim;
        }
        const std::vector<Warning> got = check_modelling(scene);
        EXPECT_TRUE(got.empty()) << listed(got);
    }
}

// Points facing away from every luminaire measure what was meant where they lie on the surface
// they measure: a ceiling's illuminance under downlights, 1 cm below it. The same points at
// work-plane height are a normal reversed (tests/data/warnings).
TEST(ModellingChecks, PointsOnTheCeilingFacingDownAreNotWarnedAbout) {
    Scene scene = load(warnings_dir() / "workplane-facing-down.json");
    ASSERT_EQ(check_modelling(scene).size(), 1u);
    for (Vec3& p : scene.sensors[0].points) p.z = 2.99;
    const std::vector<Warning> got = check_modelling(scene);
    EXPECT_TRUE(got.empty()) << listed(got);
}

// A y-up model is lit as meant where nothing leans on z being up: luminaires aimed down its y,
// or isotropic ones. Only aims along its floor (the z-up default) are a mistake (tests/data).
TEST(ModellingChecks, AYUpModelLitAsMeantIsNotWarnedAbout) {
    const Scene y_up = load(warnings_dir() / "y-up-room.json");
    ASSERT_EQ(check_modelling(y_up).size(), 1u);
    Scene aimed = y_up, isotropic = y_up;
    for (Luminaire& l : aimed.luminaires) l.aim = {0, -1, 0};
    for (Luminaire& l : isotropic.luminaires) l.distribution = Distribution::isotropic;
    EXPECT_TRUE(check_modelling(aimed).empty()) << listed(check_modelling(aimed));
    EXPECT_TRUE(check_modelling(isotropic).empty()) << listed(check_modelling(isotropic));
    // A z-up room measured on its south wall (facing +y), lit by downlights along its north
    // wall: near the top of y, and of z.
    const proto::ParseOutcome z_up = proto::parse_scene(R"({"format": "radiant-scene/1",
        "materials": {"w": {"reflectance": 0.5}},
        "surfaces": [{"name": "room", "material": "w",
                      "box": {"min": [0, 0, 0], "max": [6, 4, 3], "facing": "in"}}],
        "luminaires": [{"name": "L1", "position": [2, 3.6, 2.95], "flux": 2000,
                        "distribution": "lambertian"},
                       {"name": "L2", "position": [4, 3.6, 2.95], "flux": 2000,
                        "distribution": "lambertian"}],
        "sensors": [{"name": "south wall", "normal": [0, 1, 0],
                     "grid": {"origin": [0.5, 0.01, 0.5], "u": [5, 0, 0], "v": [0, 0, 2],
                              "nu": 5, "nv": 2}}]})");
    ASSERT_TRUE(z_up.ok());
    EXPECT_TRUE(check_modelling(*z_up.scene).empty()) << listed(check_modelling(*z_up.scene));
}

// An imported model's surfaces are named by the document surface that imports them.
TEST(ModellingChecks, WarningsPointAtTheDocumentsSurfaces) {
    const Scene scene = load(warnings_dir() / "ceiling-wound-wrong.json");
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        EXPECT_EQ(scene.surfaces[i].pointer, "/surfaces/" + std::to_string(i));
    }
    Scene built = scene;
    for (Surface& s : built.surfaces) s.pointer = "/surfaces/9";
    const std::vector<Warning> got = check_modelling(built);
    ASSERT_EQ(got.size(), 1u) << listed(got);
    EXPECT_EQ(got[0].pointer, "/surfaces/9");
}

// Many warnings of one kind are one mistake to fix: a name used 31 times gives one duplicate_name,
// and past 20 warnings of one code a last one says how many more there are.
TEST(ModellingChecks, ManyOfOneMistakeAreSummedUp) {
    Scene scene = load(warnings_dir() / "desks-facing-in.json");
    Surface desk = scene.surfaces[1];
    desk.pointer.clear();  // each copy at its own index
    for (int copy = 0; copy < 30; ++copy) scene.surfaces.push_back(desk);
    const std::vector<Warning> got = check_modelling(scene);
    std::vector<Warning> duplicates, facing_in;
    for (const Warning& w : got) {
        if (w.code == "duplicate_name") duplicates.push_back(w);
        if (w.code == "box_faces_in") facing_in.push_back(w);
    }
    ASSERT_EQ(duplicates.size(), 1u) << listed(got);
    EXPECT_EQ(duplicates[0].pointer, "/surfaces/3/name");
    EXPECT_NE(duplicates[0].message.find("is also used by /surfaces/1 and 29 more"),
              std::string::npos)
        << duplicates[0].message;
    // 32 boxes face in: 20 listed, then the 21st with the count of the 12 not listed.
    ASSERT_EQ(facing_in.size(), 21u) << listed(got);
    EXPECT_EQ(facing_in[19].pointer, "/surfaces/20/box");
    EXPECT_EQ(facing_in[20].pointer, "/surfaces/21/box");
    EXPECT_EQ(facing_in[20].message.rfind("12 more box_faces_in warnings are not listed", 0), 0u)
        << facing_in[20].message;
}

TEST(ModellingChecks, SolvedResultsCarryTheWarningsAndJsonAlwaysHasThem) {
    SolveOptions options;
    options.tolerance = 0.1;
    const Result warned = solve(load(warnings_dir() / "ceiling-wound-wrong.json"), options);
    EXPECT_EQ(warned.status, SolveStatus::converged) << warned.error;
    EXPECT_EQ(codes_and_pointers(warned.warnings),
              (std::set<std::pair<std::string, std::string>>{{"back_face_light", "/surfaces/5"}}))
        << listed(warned.warnings);
    const json doc = proto::result_to_json(warned);
    ASSERT_EQ(doc["warnings"].size(), 1u);
    EXPECT_EQ(doc["warnings"][0]["code"], "back_face_light");
    EXPECT_EQ(doc["warnings"][0]["pointer"], "/surfaces/5");

    const Result clean =
        solve(load(fs::path(RADIANT_SOURCE_DIR) / "proto/examples/simple-room.json"), options);
    EXPECT_TRUE(clean.warnings.empty()) << listed(clean.warnings);
    EXPECT_EQ(proto::result_to_json(clean)["warnings"], json::array());
    Result failed;
    EXPECT_EQ(proto::result_to_json(failed)["warnings"], json::array());
}

/// The stages a solve reported, and the warnings it announced before solving.
class StageRecorder : public SolveObserver {
public:
    void on_progress(const Progress& p) override { stages.insert(p.stage); }
    void on_warnings(const std::vector<Warning>& w) override { announced = w; }
    std::set<std::string> stages;
    std::vector<Warning> announced;
};

// Strict: every mistake refuses before any solving stage runs, with its warnings.
TEST(ModellingChecks, StrictSolvesRefuseEveryMistakeBeforeSolving) {
    SolveOptions options;
    options.strict = true;
    for (const fs::path& file : test::json_files(warnings_dir())) {
        SCOPED_TRACE(file.filename().string());
        StageRecorder recorder;
        const Result r = solve(load(file), options, &recorder);
        EXPECT_EQ(r.status, SolveStatus::failed);
        EXPECT_EQ(r.error.rfind("strict: ", 0), 0u) << r.error;
        EXPECT_FALSE(r.warnings.empty());
        EXPECT_NE(r.error.find(r.warnings[0].pointer), std::string::npos) << r.error;
        EXPECT_EQ(codes_and_pointers(recorder.announced), codes_and_pointers(r.warnings));
        EXPECT_EQ(recorder.stages, std::set<std::string>{"meshing"}) << "only the preparation";
        EXPECT_TRUE(r.sensors.empty());
    }
    // settings.strict is the same switch.
    Scene scene = load(warnings_dir() / "no-light.json");
    scene.settings.strict = true;
    EXPECT_EQ(solve(scene, options_from(scene.settings)).status, SolveStatus::failed);
    scene = load(fs::path(RADIANT_SOURCE_DIR) / "proto/examples/simple-room.json");
    scene.settings.strict = true;
    scene.settings.tolerance = 0.1;
    const Result clean = solve(scene, options_from(scene.settings));
    EXPECT_EQ(clean.status, SolveStatus::converged) << clean.error;
}

TEST(ModellingChecks, TimeLimitIsAWarningAndStrictMakesItAFailure) {
    Scene scene = load(warnings_dir() / "desks-facing-in.json");
    scene.surfaces.resize(1);  // the room alone: no modelling warning
    SolveOptions options;
    options.tolerance = 0.001;
    options.max_seconds = 0.02;
    const Result stopped = solve(scene, options);
    ASSERT_EQ(stopped.status, SolveStatus::stopped) << stopped.error;
    EXPECT_EQ(
        codes_and_pointers(stopped.warnings),
        (std::set<std::pair<std::string, std::string>>{{"time_limit", "/settings/max_seconds"}}))
        << listed(stopped.warnings);
    options.strict = true;
    const Result failed = solve(scene, options);
    EXPECT_EQ(failed.status, SolveStatus::failed);
    EXPECT_NE(failed.error.find("time_limit"), std::string::npos) << failed.error;
    // A cancel is the user's own doing: no warning.
    CancellationToken cancel;
    cancel.cancel();
    options.strict = false;
    options.max_seconds.reset();
    const Result cancelled = solve(scene, options, nullptr, &cancel);
    EXPECT_TRUE(cancelled.warnings.empty()) << listed(cancelled.warnings);
}

// A solve stopped at its limit says where its estimate stands against the tolerance: a stop
// during a first estimate below the tolerance (a hierarchical solve swept in its grace, say) is
// not "over" it.
TEST(ModellingChecks, TimeLimitWarningPlacesTheEstimateAgainstTheTolerance) {
    SolveOptions options;
    options.tolerance = 0.01;
    options.max_seconds = 10;
    Result r;
    r.status = SolveStatus::stopped;
    r.stats.seconds = 10.2;
    auto message = [&](double estimate) {
        r.stats.error_estimate = estimate;
        std::vector<Warning> out;
        check_solve_outcome(r, options, false, out);
        return out.size() == 1 ? out.front().message : listed(out);
    };
    EXPECT_NE(message(0.5).find("an error estimate of 0.5, over the tolerance 0.01:"),
              std::string::npos)
        << message(0.5);
    EXPECT_NE(message(0.004).find("an error estimate of 0.004 (tolerance 0.01):"),
              std::string::npos)
        << message(0.004);
}

TEST(ModellingChecks, SettingsStrictIsReadAndChecked) {
    const std::string scene =
        R"({"format": "radiant-scene/1", "materials": {"w": {"reflectance": 0.5}},
            "surfaces": [{"name": "r", "material": "w", "box": {"min": [0,0,0], "max": [1,1,1]}}],
            "settings": {"strict": )";
    const proto::ParseOutcome on = proto::parse_scene(scene + "true}}");
    ASSERT_TRUE(on.ok());
    EXPECT_TRUE(on.scene->settings.strict);
    EXPECT_TRUE(options_from(on.scene->settings).strict);
    const proto::ParseOutcome bad = proto::parse_scene(scene + "\"yes\"}}");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.problems[0].pointer, "/settings/strict");
}

// docs/warnings.md documents exactly the codes the result schema allows, and the mistake
// scenes use only those.
TEST(ModellingChecks, DocumentedCodesAreTheSchemasCodes) {
    const json schema = json::parse(
        test::read_text(fs::path(RADIANT_SOURCE_DIR) / "proto/schema/result.schema.json"));
    std::set<std::string> allowed;
    for (const std::string code : schema["$defs"]["warning"]["properties"]["code"]["enum"])
        allowed.insert(code);
    std::set<std::string> documented;
    std::istringstream doc(test::read_text(fs::path(RADIANT_SOURCE_DIR) / "docs/warnings.md"));
    std::string line;
    bool in_table = false;
    while (std::getline(doc, line)) {
        if (line.rfind("## ", 0) == 0) in_table = line == "## The codes";
        if (in_table && line.rfind("| `", 0) == 0)
            documented.insert(line.substr(3, line.find('`', 3) - 3));
    }
    EXPECT_EQ(documented, allowed);
    const json expected = json::parse(test::read_text(warnings_dir() / "expected.json"));
    for (const auto& [file, warnings] : expected.items()) {
        for (const json& w : warnings) EXPECT_TRUE(allowed.contains(w.at("code"))) << file;
    }
}

}  // namespace
}  // namespace radiant
