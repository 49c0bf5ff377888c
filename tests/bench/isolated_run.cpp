#include "isolated_run.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>

namespace radiant::bench {
namespace {

bool write_all(int fd, const std::string& text) {
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

std::string read_all(int fd) {
    std::string text;
    char buf[65536];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        text.append(buf, static_cast<std::size_t>(n));
    }
    return text;
}

// The process's own high-water mark of resident memory (VmHWM), in KiB; 0 if unreadable.
// Reported next to the parent's ru_maxrss of the child: on a loaded machine the two were seen
// to disagree (a 7.4 GB child reported 0.8 GB by wait4), so the larger one is used.
long peak_resident_kib() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmHWM:", 0) == 0) return std::atol(line.c_str() + 6);
    }
    return 0;
}

[[noreturn]] void child(int fd, const std::function<nlohmann::json()>& work,
                        unsigned watchdog_seconds) {
    ::alarm(watchdog_seconds);
    nlohmann::json out;
    try {
        out = {{"value", work()}};
    } catch (const std::exception& e) {
        out = {{"error", e.what()}};
    }
    out["peak_kib"] = peak_resident_kib();
    // _exit: no static destructors or atexit handlers of the parent's state run twice.
    ::_exit(write_all(fd, out.dump()) ? 0 : 3);
}

}  // namespace

IsolatedOutcome run_isolated(const std::function<nlohmann::json()>& work,
                             unsigned watchdog_seconds) {
    IsolatedOutcome outcome;
    int fds[2];
    if (::pipe(fds) != 0) {
        outcome.failure = std::string("pipe: ") + std::strerror(errno);
        return outcome;
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
        outcome.failure = std::string("fork: ") + std::strerror(errno);
        ::close(fds[0]);
        ::close(fds[1]);
        return outcome;
    }
    if (pid == 0) {
        ::close(fds[0]);
        child(fds[1], work, watchdog_seconds);
    }
    ::close(fds[1]);
    const std::string text = read_all(fds[0]);
    ::close(fds[0]);
    int status = 0;
    rusage usage{};
    while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    outcome.peak_mib = static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
    if (WIFSIGNALED(status)) {
        const int sig = WTERMSIG(status);
        outcome.failure = sig == SIGALRM ? "killed by the watchdog"
                                         : std::string("killed by signal ") + strsignal(sig);
        return outcome;
    }
    const auto parsed = nlohmann::json::parse(text, nullptr, false);
    if (parsed.is_object() && parsed.contains("peak_kib")) {
        outcome.peak_mib = std::max(outcome.peak_mib, parsed.at("peak_kib").get<double>() / 1024.0);
    }
    if (parsed.is_discarded() || !parsed.is_object()) {
        outcome.failure =
            "the child exited with " + std::to_string(WEXITSTATUS(status)) + " and no result";
    } else if (parsed.contains("error")) {
        outcome.failure = parsed.at("error").get<std::string>();
    } else {
        outcome.value = parsed.at("value");
    }
    return outcome;
}

}  // namespace radiant::bench
