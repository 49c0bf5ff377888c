#include "visibility/occluder_triangles.h"

namespace radiant {

std::pair<std::vector<Triangle>, std::vector<int>> occluder_triangles(const PreparedScene& scene) {
    std::vector<Triangle> tris;
    std::vector<int> piece;
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        const auto& v = scene.pieces[i].vertices;
        for (std::size_t k = 1; k + 1 < v.size(); ++k) {
            tris.push_back({v[0], v[k], v[k + 1]});
            piece.push_back(static_cast<int>(i));
        }
    }
    return {tris, piece};
}

}  // namespace radiant
