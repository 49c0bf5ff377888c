// The JSON Schema and the C++ parser must agree: on every good file, and on which bad files the
// schema alone can reject (tests/data/bad/expected.json says so per file).
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

#include "radiant/proto/scene_json.h"
#include "test_files.h"

namespace radiant::proto {
namespace {

namespace fs = std::filesystem;

/// File → whether python3-jsonschema finds it valid against the scene schema.
std::map<std::string, bool> schema_verdicts(const std::vector<fs::path>& files) {
    std::string command = std::string("python3 ") + RADIANT_SOURCE_DIR +
                          "/tests/support/schema_check.py " + RADIANT_SOURCE_DIR +
                          "/proto/schema/scene.schema.json";
    for (const auto& f : files) command += " '" + f.string() + "'";
    std::map<std::string, bool> verdicts;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return verdicts;
    char line[4096];
    while (std::fgets(line, sizeof line, pipe)) {
        std::string text(line);
        const std::size_t colon = text.rfind(": ");
        if (colon == std::string::npos) continue;
        verdicts[text.substr(0, colon)] = text.compare(colon + 2, 5, "valid") == 0;
    }
    EXPECT_EQ(pclose(pipe), 0) << command;
    return verdicts;
}

TEST(SchemaAgreement, GoodFilesAreValidForBoth) {
    const auto files = test::good_scenes();
    ASSERT_GE(files.size(), 5u);
    const auto verdicts = schema_verdicts(files);
    for (const auto& f : files) {
        EXPECT_TRUE(verdicts.contains(f.string()) && verdicts.at(f.string())) << f;
        const ParseOutcome outcome = load_scene_file(f);
        EXPECT_TRUE(outcome.ok()) << format_problem(f.string(),
                                                    outcome.ok() ? Problem{} : outcome.problems[0]);
    }
}

TEST(SchemaAgreement, BadFilesAreRefusedWithTheExpectedPointer) {
    const fs::path dir = fs::path(RADIANT_TEST_DATA) / "bad";
    const auto expected = nlohmann::json::parse(test::read_text(dir / "expected.json"));
    const auto files = test::json_files(dir);
    ASSERT_GE(files.size(), 20u);
    ASSERT_EQ(files.size(), expected.size()) << "every bad file needs an expectation";
    const auto verdicts = schema_verdicts(files);
    for (const auto& f : files) {
        SCOPED_TRACE(f.string());
        const auto& want = expected.at(f.filename().string());
        const ParseOutcome outcome = load_scene_file(f);
        ASSERT_FALSE(outcome.ok());
        bool found = false;
        for (const Problem& p : outcome.problems) found = found || p.pointer == want["pointer"];
        EXPECT_TRUE(found) << "expected " << want["pointer"] << ", got "
                           << format_problem(f.string(), outcome.problems[0]);
        ASSERT_TRUE(verdicts.contains(f.string()));
        // schema:true → the schema rejects it; schema:false → only the C++ checks can.
        EXPECT_EQ(verdicts.at(f.string()), !want["schema"].get<bool>());
    }
}

}  // namespace
}  // namespace radiant::proto
