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

// The two edges of one fork-join, named for TSan by the tokens' addresses. It is made before the
// tasks fork and destroyed after they joined; a Task lives as long as one task. Destructors keep
// the edges when a task throws and TBB passes the exception on to the caller.
class ForkJoin {
public:
    ForkJoin() { release(&fork_); }
    ~ForkJoin() { acquire(&join_); }
    ForkJoin(const ForkJoin&) = delete;
    ForkJoin& operator=(const ForkJoin&) = delete;

    class Task {
    public:
        explicit Task(const ForkJoin& edges) : edges_(edges) { acquire(&edges_.fork_); }
        ~Task() { release(&edges_.join_); }
        Task(const Task&) = delete;
        Task& operator=(const Task&) = delete;

    private:
        const ForkJoin& edges_;
    };

private:
    char fork_ = 0, join_ = 0;
};

}  // namespace

namespace detail {

void parallel_chunks(std::size_t begin, std::size_t end, std::size_t grain,
                     BorrowedCall<void(std::size_t, std::size_t)> chunk) {
    if (begin >= end) return;
    const ForkJoin edges;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, end, grain),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          const ForkJoin::Task task(edges);
                          chunk(range.begin(), range.end());
                      });
}

}  // namespace detail

void run_with_threads(int threads, BorrowedCall<void()> work) {
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    // execute() may hand `work` to another thread when the arena has no free slot.
    const ForkJoin edges;
    arena.execute([&] {
        const ForkJoin::Task task(edges);
        work();
    });
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
