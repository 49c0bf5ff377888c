#include "montecarlo/set_allotment.h"

#include <algorithm>
#include <cmath>

namespace radiant {
namespace {

// Bisection steps for the proportionality factor: far more than a double's 52 bits of
// mantissa need between the bounds below.
constexpr int kBisections = 100;

// The sets of a sensor set's points for a factor λ: λσ each, at least what it has (`has` from
// the set's first point on).
long long total_for(double lambda, const int* has, const std::vector<double>& sigma) {
    long long total = 0;
    for (std::size_t k = 0; k < sigma.size(); ++k)
        total += std::max<long long>(has[k], static_cast<long long>(std::ceil(lambda * sigma[k])));
    return total;
}

}  // namespace

std::vector<int> allot_sets(const std::vector<int>& sets, const std::vector<int>& has,
                            const std::vector<double>& spread,
                            const std::vector<std::size_t>& set_sizes) {
    std::vector<int> out(has);
    std::size_t first = 0;
    for (std::size_t set = 0; set < set_sizes.size(); ++set) {
        const std::size_t size = set_sizes[set];
        const long long wanted = static_cast<long long>(size) * sets[set];
        double squares = 0;
        for (std::size_t i = first; i < first + size && !spread.empty(); ++i)
            squares += spread[i] * spread[i];
        const double floor = size > 0 ? kMinSpreadShare * std::sqrt(squares / size) : 0.0;
        const int* had = has.data() + first;
        std::vector<double> sigma(size, 0.0);
        double least = 0;
        for (std::size_t k = 0; k < size; ++k) {
            const double s = spread.empty() ? 0.0 : spread[first + k];
            sigma[k] = std::isfinite(s) ? std::max(s, floor) : floor;
            if (sigma[k] > 0) least = least > 0 ? std::min(least, sigma[k]) : sigma[k];
        }
        if (!(least > 0) || !std::isfinite(floor)) {
            for (std::size_t k = 0; k < size; ++k) out[first + k] = std::max(had[k], sets[set]);
        } else if (total_for(0, had, sigma) < wanted) {
            // The least λ whose sets reach the wanted total: λ = wanted / least gives every
            // point at least `wanted` sets, more than enough.
            double lo = 0, hi = static_cast<double>(wanted) / least;
            for (int step = 0; step < kBisections; ++step) {
                const double mid = 0.5 * (lo + hi);
                (total_for(mid, had, sigma) >= wanted ? hi : lo) = mid;
            }
            for (std::size_t k = 0; k < size; ++k)
                out[first + k] = std::max(had[k], static_cast<int>(std::ceil(hi * sigma[k])));
        }
        first += size;
    }
    return out;
}

}  // namespace radiant
