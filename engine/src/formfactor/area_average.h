// Area-to-area form factors where the kernel is near-singular: a receiver close to a source
// compared with its own size (an emitter 1 mm above a floor), where a fixed quadrature rule on
// the receiver puts no point in the narrow strip along the source's edges in which Lambert's
// factor changes from nearly 1 to nearly 0.
#pragma once

#include <span>

#include "radiant/vec3.h"

namespace radiant {

/// Mean over the convex planar `receiver` (unit normal `receiver_normal`) of Lambert's exact,
/// unoccluded factor to the one-sided convex `source` polygon (unit normal `source_normal`):
/// the form factor F(receiver → source). Adaptive cubature: a piece of the receiver is split in
/// four where its rule and its quarters' rules disagree, largest disagreement first, until all
/// disagreements together are below `relative_tolerance` of the result, or below
/// `absolute_tolerance_m2` (the error of the factor times the receiver's area), or there are
/// `max_pieces` pieces.
/// The work grows with log(size / distance), not with (size / distance)².
double area_averaged_factor(std::span<const Vec3> receiver, const Vec3& receiver_normal,
                            std::span<const Vec3> source, const Vec3& source_normal,
                            double relative_tolerance = 1e-3, double absolute_tolerance_m2 = 0,
                            int max_pieces = 2048);

}  // namespace radiant
