#include "combined_runs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace radiant::bench {
namespace {

double median_of(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t half = values.size() / 2;
    return values.size() % 2 ? values[half] : (values[half - 1] + values[half]) / 2;
}

}  // namespace

CombinedRuns combine_runs(const std::vector<std::vector<double>>& runs, bool median) {
    CombinedRuns out;
    if (runs.empty()) return out;
    const std::size_t points = runs.front().size();
    const double n = static_cast<double>(runs.size());
    for (std::size_t i = 0; i < points; ++i) {
        std::vector<double> values;
        for (const auto& r : runs) values.push_back(r[i]);
        double mean = 0;
        for (const double v : values) mean += v / n;
        double squares = 0;
        for (const double v : values) squares += (v - mean) * (v - mean);
        double error = runs.size() > 1 ? std::sqrt(squares / (n - 1) / n)
                                       : std::numeric_limits<double>::quiet_NaN();
        double value = mean;
        if (median) {
            value = median_of(values);
            // The spread from the median absolute deviation (1.4826 times it is a normal's σ), so
            // that the bright path the median resists does not make its error either.
            std::vector<double> deviations;
            for (const double v : values) deviations.push_back(std::abs(v - value));
            const double sigma = 1.4826 * median_of(deviations);
            if (runs.size() > 1) error = std::sqrt(std::numbers::pi / 2) * sigma / std::sqrt(n);
        }
        out.value.push_back(value);
        out.standard_error.push_back(error);
    }
    return out;
}

}  // namespace radiant::bench
