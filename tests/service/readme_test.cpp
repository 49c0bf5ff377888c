// Runs the README's curl session against a live radiantd, so the documented example keeps working.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "daemon.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;

/// The first ```sh block after the <!-- service-session --> marker.
std::string readme_session() {
    const std::string readme = radiant::test::read_text(fs::path(RADIANT_SOURCE_DIR) / "README.md");
    const std::size_t marker = readme.find("<!-- service-session -->");
    if (marker == std::string::npos) return {};
    const std::size_t start = readme.find("```sh\n", marker);
    const std::size_t end = readme.find("```\n", start + 6);
    if (start == std::string::npos || end == std::string::npos) return {};
    return readme.substr(start + 6, end - start - 6);
}

TEST(Readme, CurlSessionWorksAsWritten) {
    if (std::system("command -v curl > /dev/null && command -v jq > /dev/null") != 0) {
        GTEST_SKIP() << "curl or jq missing (scripts/deps installs them)";
    }
    const std::string session = readme_session();
    ASSERT_FALSE(session.empty());
    const fs::path dir =
        fs::temp_directory_path() / ("radiant_readme_test_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "session.sh") << session;

    radiant::test::Daemon d(dir / "data", {}, dir / "radiantd.log");
    std::string command = "cd '" RADIANT_SOURCE_DIR "' && RADIANT_SERVER=http://127.0.0.1:" +
                          std::to_string(d.port()) + " bash -eo pipefail '" +
                          (dir / "session.sh").string() + "' > '" + (dir / "out").string() +
                          "' 2>&1";
    const int status = std::system(command.c_str());
    const std::string out = radiant::test::read_text(dir / "out");
    EXPECT_EQ(status, 0) << out;
    EXPECT_NE(out.find("event: done"), std::string::npos) << out;
    EXPECT_NE(out.find("{\"name\":\""), std::string::npos) << out;  // the sensors
    EXPECT_NE(out.find("\"code\":\"invalid_scene\""), std::string::npos) << out;
    fs::remove_all(dir);
}

}  // namespace
