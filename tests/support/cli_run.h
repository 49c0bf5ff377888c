// Runs the built `radiant` binary (cmake --build builds it with the tests) and captures what it
// printed and its peak resident memory, for tests of the command line.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "test_files.h"

namespace radiant::test {

struct CliRun {
    int exit_code;
    std::string out, err;
    double peak_mib = 0;  ///< the process's peak resident set, as the kernel counted it
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
    // Forked and waited for here, not by std::system, so that wait4 gives this run's peak.
    const pid_t pid = fork();
    if (pid == 0) {
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    CliRun r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(dir / "out"),
             read_text(dir / "err"), static_cast<double>(usage.ru_maxrss) / 1024};  // KiB
    fs::remove_all(dir);
    return r;
}

}  // namespace radiant::test
