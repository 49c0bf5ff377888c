#include "visibility/occluder_triangles.h"

#include <utility>

namespace radiant {

std::pair<std::vector<Triangle>, std::vector<int>> occluder_triangles(const PreparedScene& scene) {
    // Reserved exactly: the memory budget counts these lists at their size.
    std::size_t count = 0;
    for (const Piece& p : scene.pieces) count += p.vertices.size() >= 3 ? p.vertices.size() - 2 : 0;
    std::vector<Triangle> tris;
    std::vector<int> piece;
    tris.reserve(count);
    piece.reserve(count);
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        const auto& v = scene.pieces[i].vertices;
        for (std::size_t k = 1; k + 1 < v.size(); ++k) {
            tris.push_back({v[0], v[k], v[k + 1]});
            piece.push_back(static_cast<int>(i));
        }
    }
    return {std::move(tris), std::move(piece)};
}

}  // namespace radiant
