// docker/compose.yaml, docker/nginx.conf and docker/k8s/ against radiantd, without Docker or a
// cluster (tests/support/deployment_check.py): the flags, variables, probes, Secret and Service
// they use exist and agree, and the probe paths answer on a running radiantd. A copy with a
// mistake in each kind of reference must fail the same check.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "daemon.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;

struct Check {
    int code = -1;
    std::string out;
};

class DeploymentFilesTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("radiant_deployment_test_" + std::to_string(getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        daemon_ = std::make_unique<radiant::test::Daemon>(dir_ / "data", std::vector<std::string>{},
                                                          dir_ / "radiantd.log");
    }
    void TearDown() override {
        daemon_.reset();
        fs::remove_all(dir_);
    }

    Check check(const fs::path& docker) const {
        const fs::path out = dir_ / "check.out";
        const std::string command =
            "python3 '" RADIANT_SOURCE_DIR
            "/tests/support/deployment_check.py' --radiantd '" RADIANT_BIN_DIR
            "/radiantd' --docker '" +
            docker.string() + "' --port " + std::to_string(daemon_->port()) + " > '" +
            out.string() + "' 2>&1";
        const int status = std::system(command.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, radiant::test::read_text(out)};
    }

    /// Replaces `from` with `to` once in `file`; fails the test when `from` is not there.
    static void replace(const fs::path& file, const std::string& from, const std::string& to) {
        std::string text = radiant::test::read_text(file);
        const std::size_t at = text.find(from);
        ASSERT_NE(at, std::string::npos) << from << " not in " << file;
        text.replace(at, from.size(), to);
        std::ofstream(file) << text;
    }

    fs::path dir_;
    std::unique_ptr<radiant::test::Daemon> daemon_;
};

TEST_F(DeploymentFilesTest, ComposeAndKubernetesFilesAgreeWithRadiantd) {
    const Check ok = check(fs::path(RADIANT_SOURCE_DIR) / "docker");
    EXPECT_EQ(ok.code, 0) << ok.out;
    EXPECT_NE(ok.out.find("'/readyz'"), std::string::npos) << ok.out;
    EXPECT_NE(ok.out.find("'/healthz'"), std::string::npos) << ok.out;
}

TEST_F(DeploymentFilesTest, AMistakeInAnyReferenceFailsTheCheck) {
    const fs::path copy = dir_ / "docker";
    fs::copy(fs::path(RADIANT_SOURCE_DIR) / "docker", copy, fs::copy_options::recursive);
    replace(copy / "k8s" / "deployment.yaml", "\"--lease-seconds\"", "\"--lease-secs\"");
    replace(copy / "k8s" / "deployment.yaml", "path: /readyz", "path: /ready");
    replace(copy / "k8s" / "deployment.yaml", "key: RADIANT_STORE", "key: STORE");
    replace(copy / "compose.yaml", "RADIANT_REPLICA: radiant-2", "RADIANT_REPLICAS: radiant-2");
    replace(copy / "nginx.conf", "server radiant-3:8080", "server radiant-4:8080");
    replace(copy / "k8s" / "deployment.yaml", "terminationGracePeriodSeconds: 30",
            "terminationGracePeriodSeconds: 15");
    const Check bad = check(copy);
    EXPECT_EQ(bad.code, 1) << bad.out;
    for (const char* problem :
         {"radiantd has no flag --lease-secs", "the readinessProbe asks /ready, not /readyz",
          "RADIANT_STORE comes from no key of a Secret", "reads no variable RADIANT_REPLICAS",
          "distinct RADIANT_REPLICA names", "nginx.conf sends to", "answers 404 to GET /ready",
          "waits 15 s after SIGTERM, radiantd drains for 20.0 s"}) {
        EXPECT_NE(bad.out.find(problem), std::string::npos) << problem << "\n" << bad.out;
    }
}

}  // namespace
