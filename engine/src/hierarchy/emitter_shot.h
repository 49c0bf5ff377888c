// The emitters' first shot, between the two stages of lazy linking (see link_refinement.h): the
// links from the emitting patches are made first, and before the other sources are linked each
// emitter sends its emission through its links, so that a viewer sees the direct light early.
#pragma once

#include <vector>

#include "hierarchy/element_tree.h"
#include "hierarchy/link_refinement.h"

namespace radiant {

/// Per surface element, the irradiance the emission reaches it with through its own links and
/// its ancestors' (for a leaf, all it gets; 0 for clusters). Links from sources that do not emit
/// add nothing.
std::vector<Rgb> emitter_shot(const ElementTree& tree, const std::vector<Link>& links);

}  // namespace radiant
