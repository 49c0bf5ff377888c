// radiant-load against a live radiantd: a short run answers every status poll, and the tool
// refuses to load anything but a loopback address.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "daemon.h"
#include "service_scenes.h"
#include "store_under_test.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;

struct LoadRun {
    int code = -1;
    std::string out;
};

LoadRun load(const std::string& args, const fs::path& dir) {
    const std::string command = std::string(RADIANT_BIN_DIR) + "/radiant-load " + args + " > '" +
                                (dir / "load.out").string() + "' 2>&1";
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1,
            radiant::test::read_text(dir / "load.out")};
}

using LoadTest = radiant::test::StoreTest;
INSTANTIATE_TEST_SUITE_P(Stores, LoadTest, radiant::test::both_stores(), radiant::test::store_name);

TEST_P(LoadTest, ShortRunAnswersEveryPollWhileSolvesRun) {
    const fs::path dir =
        fs::temp_directory_path() / ("radiant_load_test_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    { std::ofstream(dir / "room.json") << radiant::test::tiny_room(); }
    radiant::test::Daemon d(dir / "data", flags(), dir / "radiantd.log");
    const std::string server = "http://127.0.0.1:" + std::to_string(d.port());

    const LoadRun run = load("--server " + server + " --scene '" + (dir / "room.json").string() +
                                 "' --rate 100 --seconds 2 --solves 2 --tolerance 0.001",
                             dir);
    EXPECT_EQ(run.code, 0) << run.out;
    EXPECT_NE(run.out.find("requests 200  errors 0  "), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("p99 "), std::string::npos) << run.out;

    const LoadRun remote = load(
        "--server http://192.0.2.1:8080 --scene '" + (dir / "room.json").string() + "' --seconds 1",
        dir);
    EXPECT_EQ(remote.code, 2) << remote.out;
    EXPECT_NE(remote.out.find("loopback"), std::string::npos) << remote.out;
    fs::remove_all(dir);
}

}  // namespace
