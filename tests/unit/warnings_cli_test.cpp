// Warnings on the command line: `FILE: /pointer: message [code]` on stderr, exit 0 unless
// --strict (or the scene's settings.strict) makes them errors: exit 2 and nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using radiant::test::CliRun;
using radiant::test::run_cli;

std::string mistake(const std::string& name) {
    return std::string(RADIANT_TEST_DATA) + "/warnings/" + name;
}

fs::path scratch(const std::string& name) {
    return fs::temp_directory_path() /
           ("radiant_warnings_cli_" + std::to_string(getpid()) + "_" + name);
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

TEST(WarningsCli, ValidatePrintsEachWarningAsALineAndExitsZero) {
    const std::string file = mistake("desks-facing-in.json");
    const CliRun r = run_cli("validate '" + file + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, file + ": ok\n");
    const std::regex shape("^" + file +
                           R"(: /surfaces/[12]/box: box "desk [12]" faces in.* \[box_faces_in\]$)");
    const std::vector<std::string> lines = lines_of(r.err);
    EXPECT_EQ(lines.size(), 2u) << r.err;
    for (const std::string& line : lines) EXPECT_TRUE(std::regex_match(line, shape)) << line;
}

TEST(WarningsCli, StrictMakesEveryMistakeAnErrorWithItsPointer) {
    const json expected = json::parse(
        radiant::test::read_text(std::string(RADIANT_TEST_DATA) + "/warnings/expected.json"));
    for (const auto& [name, warnings] : expected.items()) {
        const std::string file = mistake(name);
        const CliRun r = run_cli("validate --strict '" + file + "'");
        EXPECT_EQ(r.exit_code, 2) << name;
        EXPECT_EQ(r.out, "") << name;
        for (const json& w : warnings) {
            // Built with append: GCC 12 reports a false -Wrestrict on "[" + code + "]".
            const std::string start = std::string(file)
                                          .append(": ")
                                          .append(w.at("pointer").get<std::string>())
                                          .append(": ");
            const std::string end =
                std::string("[").append(w.at("code").get<std::string>()).append("]\n");
            EXPECT_NE(r.err.find(start), std::string::npos) << name << ":\n" << r.err;
            EXPECT_NE(r.err.find(end), std::string::npos) << r.err;
        }
    }
}

TEST(WarningsCli, SettingsStrictInTheSceneIsTheSameAsTheFlag) {
    json scene = json::parse(radiant::test::read_text(mistake("no-light.json")));
    scene["settings"] = {{"strict", true}};
    const fs::path file = scratch("strict.json");
    std::ofstream(file) << scene.dump();
    const CliRun r = run_cli("validate '" + file.string() + "'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find(": /luminaires: "), std::string::npos) << r.err;
    fs::remove(file);
}

TEST(WarningsCli, StrictSolveWritesNothing) {
    const fs::path out = scratch("strict-result.json");
    fs::remove(out);
    const CliRun r = run_cli("solve --strict '" + mistake("luminaire-in-desk.json") + "' --out '" +
                             out.string() + "'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_FALSE(fs::exists(out));
    EXPECT_NE(r.err.find(": /luminaires/1/position: luminaire \"L2\" is inside a closed solid"),
              std::string::npos)
        << r.err;
}

TEST(WarningsCli, SolvePrintsTheWarningsAndTheResultHoldsThem) {
    const fs::path out = scratch("result.json");
    const CliRun r = run_cli("solve '" + mistake("ceiling-wound-wrong.json") +
                             "' --tolerance 0.1 --out '" + out.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find(": /surfaces/5: "), std::string::npos) << r.err;
    const json result = json::parse(radiant::test::read_text(out));
    ASSERT_EQ(result["warnings"].size(), 1u) << result["warnings"];
    EXPECT_EQ(result["warnings"][0]["code"], "back_face_light");
    fs::remove(out);
}

TEST(WarningsCli, ACleanSceneIsCleanEvenWhenStrict) {
    const std::string file = std::string(RADIANT_SOURCE_DIR) + "/proto/examples/office.json";
    const CliRun r = run_cli("validate --strict '" + file + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

}  // namespace
