// The split of the bounding-volume hierarchies (the element tree's clusters, the light tree, the
// receiver rules' centroid tree): a range of items partitioned at its middle along the axis where
// their centres spread most, O(k) per split and balanced whatever the items' sizes.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "radiant/vec3.h"

namespace radiant {

/// Partitions `items[begin, end)` at its middle along the longest axis of `extent` (the extent
/// of their centres), by `centre(item)`: those before the middle lie at or below it. Returns the
/// middle.
template <class Item, class Centre>
std::size_t split_at_median(std::vector<Item>& items, std::size_t begin, std::size_t end,
                            const Vec3& extent, Centre&& centre) {
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::size_t middle = begin + (end - begin) / 2;
    std::nth_element(
        items.begin() + static_cast<std::ptrdiff_t>(begin),
        items.begin() + static_cast<std::ptrdiff_t>(middle),
        items.begin() + static_cast<std::ptrdiff_t>(end),
        [&](const Item& a, const Item& b) { return centre(a)[axis] < centre(b)[axis]; });
    return middle;
}

}  // namespace radiant
