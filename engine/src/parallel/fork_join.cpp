#include "parallel/fork_join.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#ifdef RADIANT_TSAN_EDGES
#include <sanitizer/tsan_interface.h>
#endif

// Compiled without -fsanitize=thread, like libtbb itself (engine/src/parallel/CMakeLists.txt):
// TBB's task objects are written on one thread and run on another through atomics inside libtbb
// that TSan cannot see. The edges below are exactly those TBB guarantees: everything before a
// fork happens before each task, each task happens before the join. Tasks stay unordered with
// each other, so races between them are still reported.
namespace radiant {
namespace {

#ifdef RADIANT_TSAN_EDGES
void release(const void* token) { __tsan_release(const_cast<void*>(token)); }
void acquire(const void* token) { __tsan_acquire(const_cast<void*>(token)); }
#else
void release(const void*) {}
void acquire(const void*) {}
#endif

// The two edges of one fork-join: the tokens' addresses name them for TSan.
struct ForkJoin {
    char fork = 0, join = 0;
    ForkJoin() { release(&fork); }
    ForkJoin(const ForkJoin&) = delete;
    ForkJoin& operator=(const ForkJoin&) = delete;
    void task_starts() const { acquire(&fork); }
    void task_ends() const { release(&join); }
    void joined() const { acquire(&join); }
};

}  // namespace

namespace detail {

void parallel_chunks(std::size_t begin, std::size_t end, std::size_t grain,
                     BorrowedCall<void(std::size_t, std::size_t)> chunk) {
    if (begin >= end) return;
    const ForkJoin edges;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, grain),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          edges.task_starts();
                          chunk(range.begin(), range.end());
                          edges.task_ends();
                      });
    edges.joined();
}

}  // namespace detail

void run_with_threads(int threads, BorrowedCall<void()> work) {
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    // execute() may hand `work` to another thread when the arena has no free slot.
    const ForkJoin edges;
    arena.execute([&] {
        edges.task_starts();
        work();
        edges.task_ends();
    });
    edges.joined();
}

void run_library_parallel_work(BorrowedCall<void()> work) {
#ifdef RADIANT_TSAN_EDGES
    tbb::task_arena(1).execute([&] { work(); });
#else
    work();
#endif
}

int arena_threads() { return tbb::this_task_arena::max_concurrency(); }

}  // namespace radiant
