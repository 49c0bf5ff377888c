// Runs the built `radiant` binary (cmake --build builds it with the tests) and checks the
// contract's exit codes and problem lines.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>

#include "cli_run.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;

using radiant::test::CliRun;

CliRun run(const std::string& args) { return radiant::test::run_cli(args); }

std::string data(const std::string& relative) {
    return std::string(RADIANT_TEST_DATA) + "/" + relative;
}

TEST(Cli, ValidateGoodFile) {
    const std::string file = std::string(RADIANT_SOURCE_DIR) + "/proto/examples/simple-room.json";
    const CliRun r = run("validate '" + file + "'");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, file + ": ok\n");
    EXPECT_EQ(r.err, "");
}

TEST(Cli, ValidateBadFileListsProblems) {
    const std::string file = data("bad/unknown-material.json");
    const CliRun r = run("validate '" + file + "'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, file + ": /surfaces/0/material: unknown material \"foo\"\n");
}

TEST(Cli, EveryProblemLineHasTheContractShape) {
    const std::regex shape(R"(^.+\.json: (/[^ ]*)?: \S.*$)");
    for (const auto& file : radiant::test::json_files(data("bad"))) {
        const CliRun r = run("validate '" + file.string() + "'");
        EXPECT_EQ(r.exit_code, 2) << file;
        std::istringstream lines(r.err);
        std::string line;
        int count = 0;
        while (std::getline(lines, line)) {
            ++count;
            EXPECT_TRUE(std::regex_match(line, shape)) << line;
            EXPECT_EQ(line.rfind(file.string() + ": ", 0), 0u) << line;
        }
        EXPECT_GE(count, 1) << file;
    }
}

TEST(Cli, SolveBadFileWritesNothing) {
    const fs::path out =
        fs::temp_directory_path() / ("radiant_cli_out_" + std::to_string(getpid()) + ".json");
    fs::remove(out);
    const CliRun r =
        run("solve '" + data("bad/reflectance-one.json") + "' --out '" + out.string() + "'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_FALSE(fs::exists(out));
    EXPECT_NE(r.err.find("/materials/wall/reflectance: "), std::string::npos) << r.err;
}

TEST(Cli, SolveRefusesBadFlags) {
    const std::string solve = "solve '" + data("good/minimal.json") + "' ";
    for (const char* flags :
         {"--tolerance 1.5", "--threads -1", "--method magic", "--max-memory-mb 0"}) {
        EXPECT_EQ(run(solve + flags).exit_code, 2) << flags;
    }
}

TEST(Cli, SolveWritesAResultDocument) {
    const CliRun r = run("solve '" + data("good/minimal.json") + "' --tolerance 0.1");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("\"format\": \"radiant-result/1\""), std::string::npos) << r.out;
}

// --progress prints every snapshot as a line; the last is the result's, with its sensors.
TEST(Cli, ProgressPrintsEverySnapshot) {
    const CliRun r = run("solve '" + data("good/all-features.json") +
                         "' --tolerance 0.1 --max-memory-mb 64 --progress");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto final_line = r.err.rfind("snapshot ");
    ASSERT_NE(final_line, std::string::npos) << r.err;
    const std::string last = r.err.substr(final_line);
    EXPECT_NE(last.find("(final)"), std::string::npos) << last;
    EXPECT_NE(last.find("workplane: "), std::string::npos) << last;
    EXPECT_NE(last.find(" lx (min "), std::string::npos) << last;
    EXPECT_EQ(r.err.find('\r'), std::string::npos) << "lines, not a rewritten progress line";
}

/// The exit code of `radiant ARGS` run by the shell as it is written (its own redirections).
int shell_exit_code(const std::string& args) {
    const int status = std::system((std::string(RADIANT_BIN_DIR) + "/radiant " + args).c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(Cli, SolveRefusesAnOutputThatIsNoRegularFile) {
    // A pipe stands for /dev/full: renaming the result over it replaced the device with a file.
    const fs::path fifo =
        fs::temp_directory_path() / ("radiant_cli_fifo_" + std::to_string(getpid()));
    fs::remove(fifo);
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    const CliRun r = run("solve '" + data("good/minimal.json") + "' --tolerance 0.1 --out '" +
                         fifo.string() + "'");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("is not a regular file"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_fifo(fifo)) << "left as it was";
    fs::remove(fifo);
}

TEST(Cli, AWriteErrorOnStdoutExitsNonZero) {
    const std::string solve = "solve '" + data("good/minimal.json") + "' --tolerance 0.1";
    EXPECT_EQ(shell_exit_code(solve + " > /dev/full 2> /dev/null"), 1);
    EXPECT_EQ(shell_exit_code(solve + " > /dev/null 2> /dev/null"), 0);
}

TEST(Cli, SubmitReadsNoMoreThanTheServiceTakes) {
    // Refused before any connection: no service is needed, and /dev/zero never ends.
    const CliRun r = run("submit /dev/zero --server http://127.0.0.1:9");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("over the limit of 67108864 bytes"), std::string::npos) << r.err;
}

}  // namespace
