// Runs the built `radiant` binary (cmake --build builds it with the tests) and captures what it
// printed, for tests of the command line.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "test_files.h"

namespace radiant::test {

struct CliRun {
    int exit_code;
    std::string out, err;
};

inline CliRun run_cli(const std::string& args) {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("radiant_cli_test_" + std::to_string(getpid()));
    fs::create_directories(dir);
    // Built with append: GCC 12 reports a false -Wrestrict on long operator+ chains.
    std::string command = RADIANT_BIN_DIR;
    command.append("/radiant ").append(args);
    command.append(" > '").append((dir / "out").string()).append("'");
    command.append(" 2> '").append((dir / "err").string()).append("'");
    const int status = std::system(command.c_str());
    CliRun r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(dir / "out"),
             read_text(dir / "err")};
    fs::remove_all(dir);
    return r;
}

}  // namespace radiant::test
