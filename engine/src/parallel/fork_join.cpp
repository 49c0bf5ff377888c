#include "parallel/fork_join.h"

#include <memory>

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
// On the heap, not the stack: TSan forgets a token's clock when its memory is freed, not when a
// frame returns, and a stack address comes back in later fork-joins, also of a new thread that
// reuses a finished thread's stack.
class Tokens {
public:
    const void* fork() const { return &bytes_[0]; }
    const void* join() const { return &bytes_[1]; }

private:
    std::unique_ptr<char[]> bytes_ = std::make_unique<char[]>(2);
};
#else
void release(const void*) {}
void acquire(const void*) {}
struct Tokens {
    const void* fork() const { return nullptr; }
    const void* join() const { return nullptr; }
};
#endif

// The two edges of one fork-join, named for TSan by its tokens' addresses. It is made before the
// tasks fork and destroyed after they joined; a Task lives as long as one task. Destructors keep
// the edges when a task throws and TBB passes the exception on to the caller.
class ForkJoin {
public:
    ForkJoin() { release(tokens_.fork()); }
    ~ForkJoin() { acquire(tokens_.join()); }
    ForkJoin(const ForkJoin&) = delete;
    ForkJoin& operator=(const ForkJoin&) = delete;

    class Task {
    public:
        explicit Task(const ForkJoin& edges) : edges_(edges) { acquire(edges_.tokens_.fork()); }
        ~Task() { release(edges_.tokens_.join()); }
        Task(const Task&) = delete;
        Task& operator=(const Task&) = delete;

    private:
        const ForkJoin& edges_;
    };

private:
    Tokens tokens_;
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
