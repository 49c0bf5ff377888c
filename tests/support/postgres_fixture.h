// A test on a fresh PostgreSQL database of its own, on the binary's shared test cluster
// (postgres_server.h); skipped, saying why, where PostgreSQL is not installed.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

#include "postgres_server.h"

namespace radiant::test {

class PostgresFixture : public ::testing::Test {
protected:
    void SetUp() override {
        const std::string missing = postgres_missing();
        if (!missing.empty()) GTEST_SKIP() << missing;
        database_ = "test_" + std::to_string(getpid()) + "_" + std::to_string(++count_);
        shared_postgres().create_database(database_);
    }
    /// The libpq connection string of this test's database.
    std::string uri() const { return shared_postgres().uri(database_); }

    std::string database_;

private:
    static inline int count_ = 0;
};

}  // namespace radiant::test
