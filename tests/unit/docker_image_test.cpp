// docker/Dockerfile where no Docker engine runs (CI): its steps are the repository's own scripts,
// the runtime stage installs exactly the packages that the built programs link, and what
// scripts/install puts in a prefix starts the way the image starts it and passes its health
// check.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "test_files.h"

namespace {

namespace fs = std::filesystem;

const fs::path kSource = RADIANT_SOURCE_DIR;

/// `path` in single quotes, for a shell command. (Built by appending: GCC 12 reports a false
/// -Wrestrict on "literal" + std::string.)
std::string shell_quoted(const fs::path& path) {
    std::string out(1, '\'');
    out.append(path.string()).push_back('\'');
    return out;
}

struct Shell {
    int status = -1;
    std::string out;
};

/// Runs `command` with bash; its stdout, and its exit status.
Shell shell(const std::string& command) {
    const fs::path script =
        fs::temp_directory_path() / ("radiant_docker_test_" + std::to_string(getpid()) + ".sh");
    std::ofstream(script) << command;
    Shell r;
    FILE* pipe = popen(("bash " + shell_quoted(script) + " 2>&1").c_str(), "r");
    char buffer[4096];
    while (pipe && std::fgets(buffer, sizeof buffer, pipe)) r.out += buffer;
    const int status = pipe ? pclose(pipe) : -1;
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    fs::remove(script);
    return r;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty()) out.push_back(line);
    }
    return out;
}

/// The Dockerfile's stages by name ("build", "runtime"), continuation lines joined.
std::map<std::string, std::string> stages() {
    const std::string text = radiant::test::read_text(kSource / "docker/Dockerfile");
    std::map<std::string, std::string> out;
    std::string name;
    const std::regex from(R"(^FROM\s+\S+\s+AS\s+(\S+))");
    for (const std::string& line : lines(std::regex_replace(text, std::regex(R"(\\\n)"), " "))) {
        std::smatch m;
        if (std::regex_search(line, m, from)) name = m[1];
        if (!name.empty() && line[0] != '#') out[name] += line + "\n";
    }
    return out;
}

TEST(DockerImage, ItsStepsAreTheRepositorysScripts) {
    const auto s = stages();
    ASSERT_TRUE(s.contains("build") && s.contains("runtime"));
    const std::string& build = s.at("build");
    const std::string& runtime = s.at("runtime");
    EXPECT_NE(build.find("FROM debian:12 "), std::string::npos) << build;
    // Only scripts that CI runs: deps (scripts/build runs it) and install (the test below).
    std::smatch run;
    std::vector<std::string> runs;
    for (std::string rest = build; std::regex_search(rest, run, std::regex(R"(\nRUN ([^\n]*))"));
         rest = run.suffix()) {
        runs.push_back(run[1]);
    }
    EXPECT_EQ(runs, (std::vector<std::string>{"scripts/deps && rm -rf /var/lib/apt/lists/*",
                                              "scripts/install /opt/radiant"}))
        << build;
    EXPECT_NE(runtime.find("FROM debian:12-slim "), std::string::npos) << runtime;
    EXPECT_NE(runtime.find("RUN /tmp/radiant-scripts/runtime-deps"), std::string::npos);
    EXPECT_NE(runtime.find("COPY --from=build /opt/radiant /opt/radiant"), std::string::npos);
    // Nothing of the build stage's toolchain in the runtime stage.
    for (const char* tool : {"scripts/deps", "scripts/build", "g++", "cmake", "-dev"}) {
        EXPECT_EQ(runtime.find(tool), std::string::npos) << tool;
    }
    // A non-root user, the data volume where radiantd keeps its store, a health check.
    std::smatch user;
    ASSERT_TRUE(std::regex_search(runtime, user, std::regex(R"(\nUSER (\S+))")));
    EXPECT_NE(user[1], "root");
    EXPECT_NE(user[1], "0");
    EXPECT_NE(runtime.find("RADIANT_DATA=/var/lib/radiant/data"), std::string::npos);
    EXPECT_NE(runtime.find("VOLUME /var/lib/radiant/data"), std::string::npos);
    EXPECT_NE(runtime.find("HEALTHCHECK "), std::string::npos);
    // The README's Install table names the scripts the build stage runs.
    const std::string readme = radiant::test::read_text(kSource / "README.md");
    EXPECT_NE(readme.find("`scripts/deps`"), std::string::npos);
    EXPECT_NE(readme.find("`scripts/build`"), std::string::npos);
}

/// The shared libraries `binaries` name as NEEDED (objdump), where ldd finds them: apt brings
/// what those need in turn (libpq5's Kerberos and TLS, for instance).
std::set<std::string> linked_libraries(const std::vector<fs::path>& binaries) {
    std::set<std::string> libraries;
    const std::regex needed_entry(R"(^\s*NEEDED\s+(\S+))");
    const std::regex found(R"(^\s*(\S+)\s+=>\s*(/\S+)\s+\(0x)");
    for (const fs::path& binary : binaries) {
        const Shell objdump = shell(std::string("objdump -p ") + shell_quoted(binary));
        EXPECT_EQ(objdump.status, 0) << objdump.out;
        std::set<std::string> needed;
        for (const std::string& line : lines(objdump.out)) {
            std::smatch m;
            if (std::regex_search(line, m, needed_entry)) needed.insert(m[1]);
        }
        const Shell ldd = shell(std::string("ldd ") + shell_quoted(binary));
        EXPECT_EQ(ldd.status, 0) << ldd.out;
        for (const std::string& line : lines(ldd.out)) {
            std::smatch m;
            if (std::regex_search(line, m, found) && needed.contains(m[1])) libraries.insert(m[2]);
        }
    }
    return libraries;
}

/// The Debian packages owning `libraries` (dpkg -S, once for all of them).
std::set<std::string> owning_packages(const std::set<std::string>& libraries) {
    // Debian 12 merges /lib into /usr/lib: dpkg knows a file under one of its names.
    std::map<std::string, std::vector<std::string>> names;
    std::string command = "dpkg -S";
    for (const std::string& path : libraries) {
        names[path] = {path, fs::canonical(path).string(), "/usr" + path};
        for (const std::string& name : names[path]) command.append(" ").append(shell_quoted(name));
    }
    const Shell dpkg = shell(command.append(" 2>/dev/null"));
    std::map<std::string, std::string> owner;  // file → package
    const std::regex entry(R"(^([^:]+)(?::\w+)?: (/\S+)$)");
    for (const std::string& line : lines(dpkg.out)) {
        std::smatch m;
        if (std::regex_match(line, m, entry)) owner[m[2]] = m[1];
    }
    std::set<std::string> packages;
    for (const auto& [path, candidates] : names) {
        const auto found = std::find_if(candidates.begin(), candidates.end(),
                                        [&](const std::string& c) { return owner.contains(c); });
        EXPECT_NE(found, candidates.end()) << "no package owns " << path;
        if (found != candidates.end()) packages.insert(owner.at(*found));
    }
    return packages;
}

TEST(DockerImage, RuntimePackagesAreWhatTheProgramsLink) {
    const std::set<std::string> linked = owning_packages(linked_libraries(
        {fs::path(RADIANT_BIN_DIR) / "radiantd", fs::path(RADIANT_BIN_DIR) / "radiant"}));
    const Shell listed = shell(shell_quoted(kSource / "scripts/runtime-deps") + " --list");
    ASSERT_EQ(listed.status, 0) << listed.out;
    const std::vector<std::string> names = lines(listed.out);
    const std::set<std::string> runtime(names.begin(), names.end());
    EXPECT_EQ(runtime, linked);
    EXPECT_TRUE(linked.contains("libembree3-3") && linked.contains("libsqlite3-0"));
}

TEST(DockerImage, RuntimeScriptRuns) {
    // On a machine that built Radiant every runtime package is there: the script installs
    // nothing and succeeds, as in the image after apt-get.
    const Shell run = shell(shell_quoted(kSource / "scripts/runtime-deps"));
    EXPECT_EQ(run.status, 0) << run.out;
}

TEST(DockerImage, InstalledDaemonStartsAsTheImageStartsItAndIsHealthy) {
    // scripts/install builds build/ as CI does and installs it: here, on the tree CI just built
    // (so the build is a no-op), exactly the step of the image's build stage.
    if (fs::weakly_canonical(fs::path(RADIANT_BIN_DIR).parent_path()) !=
        fs::weakly_canonical(kSource / "build")) {
        GTEST_SKIP() << "scripts/install builds build/; this test binary is from "
                     << RADIANT_BIN_DIR;
    }
    const fs::path dir =
        fs::temp_directory_path() / ("radiant_docker_install_" + std::to_string(getpid()));
    fs::remove_all(dir);
    const fs::path prefix = dir / "opt";
    const Shell installed =
        shell(shell_quoted(kSource / "scripts/install") + " " + shell_quoted(prefix));
    ASSERT_EQ(installed.status, 0) << installed.out;
    for (const char* file :
         {"bin/radiantd", "bin/radiant", "share/radiant/openapi.yaml",
          "share/radiant/schema/result.schema.json", "share/radiant/examples/simple-room.json",
          "share/radiant/web/index.html"}) {
        EXPECT_TRUE(fs::exists(prefix / file)) << file;
    }
    // The image's HEALTHCHECK command, on the port this daemon got.
    std::smatch health;
    const std::string runtime = stages().at("runtime");
    ASSERT_TRUE(std::regex_search(runtime, health, std::regex(R"(HEALTHCHECK .*CMD (.*))")));
    const std::string check = std::regex_replace(health[1].str(), std::regex(":8080/"), ":$port/");
    // Started as the image starts it: no flags, RADIANT_LISTEN and RADIANT_DATA.
    std::string script = "PREFIX=";
    script.append(shell_quoted(prefix)).append("\nDIR=").append(shell_quoted(dir));
    script.append("\nhealth_check() { ").append(check).append("; }\n");
    script.append(R"sh(set -e
export PATH="$PREFIX/bin:$PATH" RADIANT_LISTEN=127.0.0.1:0 RADIANT_DATA="$DIR/data"
radiantd > "$DIR/out" 2> "$DIR/log" &
pid=$!
trap 'kill $pid; wait $pid || true' EXIT
for i in $(seq 100); do grep -q '^listening on' "$DIR/out" && break; sleep 0.1; done
port=$(sed -n 's/^listening on 127.0.0.1:\([0-9]*\)$/\1/p' "$DIR/out")
test -n "$port"
health_check
curl -fsS "http://127.0.0.1:$port/v1/openapi.yaml" | cmp - "$PREFIX/share/radiant/openapi.yaml"
curl -fsS "http://127.0.0.1:$port/" | cmp - "$PREFIX/share/radiant/web/index.html"
echo healthy
)sh");
    const Shell run = shell(script);
    EXPECT_EQ(run.status, 0) << run.out;
    EXPECT_NE(run.out.find("\"status\":\"ok\""), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("healthy"), std::string::npos) << run.out;
    // The script waited for the daemon to stop, so nothing is left writing in `dir`.
    std::error_code ignored;
    fs::remove_all(dir, ignored);
}

}  // namespace
