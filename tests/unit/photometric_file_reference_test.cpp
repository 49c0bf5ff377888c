// `ies_file` / `ldt_file`: photometric files next to the scene file read like inline text, and
// refused with the key's pointer when missing or when the scene was not read from a file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "photometric_files.h"
#include "radiant/proto/scene_json.h"

namespace radiant::proto {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

double downlight(double gamma, double) {
    return gamma <= 90 ? 800 * std::cos(gamma * std::numbers::pi / 180) : 0;
}

Json scene_with(const Json& distribution) {
    return {
        {"format", "radiant-scene/1"},
        {"surfaces",
         {{{"name", "floor"},
           {"polygon", {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}}},
           {"material", "m"}}}},
        {"materials", {{"m", {{"reflectance", 0.5}}}}},
        {"luminaires", {{{"name", "L"}, {"position", {2, 2, 2}}, {"distribution", distribution}}}}};
}

class PhotometricFileReference : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("radiant_ies_file_" + std::to_string(getpid()));
        fs::create_directories(dir_);
        ies_ = testing::ies_text(testing::angles(0, 90, 5), {0}, downlight);
        std::ofstream(dir_ / "down.ies") << ies_;
    }
    void TearDown() override { fs::remove_all(dir_); }

    ParseOutcome load(const Json& scene) {
        std::ofstream(dir_ / "scene.json") << scene.dump();
        return load_scene_file(dir_ / "scene.json");
    }

    fs::path dir_;
    std::string ies_;
};

TEST_F(PhotometricFileReference, ReadsTheFileLikeInlineText) {
    const ParseOutcome from_file = load(scene_with({{"ies_file", "down.ies"}}));
    ASSERT_TRUE(from_file.ok()) << from_file.problems[0].pointer << ": "
                                << from_file.problems[0].message;
    const ParseOutcome inline_text = parse_scene(scene_with({{"ies", ies_}}).dump());
    ASSERT_TRUE(inline_text.ok());
    const auto& a = from_file.scene->luminaires.at(0).photometry;
    const auto& b = inline_text.scene->luminaires.at(0).photometry;
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->candela, b->candela);
    EXPECT_EQ(a->gamma_deg, b->gamma_deg);
}

TEST_F(PhotometricFileReference, MissingFileIsRefusedAtItsKey) {
    const ParseOutcome outcome = load(scene_with({{"ldt_file", "nope.ldt"}}));
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "/luminaires/0/distribution/ldt_file");
    EXPECT_NE(outcome.problems[0].message.find("nope.ldt"), std::string::npos);
}

TEST_F(PhotometricFileReference, ADocumentWithoutAFileCannotReferToOne) {
    const ParseOutcome outcome = parse_scene(scene_with({{"ies_file", "down.ies"}}).dump());
    ASSERT_EQ(outcome.problems.size(), 1u);
    EXPECT_EQ(outcome.problems[0].pointer, "/luminaires/0/distribution/ies_file");
}

TEST_F(PhotometricFileReference, TwoSourcesAreRefused) {
    const ParseOutcome outcome = load(scene_with({{"ies_file", "down.ies"}, {"ies", ies_}}));
    ASSERT_FALSE(outcome.problems.empty());
    EXPECT_EQ(outcome.problems[0].pointer, "/luminaires/0/distribution");
}

}  // namespace
}  // namespace radiant::proto
