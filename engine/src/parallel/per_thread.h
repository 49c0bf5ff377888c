#pragma once

#include <memory>
#include <utility>

#include <tbb/enumerable_thread_specific.h>

namespace radiant {

// One T per thread of a parallel loop, combined after it: tbb::combinable, with its storage from
// operator new rather than TBB's allocator, whose reuse of memory between threads
// ThreadSanitizer cannot see (docs/fuzzing.md). Its bookkeeping is in headers, with atomics TSan
// follows.
template <class T>
class PerThread {
public:
    PerThread() = default;
    template <class Init>
    explicit PerThread(Init init) : values_(std::move(init)) {}

    // The calling thread's value, made by `init` (or T{}) on the thread's first call.
    T& local() { return values_.local(); }

    template <class Combine>
    T combine(Combine combine) {
        return values_.combine(combine);
    }

    template <class Visit>
    void combine_each(Visit visit) {
        values_.combine_each(visit);
    }

    void clear() { values_.clear(); }

private:
    tbb::enumerable_thread_specific<T, std::allocator<T>> values_;
};

}  // namespace radiant
