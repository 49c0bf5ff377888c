// A generated open-plan office for the benchmark: a 32 × 32 × 3 m room lit by 64 emitting
// ceiling panels, furnished with `units` furniture groups (two desks back to back, two chairs
// and a shelf, all closed boxes of 12 triangles), spread evenly over the floor, and a work-plane
// sensor grid. 64 groups give 23 040 furniture triangles.
#pragma once

#include <cstddef>

#include "radiant/scene.h"

namespace radiant::bench {

/// `units` must be a power of four (1, 4, 16, 64, …): the groups sit at the centres of a
/// √units × √units grid of equal cells.
Scene furnished_office(int units);

/// Triangles of the input geometry: mesh faces and polygons as fans, boxes as 12.
std::size_t input_triangles(const Scene& scene);

}  // namespace radiant::bench
