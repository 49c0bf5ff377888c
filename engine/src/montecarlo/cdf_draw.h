// Drawing an index by its weight from cumulative weights, as light sources and their pieces are.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>

namespace radiant {

/// The index whose weight `r` in [0, 1) lands in: the first cumulative weight above r times the
/// total (`cdf` non-empty and non-decreasing).
inline std::size_t draw_index(std::span<const double> cdf, double r) {
    const double target = r * cdf.back();
    const auto it = std::upper_bound(cdf.begin(), cdf.end(), target);
    return std::min(static_cast<std::size_t>(it - cdf.begin()), cdf.size() - 1);
}

}  // namespace radiant
