// Runs every ```sh block of README.md and docs/*.md as written, against a live radiantd, so the
// documented commands keep working; the `<!-- check: CMD -->` lines after a block hold the
// numbers the text quotes to what the commands produce. Also: commands appear only in ```sh
// blocks, and every relative link points at a file (and heading) in the repository.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "daemon.h"
#include "markdown_doc.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;
using radiant::test::MarkdownDoc;
using radiant::test::parse_markdown;

const fs::path kSource = RADIANT_SOURCE_DIR;

MarkdownDoc read_doc(const std::string& name) {
    return parse_markdown(radiant::test::read_text(kSource / name));
}

/// Runs `script` with bash -eo pipefail in `dir`, its output into `out`; the exit code.
int run_script(const fs::path& dir, const fs::path& script, const fs::path& out,
               const std::string& env) {
    const std::string command = "cd '" + dir.string() + "' && " + env + " bash -eo pipefail '" +
                                script.string() + "' > '" + out.string() + "' 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// A scratch copy of the repository as a reader's checkout looks: every top-level entry of the
/// source tree linked in, build/bin the binaries under test; what the commands write stays here.
fs::path scratch_checkout(const fs::path& dir) {
    const fs::path repo = dir / "repo";
    fs::create_directories(repo / "build");
    for (const auto& entry : fs::directory_iterator(kSource)) {
        const std::string name = entry.path().filename().string();
        if (name == ".git" || name == "data" || name.rfind("build", 0) == 0) continue;
        fs::create_directory_symlink(entry.path(), repo / name);
    }
    fs::create_directory_symlink(RADIANT_BIN_DIR, repo / "build" / "bin");
    return repo;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = info.param;
    for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    }
    return name;
}

class DocCommands : public ::testing::TestWithParam<std::string> {};

TEST_P(DocCommands, RunAsWritten) {
    const std::string name = GetParam();
    const MarkdownDoc doc = read_doc(name);
    if (doc.blocks.empty()) return;  // nothing to run
    if (std::system("command -v curl > /dev/null && command -v jq > /dev/null") != 0) {
        GTEST_SKIP() << "curl or jq missing (scripts/deps installs them)";
    }
    const fs::path dir = fs::temp_directory_path() /
                         ("radiant_docs_" + test_name({name, 0}) + "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path repo = scratch_checkout(dir);
    radiant::test::Daemon d(dir / "data", {}, dir / "radiantd.log");
    const std::string server = "RADIANT_SERVER=http://127.0.0.1:" + std::to_string(d.port());

    bool all_ok = true;
    for (std::size_t i = 0; i < doc.blocks.size() && all_ok; ++i) {
        const auto& block = doc.blocks[i];
        const std::string where = name + ":" + std::to_string(block.line);
        const fs::path script = dir / ("block" + std::to_string(i) + ".sh");
        const fs::path out = dir / ("block" + std::to_string(i) + ".out");
        std::ofstream(script) << block.code;
        const int code = run_script(repo, script, out, server);
        const std::string output = radiant::test::read_text(out);
        EXPECT_EQ(code, 0) << where << ": the block failed\n"
                           << block.code << "--- its output:\n"
                           << output;
        all_ok = code == 0;  // later blocks may use what this one writes
        for (std::size_t k = 0; k < block.checks.size() && all_ok; ++k) {
            const fs::path check = dir / ("check" + std::to_string(i) + "_" + std::to_string(k));
            std::ofstream(check.string() + ".sh") << block.checks[k] << "\n";
            const int check_code = run_script(repo, check.string() + ".sh", check.string() + ".out",
                                              server + " BLOCK_OUTPUT='" + out.string() + "'");
            EXPECT_EQ(check_code, 0)
                << where << ": check failed: " << block.checks[k] << "\n"
                << radiant::test::read_text(check.string() + ".out") << "--- the block's output:\n"
                << output;
            all_ok = check_code == 0;
        }
    }
    if (all_ok) fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Docs, DocCommands,
                         ::testing::ValuesIn(radiant::test::project_documents(kSource)), test_name);

TEST(DocRules, OnlyShBlocksHoldCommands) {
    for (const std::string& name : radiant::test::project_documents(kSource)) {
        for (const std::string& problem : read_doc(name).problems) {
            ADD_FAILURE() << name << ": " << problem;
        }
    }
}

TEST(DocRules, TheReadmeShowsTheFirstExampleAndTheService) {
    const MarkdownDoc readme = read_doc("README.md");
    std::string all;
    std::size_t checks = 0;
    for (const auto& block : readme.blocks) {
        all += block.code;
        checks += block.checks.size();
    }
    EXPECT_NE(all.find("build/bin/radiant solve proto/examples/simple-room.json"),
              std::string::npos);
    EXPECT_NE(all.find("build/bin/radiant submit"), std::string::npos);
    EXPECT_GE(checks, 1u) << "the first example's numbers must be checked";
}

TEST(DocRules, LinksPointIntoTheRepository) {
    for (const std::string& name : radiant::test::project_documents(kSource)) {
        const MarkdownDoc doc = read_doc(name);
        const fs::path base = (kSource / name).parent_path();
        for (const auto& link : doc.links) {
            const std::string where = name + ":" + std::to_string(link.line) + ": " + link.target;
            if (link.target.rfind("http://", 0) == 0 || link.target.rfind("https://", 0) == 0) {
                continue;
            }
            const std::size_t hash = link.target.find('#');
            const std::string path = link.target.substr(0, hash);
            const std::string anchor =
                hash == std::string::npos ? "" : link.target.substr(hash + 1);
            ASSERT_FALSE(!path.empty() && path[0] == '/') << where << ": absolute path";
            const fs::path target = path.empty() ? kSource / name : base / path;
            const std::string in_repo =
                fs::weakly_canonical(target).lexically_relative(kSource).generic_string();
            EXPECT_TRUE(in_repo.rfind("..", 0) != 0) << where << ": outside the repository";
            EXPECT_TRUE(fs::exists(target)) << where << ": no such file";
            if (!anchor.empty() && target.extension() == ".md" && fs::exists(target)) {
                const MarkdownDoc linked = parse_markdown(radiant::test::read_text(target));
                EXPECT_EQ(linked.anchors.count(anchor), 1u) << where << ": no such heading";
            }
        }
    }
}

TEST(MarkdownDoc, ReadsBlocksChecksLinksAndProblems) {
    const MarkdownDoc doc = parse_markdown(
        "# A Title, with `code`\n"
        "See [the format](docs/scene-format.md#units) and `[not](a-link)`.\n"
        "```sh\n"
        "echo hi\n"
        "```\n"
        "<!-- check: grep -q hi \"$BLOCK_OUTPUT\" -->\n"
        "```json\n"
        "{}\n"
        "```\n"
        "\n"
        "    build/bin/radiant solve x.json\n"
        "```bash\n"
        "```\n");
    ASSERT_EQ(doc.blocks.size(), 1u);
    EXPECT_EQ(doc.blocks[0].line, 3);
    EXPECT_EQ(doc.blocks[0].code, "echo hi\n");
    ASSERT_EQ(doc.blocks[0].checks.size(), 1u);
    EXPECT_EQ(doc.blocks[0].checks[0], "grep -q hi \"$BLOCK_OUTPUT\"");
    ASSERT_EQ(doc.links.size(), 1u);
    EXPECT_EQ(doc.links[0].target, "docs/scene-format.md#units");
    EXPECT_EQ(doc.anchors.count("a-title-with-code"), 1u);
    EXPECT_EQ(doc.problems.size(), 2u);  // the indented command and the bash fence
}

}  // namespace
