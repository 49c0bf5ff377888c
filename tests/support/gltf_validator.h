// Runs the Khronos glTF validator (npm gltf-validator, installed by scripts/deps into
// tools/node_modules) on a file and expects no errors.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace radiant::test {

/// Its report goes to the test log on failure.
inline void expect_valid_gltf(const std::filesystem::path& file) {
    if (std::system("command -v node >/dev/null 2>&1") != 0) {
        GTEST_SKIP() << "node is not installed (scripts/deps installs it): glTF not validated";
    }
    const std::string command = std::string("node '") + RADIANT_SOURCE_DIR +
                                "/tools/validate-gltf.mjs' '" + file.string() + "' 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string report;
    char line[1024];
    while (std::fgets(line, sizeof line, pipe)) report += line;
    const int status = pclose(pipe);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << report;
    EXPECT_NE(report.find(": 0 errors"), std::string::npos) << report;
}

}  // namespace radiant::test
