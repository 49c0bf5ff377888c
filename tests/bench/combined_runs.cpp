#include "combined_runs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace radiant::bench {

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
            std::sort(values.begin(), values.end());
            const std::size_t half = values.size() / 2;
            value = values.size() % 2 ? values[half] : (values[half - 1] + values[half]) / 2;
            error *= std::sqrt(std::numbers::pi / 2);
        }
        out.value.push_back(value);
        out.standard_error.push_back(error);
    }
    return out;
}

}  // namespace radiant::bench
