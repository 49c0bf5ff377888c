#include "radiance_run.h"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace radiant::radiance {
namespace {

namespace fs = std::filesystem;

std::string quoted(const std::string& s) {
    std::string out = "'";
    for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

bool executable(const fs::path& p) { return ::access(p.c_str(), X_OK) == 0; }

std::size_t line_count(const fs::path& file) {
    std::ifstream in(file);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) n += line.empty() ? 0 : 1;
    return n;
}

// Runs a shell command; returns its exit status, or -1 when it did not exit normally.
int shell(const std::string& command) {
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string in_dir(const fs::path& bin, const fs::path& dir) {
    // Built with append: GCC 12 reports a false -Wrestrict on long operator+ chains.
    std::string c = "cd ";
    c.append(quoted(dir.string())).append(" && RAYPATH=").append(quoted(raypath_for(bin)));
    return c.append(" ");
}

}  // namespace

std::optional<fs::path> find_radiance() {
    const char* path = std::getenv("PATH");
    if (!path) return std::nullopt;
    std::istringstream dirs(path);
    for (std::string d; std::getline(dirs, d, ':');) {
        if (d.empty()) continue;
        if (executable(fs::path(d) / "rtrace") && executable(fs::path(d) / "oconv")) {
            return fs::path(d);
        }
    }
    return std::nullopt;
}

std::string raypath_for(const fs::path& bin) {
    std::string path = ".";
    if (const char* set = std::getenv("RAYPATH"); set && *set) path = set;
    // The build's own lib goes last, so a RAYPATH that misses rayinit.cal still runs and files
    // of the user's own directories still come first.
    const fs::path lib = bin.parent_path() / "lib";
    if (fs::exists(lib / "rayinit.cal")) path.append(":").append(lib.string());
    return path;
}

std::string make_octree(const fs::path& bin, const fs::path& dir) {
    if (fs::exists(dir / "scene.oct")) return {};
    std::string command = in_dir(bin, dir);
    command.append(quoted((bin / "oconv").string())).append(" scene.rad > scene.oct 2> oconv.log");
    if (shell(command) != 0) {
        fs::remove(dir / "scene.oct");
        return "oconv failed in " + dir.string() + " (see oconv.log)";
    }
    return {};
}

RtraceRun run_rtrace(const fs::path& bin, const fs::path& dir, const std::string& settings,
                     const std::string& points) {
    RtraceRun run;
    std::string command = in_dir(bin, dir);
    command.append(quoted((bin / "rtrace").string()))
        .append(" -I -h ")
        .append(settings)
        .append(" scene.oct < ")
        .append(quoted(points))
        .append(" > rtrace.out 2> rtrace.log");
    const auto start = std::chrono::steady_clock::now();
    const int status = shell(command);
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (status != 0) {
        run.error = "rtrace " + settings + " failed in " + dir.string() + " (see rtrace.log)";
        return run;
    }
    std::ifstream out(dir / "rtrace.out");
    run.irradiance_lux = irradiance_from_rtrace(out);
    const std::size_t want = line_count(dir / points);
    if (run.irradiance_lux.size() != want) {
        run.error = "rtrace gave " + std::to_string(run.irradiance_lux.size()) + " values for " +
                    std::to_string(want) + " points";
        return run;
    }
    run.ok = true;
    return run;
}

}  // namespace radiant::radiance
