// radiant-queue-bench against a PostgreSQL of its own: a short run (the 2,000-job table is in
// tests/bench/results/queue-claims.md) claims every job once across three replicas and prints
// its rates, and the bench refuses a database that already holds jobs.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "postgres_fixture.h"
#include "test_files.h"

namespace {

namespace fs = std::filesystem;
using radiant::test::shared_postgres;

class QueueBenchTest : public radiant::test::PostgresFixture {
protected:
    struct Run {
        int code = -1;
        std::string out;
    };
    Run bench(const std::string& args) const {
        const fs::path out = fs::temp_directory_path() / (database_ + ".out");
        const std::string command =
            std::string(RADIANT_BIN_DIR) + "/radiant-queue-bench --store '" +
            shared_postgres().url(database_) + "' " + args + " > '" + out.string() + "' 2>&1";
        const int status = std::system(command.c_str());
        Run run{WIFEXITED(status) ? WEXITSTATUS(status) : -1, radiant::test::read_text(out)};
        fs::remove(out);
        return run;
    }
};

TEST_F(QueueBenchTest, ThreeReplicasClaimEveryJobOnceAndTheRatesArePrinted) {
    const Run run = bench("--jobs 90 --replicas 3");
    ASSERT_EQ(run.code, 0) << run.out;
    EXPECT_NE(run.out.find("| claims/s | claim p50 ms | claim p99 ms |"), std::string::npos)
        << run.out;
    // jobs, replicas and workers, then the numbers; no job claimed twice, none left, 90 results.
    EXPECT_NE(run.out.find("| 90 | 3 | 1 | "), std::string::npos) << run.out;
    EXPECT_NE(run.out.find(" | 0 | 0 | 0 | 90 |"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("every job was claimed once"), std::string::npos) << run.out;
    EXPECT_EQ(
        shared_postgres().query_row(database_, "SELECT COUNT(*) FROM jobs WHERE attempts = 1"),
        std::vector<std::string>{"90"});

    const Run again = bench("--jobs 5");
    EXPECT_EQ(again.code, 2) << again.out;
    EXPECT_NE(again.out.find("holds jobs already"), std::string::npos) << again.out;
}

}  // namespace
