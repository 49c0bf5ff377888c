#include "hierarchy/emitter_shot.h"

namespace radiant {

std::vector<Rgb> emitter_shot(const ElementTree& tree, const std::vector<Link>& links) {
    const std::size_t n = tree.size();
    std::vector<Rgb> received(n, Rgb{0, 0, 0});  // through each element's own links
    for (const Link& l : links) {
        const Rgb b = handed_radiosity(l, tree, [&tree](int s) -> const Rgb& {
            return tree[static_cast<std::size_t>(s)].exitance;
        });
        Rgb& r = received[static_cast<std::size_t>(l.receiver)];
        for (int c = 0; c < 3; ++c) r[c] += l.factor * b[c];
    }
    // Down: an element gets its ancestors' light too (a parent comes before its children).
    for (std::size_t e = 0; e < n; ++e) {
        const Element& x = tree[e];
        if (x.cluster || x.depth == 0) continue;
        const Rgb& above = received[static_cast<std::size_t>(x.parent)];
        for (int c = 0; c < 3; ++c) received[e][c] += above[c];
    }
    return received;
}

}  // namespace radiant
