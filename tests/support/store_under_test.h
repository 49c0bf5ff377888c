// The job stores the service tests run on: every test that drives radiantd or its router runs
// once on SQLite (the default, under --data) and once on PostgreSQL (a fresh database of its own
// on the test binary's shared cluster, postgres_server.h), as Stores/Suite.Test/sqlite and
// Stores/Suite.Test/postgresql.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "postgres_server.h"
#include "radiant/server/postgres_job_store.h"
#include "radiant/server/sqlite_job_store.h"

namespace radiant::test {

/// The parameter values of a suite instantiated on both stores, and their names.
inline auto both_stores() { return ::testing::Values(std::string("sqlite"), "postgresql"); }
inline std::string store_name(const ::testing::TestParamInfo<std::string>& info) {
    return info.param;
}

/// The running test's name as one file name: a test run on each store is named Test/sqlite.
inline std::string test_file_name() {
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '_');
    return name;
}

/// One test's store: nothing to set up for SQLite, a new database for PostgreSQL.
class StoreUnderTest {
public:
    /// `kind` is "sqlite" or "postgresql"; PostgreSQL must be installed (see skip_reason).
    explicit StoreUnderTest(const std::string& kind) : postgresql_(kind == "postgresql") {
        if (!postgresql_) return;
        database_ = "service_" + std::to_string(::getpid()) + "_" + std::to_string(++count_);
        shared_postgres().create_database(database_);
    }

    /// Why a test on `kind` cannot run here, or empty.
    static std::string skip_reason(const std::string& kind) {
        return kind == "postgresql" ? postgres_missing() : std::string();
    }

    bool postgresql() const { return postgresql_; }
    const std::string& database() const { return database_; }

    /// `args` and radiantd's flags for this store, besides --data: --store on PostgreSQL, with the
    /// shortest lease, so that a test that kills a daemon sees its job taken up again within
    /// seconds.
    std::vector<std::string> daemon_flags(std::vector<std::string> args = {}) const {
        if (postgresql_) {
            args.insert(args.end(),
                        {"--store", shared_postgres().url(database_), "--lease-seconds", "2"});
        }
        return args;
    }

    /// The store itself, as radiantd opens it (SQLite in `sqlite_dir`).
    std::unique_ptr<server::JobStore> open(const std::filesystem::path& sqlite_dir) const {
        if (postgresql_) {
            return std::make_unique<server::PostgresJobStore>(shared_postgres().uri(database_));
        }
        return std::make_unique<server::SqliteJobStore>(sqlite_dir);
    }

private:
    static inline int count_ = 0;
    bool postgresql_;
    std::string database_;
};

/// A test run on each store: instantiate its suite with
/// INSTANTIATE_TEST_SUITE_P(Stores, Suite, both_stores(), store_name).
class StoreTest : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override {
        const std::string skip = StoreUnderTest::skip_reason(GetParam());
        if (!skip.empty()) GTEST_SKIP() << skip;
        store_.emplace(GetParam());
    }
    const StoreUnderTest& store() const { return *store_; }
    /// `args` and the flags that start radiantd on this test's store.
    std::vector<std::string> flags(std::vector<std::string> args = {}) const {
        return store_->daemon_flags(std::move(args));
    }

private:
    std::optional<StoreUnderTest> store_;
};

}  // namespace radiant::test
