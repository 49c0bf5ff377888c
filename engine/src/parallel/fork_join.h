#pragma once

#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>

// The engine's only door to oneTBB's scheduler. Debian's oneTBB is not built with
// ThreadSanitizer, so TSan cannot see the hand-over of tasks between its threads; fork_join.cpp
// calls TBB from one file compiled without TSan and tells TSan the happens-before edges TBB
// guarantees (docs/fuzzing.md). Loop bodies stay in the callers' files, checked by TSan.
namespace radiant {

// A callable borrowed for the length of one call, without allocating.
template <class Signature>
class BorrowedCall;

template <class R, class... Args>
class BorrowedCall<R(Args...)> {
public:
    template <class F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, BorrowedCall>)
        BorrowedCall(F&& f)  // NOLINT(google-explicit-constructor): borrowed like a reference
        : object_(const_cast<void*>(static_cast<const void*>(std::addressof(f)))),
          call_([](void* object, Args... args) -> R {
              return (*static_cast<std::remove_reference_t<F>*>(object))(
                  std::forward<Args>(args)...);
          }) {}
    R operator()(Args... args) const { return call_(object_, std::forward<Args>(args)...); }

private:
    void* object_;
    R (*call_)(void*, Args...);
};

namespace detail {
void parallel_chunks(std::size_t begin, std::size_t end, std::size_t grain,
                     BorrowedCall<void(std::size_t, std::size_t)> chunk);
}  // namespace detail

// body(first, last) for disjoint chunks [first, last) that cover [begin, end), on the current
// arena's threads (a chunk of `grain` indices or fewer is not split); returns when all are done.
template <class ChunkBody>
void parallel_for_chunks(std::size_t begin, std::size_t end, std::size_t grain, ChunkBody&& body) {
    detail::parallel_chunks(begin, end, grain, body);
}

// body(i) for every i in [begin, end), like tbb::parallel_for(begin, end, body).
template <class Body>
void parallel_for(std::size_t begin, std::size_t end, Body&& body) {
    auto chunk = [&body](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i != last; ++i) body(i);
    };
    detail::parallel_chunks(begin, end, 1, chunk);
}

// Runs `work` in an arena of `threads` threads (0: one per CPU) and returns when it is done.
void run_with_threads(int threads, BorrowedCall<void()> work);

// Runs `work`, which uses TBB inside a library not built with TSan (Embree's BVH build). Under
// TSan it runs on the calling thread alone: that library's hand-over of tasks between threads
// cannot be annotated from outside, and its code is invisible to TSan either way.
void run_library_parallel_work(BorrowedCall<void()> work);

// How many threads the current arena runs parallel loops on.
int arena_threads();

}  // namespace radiant
