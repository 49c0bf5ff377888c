// Counter-based random numbers: a sample stream is a pure function of its key, so results do not
// depend on which thread computes what (determinism for any thread count).
#pragma once

#include <cstdint>

namespace radiant {

inline std::uint64_t mix64(std::uint64_t x) {  // SplitMix64 finaliser (Steele et al. 2014)
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

class SampleStream {
public:
    SampleStream(std::uint64_t seed, std::uint64_t a, std::uint64_t b, std::uint64_t c = 0)
        : state_(mix64(mix64(mix64(seed) ^ a) ^ b) ^ c) {}
    /// Uniform in [0, 1).
    double next() {
        state_ = mix64(state_);
        return static_cast<double>(state_ >> 11) * 0x1.0p-53;
    }

private:
    std::uint64_t state_;
};

}  // namespace radiant
