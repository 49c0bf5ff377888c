// The engine's parallel loops (engine/src/parallel): every index once, the fork and join edges
// that ThreadSanitizer is told about, and — in the TSan build — that two tasks of one loop stay
// unordered for it, so a race between them is still reported (docs/fuzzing.md).
#include <gtest/gtest.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "parallel/fork_join.h"
#include "parallel/per_thread.h"

#if defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define RADIANT_TEST_UNDER_TSAN 1
#endif
#endif

namespace radiant {
namespace {

TEST(ForkJoin, ChunksCoverEveryIndexOnce) {
    const std::size_t begin = 3, end = 1003;
    std::vector<std::atomic<int>> visits(end);
    std::atomic<bool> backwards{false};
    parallel_for_chunks(begin, end, 64, [&](std::size_t first, std::size_t last) {
        if (first >= last) backwards = true;
        for (std::size_t i = first; i != last; ++i) ++visits[i];
    });
    EXPECT_FALSE(backwards);
    for (std::size_t i = 0; i < end; ++i) EXPECT_EQ(visits[i], i < begin ? 0 : 1) << i;
}

// Plain memory written before a loop, read by its tasks, written by them and read after it: in
// the TSan build this fails with a report unless both edges reach TSan.
TEST(ForkJoin, TasksSeeWhatCameBeforeAndTheCallerSeesWhatTheyDid) {
    const std::size_t n = 10000;
    std::vector<double> input(n), output(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) input[i] = static_cast<double>(i);
    run_with_threads(2,
                     [&] { parallel_for(0, n, [&](std::size_t i) { output[i] = 2 * input[i]; }); });
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(output[i], 2.0 * static_cast<double>(i)) << i;
}

// The caller reads what the tasks wrote also when one of them threw: in the TSan build this
// reports a race unless the join edge holds on that path too.
TEST(ForkJoin, ATasksExceptionReachesTheCallerAfterTheJoin) {
    std::vector<int> done(1000, 0);
    EXPECT_THROW(run_with_threads(2,
                                  [&] {
                                      parallel_for(0, done.size(), [&](std::size_t i) {
                                          done[i] = 1;
                                          if (i == 500) throw std::runtime_error("task 500");
                                      });
                                  }),
                 std::runtime_error);
    EXPECT_EQ(done[500], 1);
}

TEST(ForkJoin, PerThreadValuesCombineToTheTotal) {
    PerThread<std::size_t> sums([] { return std::size_t{0}; });
    run_with_threads(2, [&] { parallel_for(1, 1001, [&](std::size_t i) { sums.local() += i; }); });
    EXPECT_EQ(sums.combine([](std::size_t a, std::size_t b) { return a + b; }), 500500u);
    sums.clear();
    EXPECT_EQ(sums.combine([](std::size_t a, std::size_t b) { return a + b; }), 0u);
}

TEST(ForkJoin, ArenaHasTheThreadsAskedFor) {
    int one = 0, two = 0;
    run_with_threads(1, [&] { one = arena_threads(); });
    run_with_threads(2, [&] { two = arena_threads(); });
    EXPECT_EQ(one, 1);
    EXPECT_EQ(two, 2);
}

#ifdef RADIANT_TEST_UNDER_TSAN
// Both tasks of a two-index loop wait (with relaxed atomics, which order nothing for TSan) until
// the other has started, so they run on two threads; then task 0 writes a plain int and task 1
// writes it after it (TSan may miss two writes at the same instant).
void race_between_two_tasks() {
    std::atomic<int> started{0};
    std::atomic<bool> written{false};
    int shared = -1;
    run_with_threads(2, [&] {
        parallel_for(0, 2, [&](std::size_t i) {
            started.fetch_add(1, std::memory_order_relaxed);
            while (started.load(std::memory_order_relaxed) < 2) {
            }
            if (i == 1) {
                while (!written.load(std::memory_order_relaxed)) {
                }
            }
            shared = static_cast<int>(i);
            written.store(true, std::memory_order_relaxed);
        });
    });
    std::exit(shared == 0 || shared == 1 ? 0 : 1);
}

// The test below runs this binary again with kRacyChild set: it runs the racy loop before
// GoogleTest starts, and TSan's finding ends it.
constexpr const char* kRacyChild = "RADIANT_FORK_JOIN_RACY_CHILD";
const bool racy_child = [] {
    if (std::getenv(kRacyChild) != nullptr) race_between_two_tasks();
    return false;
}();

TEST(ForkJoinUnderTsan, RaceBetweenTwoTasksIsReported) {
    cpu_set_t cpus;
    ASSERT_EQ(sched_getaffinity(0, sizeof cpus, &cpus), 0);
    if (CPU_COUNT(&cpus) < 2) GTEST_SKIP() << "one CPU: TBB starts no second thread";
    std::array<char, 4096> self{};
    ASSERT_GT(readlink("/proc/self/exe", self.data(), self.size() - 1), 0);
    const std::string command = std::string(kRacyChild) + "=1 '" + self.data() + "' 2>&1";
    FILE* child = popen(command.c_str(), "r");
    ASSERT_NE(child, nullptr);
    std::string output;
    for (int c = std::fgetc(child); c != EOF; c = std::fgetc(child)) output += static_cast<char>(c);
    const int status = pclose(child);
    ASSERT_TRUE(WIFEXITED(status)) << output;
    EXPECT_EQ(WEXITSTATUS(status), 66) << output;  // TSan's exit status for a finding
    EXPECT_NE(output.find("ThreadSanitizer: data race"), std::string::npos) << output;
}
#endif

}  // namespace
}  // namespace radiant

#ifdef RADIANT_TEST_UNDER_TSAN
// TSan's exit status for a finding (66) also when the environment sets no options.
extern "C" const char* __tsan_default_options() { return "halt_on_error=1:exitcode=66"; }
#endif
