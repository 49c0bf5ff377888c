// The generated scenes' random numbers: SplitMix64 (Steele, Lea & Flood 2014) with our own
// mapping to ranges, because std::uniform_real_distribution's output differs between standard
// libraries and a scene must be the same for a seed everywhere.
#pragma once

#include <cstddef>
#include <cstdint>

namespace radiant::bench {

class SeededRandom {
public:
    explicit SeededRandom(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next_bits() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1).
    double unit() { return static_cast<double>(next_bits() >> 11) * 0x1.0p-53; }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    /// Uniform over {lo, …, hi}.
    int integer(int lo, int hi) {
        return lo + static_cast<int>(next_bits() % static_cast<std::uint64_t>(hi - lo + 1));
    }
    /// True with probability `p`.
    bool chance(double p) { return unit() < p; }
    /// An index in [0, n).
    std::size_t index(std::size_t n) { return static_cast<std::size_t>(next_bits() % n); }

private:
    std::uint64_t state_;
};

}  // namespace radiant::bench
