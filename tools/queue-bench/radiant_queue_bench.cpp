// radiant-queue-bench: is the shared queue a bottleneck? Inserts N trivial jobs into an empty
// PostgreSQL store, then R replicas (each its own connection, as each radiantd has one) with W
// workers each claim them (JobStore::claim: SELECT … FOR UPDATE SKIP LOCKED under a lease) and
// finish them with a tiny result, as fast as they can: no solve, so what is measured is the
// queue alone. Prints claims per second, claim latency percentiles, and, from the store's
// attempt counts, that no job was claimed twice. Exit 0 when every job ended done exactly once.
#include <libpq-fe.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "radiant/server/job_queue.h"
#include "radiant/server/postgres_job_store.h"

namespace {

using namespace radiant::server;
using Clock = std::chrono::steady_clock;

/// A job is held this long by a worker that stops renewing it; the bench never lets one expire.
constexpr std::chrono::seconds kLease{60};
constexpr int kMaxJobs = 100000;  ///< a bounded run: the bench inserts all of them first
constexpr int kMaxReplicas = 16;
constexpr int kMaxWorkers = 16;
/// Never solved: the bench measures the queue, not the engine.
constexpr const char* kScene = R"({"format": "radiant-scene/1", "name": "queue-bench"})";

struct Options {
    std::string store;
    int jobs = 2000;
    int replicas = 3;
    int workers = 1;
    std::string out;
};

/// One counted value of `sql` on `uri`; throws with the server's message.
long long count(const std::string& uri, const std::string& sql) {
    PGconn* conn = PQconnectdb(uri.c_str());
    PGresult* result = PQexec(conn, sql.c_str());
    const bool ok = PQresultStatus(result) == PGRES_TUPLES_OK && PQntuples(result) == 1;
    const std::string why = PQerrorMessage(conn);
    const long long value = ok ? std::stoll(PQgetvalue(result, 0, 0)) : -1;
    PQclear(result);
    PQfinish(conn);
    if (!ok) throw std::runtime_error(sql + ": " + why);
    return value;
}

double percentile(std::vector<double> sorted, double p) {
    if (sorted.empty()) return 0;
    const auto rank = static_cast<std::size_t>(p * static_cast<double>(sorted.size() - 1) + 0.5);
    return sorted[std::min(rank, sorted.size() - 1)];
}

struct WorkerLog {
    std::vector<double> claim_ms;
    std::vector<std::string> ids;
};

/// Claims and finishes jobs until none is waiting. Workers of one replica share its store (one
/// connection under its lock), as radiantd's do.
void work(JobStore& store, const std::string& owner, WorkerLog& log) {
    for (;;) {
        const auto start = Clock::now();
        const std::optional<JobRecord> job = store.claim(owner, kLease, kMaxJobAttempts);
        log.claim_ms.push_back(
            std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        if (!job) return;  // every job was inserted first: nothing waiting means all are taken
        log.ids.push_back(job->id);
        JobProgress progress;
        progress.fraction = 1;
        progress.sequence = job->progress.sequence + 1;
        store.finish(job->id, JobStatus::done, now_millis(), progress, "",
                     std::string(R"({"format": "radiant-result/1"})"));
    }
}

int run(const Options& o) {
    PostgresJobStore submitter(o.store);
    if (!submitter.count_by_status().empty()) {
        std::fprintf(stderr,
                     "radiant-queue-bench: the database holds jobs already; the bench would "
                     "claim them. Give it an empty database.\n");
        return 2;
    }
    const auto insert_start = Clock::now();
    for (int i = 0; i < o.jobs; ++i) {
        JobRecord job;
        job.id = new_job_id();
        job.scene_json = kScene;
        job.created = now_millis();
        submitter.insert(job);
    }
    const double insert_seconds =
        std::chrono::duration<double>(Clock::now() - insert_start).count();

    std::vector<std::unique_ptr<PostgresJobStore>> replicas;
    for (int r = 0; r < o.replicas; ++r) {
        replicas.push_back(std::make_unique<PostgresJobStore>(o.store));
    }
    std::vector<WorkerLog> logs(static_cast<std::size_t>(o.replicas * o.workers));
    const auto start = Clock::now();
    std::vector<std::thread> threads;
    for (int r = 0; r < o.replicas; ++r) {
        for (int w = 0; w < o.workers; ++w) {
            WorkerLog& log = logs[static_cast<std::size_t>(r * o.workers + w)];
            threads.emplace_back([&replicas, r, &log] {
                work(*replicas[static_cast<std::size_t>(r)], "bench-" + std::to_string(r), log);
            });
        }
    }
    for (std::thread& t : threads) t.join();
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();

    std::vector<double> latencies;
    std::multiset<std::string> claimed;
    for (const WorkerLog& log : logs) {
        latencies.insert(latencies.end(), log.claim_ms.begin(), log.claim_ms.end());
        claimed.insert(log.ids.begin(), log.ids.end());
    }
    std::sort(latencies.begin(), latencies.end());
    std::size_t seen_twice = 0;
    for (auto it = claimed.begin(); it != claimed.end(); it = claimed.upper_bound(*it)) {
        if (claimed.count(*it) > 1) ++seen_twice;
    }
    // The store's own account: every job started exactly once, and ended done with one result.
    const long long twice = count(o.store, "SELECT COUNT(*) FROM jobs WHERE attempts > 1");
    const long long unclaimed = count(o.store, "SELECT COUNT(*) FROM jobs WHERE attempts = 0");
    const long long not_done = count(o.store, "SELECT COUNT(*) FROM jobs WHERE status <> 'done'");
    const long long results = count(o.store, "SELECT COUNT(*) FROM results");

    char row[512];
    std::snprintf(row, sizeof row,
                  "| %d | %d | %d | %.0f | %.2f | %.0f | %.2f | %.2f | %.2f | %lld | %zu | %lld "
                  "| %lld |\n",
                  o.jobs, o.replicas, o.workers, o.jobs / insert_seconds, seconds,
                  static_cast<double>(claimed.size()) / seconds, percentile(latencies, 0.5),
                  percentile(latencies, 0.99), latencies.empty() ? 0.0 : latencies.back(), twice,
                  seen_twice, unclaimed + not_done, results);
    const std::string table =
        "| jobs | replicas | workers each | inserts/s | seconds | claims/s | claim p50 ms | "
        "claim p99 ms | claim max ms | claimed twice (store attempts) | claimed twice (seen) | "
        "not done | results |\n"
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n" +
        std::string(row);
    std::fputs(table.c_str(), stdout);
    if (!o.out.empty()) std::ofstream(o.out) << table;
    const bool exactly_once =
        twice == 0 && seen_twice == 0 && unclaimed == 0 && not_done == 0 && results == o.jobs;
    std::printf("%s\n", exactly_once ? "every job was claimed once and ended done"
                                     : "FAILED: a job was claimed twice, or not at all");
    return exactly_once ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"radiant-queue-bench: claim rate and latency of the shared PostgreSQL queue"};
    app.add_option("--store", o.store, "postgresql://… of an EMPTY database (jobs are inserted)")
        ->required();
    app.add_option("--jobs", o.jobs, "trivial jobs to insert, then claim")
        ->check(CLI::Range(1, kMaxJobs));
    app.add_option("--replicas", o.replicas, "replicas, each with its own connection")
        ->check(CLI::Range(1, kMaxReplicas));
    app.add_option("--workers", o.workers, "claiming workers per replica")
        ->check(CLI::Range(1, kMaxWorkers));
    app.add_option("--out", o.out, "also write the Markdown table to this file");
    CLI11_PARSE(app, argc, argv);
    try {
        return run(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "radiant-queue-bench: %s\n", e.what());
        return 2;
    }
}
