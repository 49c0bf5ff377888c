// Every scene of the shared validation set against its expected answer (tests/data/scenes,
// copied from shared/validation so that a clone is self-contained), with default settings —
// and with `method: hierarchical` forced, since every accuracy bar must hold with it too.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "scene_files.h"

namespace radiant {
namespace {

using testing::data_path;

nlohmann::json expected() {
    std::ifstream in(data_path("scenes/expected.json"));
    return nlohmann::json::parse(in);
}

class ValidationScene : public ::testing::TestWithParam<std::string> {};

void expect_matches(const std::string& name, const std::string& method) {
    const Scene scene = testing::load_scene(data_path("scenes/" + name + ".json"));
    SolveOptions options = options_from(scene.settings);
    options.method = method;
    const Result result = solve(scene, options);
    ASSERT_EQ(result.status, SolveStatus::converged) << result.error;
    EXPECT_LE(result.stats.error_estimate, scene.settings.tolerance);
    // Keep the document alive for the loop: `expected()[name]` alone would dangle (the
    // temporary json dies before the loop body runs, and the loop saw no checks at all).
    const nlohmann::json all = expected();
    ASSERT_TRUE(all.contains(name));
    ASSERT_FALSE(all[name].empty()) << "no checks for " << name;
    for (const auto& check : all[name]) {
        const std::string what = check["what"];
        if (what == "surface") {
            const auto* s = testing::find_surface(result, check["surface"]);
            ASSERT_NE(s, nullptr);
            const double got = check["field"] == "average_irradiance" ? s->average_irradiance
                                                                      : s->average_radiosity;
            const double want = check["value"];
            EXPECT_NEAR(got / want, 1.0, check["rel_tol"].get<double>())
                << check["surface"] << " " << check["field"] << ": got " << got << ", want " << want
                << " (" << check["why"] << ")";
        } else if (what == "energy") {
            const double emitted = result.stats.emitted_flux_lm;
            EXPECT_NEAR(result.stats.absorbed_flux_lm / emitted, 1.0,
                        check["rel_tol"].get<double>())
                << "absorbed " << result.stats.absorbed_flux_lm << " lm, emitted " << emitted;
        } else if (what == "sensor-max") {
            const auto* dark = testing::find_sensor(result, check["sensor"]);
            const auto* lit = testing::find_sensor(result, check["max_relative_to"]);
            ASSERT_NE(dark, nullptr);
            ASSERT_NE(lit, nullptr);
            ASSERT_GT(lit->average, 0);
            const double ratio = dark->max / lit->average;
            const double limit = check["value"].get<double>();
            EXPECT_LE(ratio, limit)
                << check["sensor"] << " max " << dark->max << " vs lit mean " << lit->average;
        } else {
            ADD_FAILURE() << "unknown check kind " << what;
        }
    }
}

TEST_P(ValidationScene, MatchesExpected) { expect_matches(GetParam(), "auto"); }

TEST_P(ValidationScene, MatchesExpectedHierarchical) { expect_matches(GetParam(), "hierarchical"); }

std::vector<std::string> scene_names() {
    const nlohmann::json all = expected();
    std::vector<std::string> names;
    for (auto it = all.cbegin(); it != all.cend(); ++it) names.push_back(it.key());
    return names;
}

INSTANTIATE_TEST_SUITE_P(Shared, ValidationScene, ::testing::ValuesIn(scene_names()),
                         [](const auto& param_info) {
                             std::string s = param_info.param;
                             for (char& c : s) {
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             }
                             return s;
                         });

}  // namespace
}  // namespace radiant
