#include "hierarchy/root_patch_locator.h"

#include <algorithm>
#include <cmath>

namespace radiant {
namespace {

// Pieces with more root patches than this get a grid; fewer are searched one by one.
constexpr std::size_t kScannedPatches = 16;

int cell_of(double coordinate, double lo, double cell, int count) {
    const double i = std::floor((coordinate - lo) / cell);
    return static_cast<int>(std::clamp(i, 0.0, static_cast<double>(count - 1)));
}

}  // namespace

RootPatchLocator::RootPatchLocator(const PreparedScene& scene, const PatchMesh& roots,
                                   const ElementTree& tree, double margin)
    : tree_(tree), margin_(margin), piece_roots_(scene.pieces.size()), grids_(scene.pieces.size()) {
    for (std::size_t e = 0; e < tree.size(); ++e) {
        const Element& x = tree[e];
        if (x.cluster || x.depth > 0) continue;
        const int piece = roots.patch(static_cast<std::size_t>(x.patch)).piece;
        piece_roots_[static_cast<std::size_t>(piece)].push_back(static_cast<int>(e));
    }
    for (std::size_t p = 0; p < scene.pieces.size(); ++p) {
        if (piece_roots_[p].size() > kScannedPatches)
            grids_[p] = make_grid(scene.pieces[p], piece_roots_[p]);
    }
}

RootPatchLocator::PieceGrid RootPatchLocator::make_grid(const Piece& piece,
                                                        const std::vector<int>& elements) const {
    PieceGrid g;
    g.origin = piece.vertices[0];
    g.u = normalized(piece.vertices[1] - piece.vertices[0]);
    g.v = cross(piece.normal, g.u);
    struct Extent {
        double lo_u, hi_u, lo_v, hi_v;
    };
    std::vector<Extent> extents;
    Extent all{1e300, -1e300, 1e300, -1e300};
    for (const int e : elements) {
        Extent x{1e300, -1e300, 1e300, -1e300};
        for (const Vec3& p : tree_[static_cast<std::size_t>(e)].polygon) {
            const double a = dot(p - g.origin, g.u), b = dot(p - g.origin, g.v);
            x = {std::min(x.lo_u, a), std::max(x.hi_u, a), std::min(x.lo_v, b),
                 std::max(x.hi_v, b)};
        }
        extents.push_back(x);
        all = {std::min(all.lo_u, x.lo_u), std::max(all.hi_u, x.hi_u), std::min(all.lo_v, x.lo_v),
               std::max(all.hi_v, x.hi_v)};
    }
    // About one element per cell.
    const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(elements.size()))));
    g.n_u = g.n_v = side;
    g.lo_u = all.lo_u;
    g.lo_v = all.lo_v;
    g.cell_u = std::max((all.hi_u - all.lo_u) / side, 1e-300);
    g.cell_v = std::max((all.hi_v - all.lo_v) / side, 1e-300);
    g.cells.resize(static_cast<std::size_t>(side) * static_cast<std::size_t>(side));
    for (std::size_t k = 0; k < elements.size(); ++k) {
        const Extent& x = extents[k];
        const int u0 = cell_of(x.lo_u - margin_, g.lo_u, g.cell_u, side);
        const int u1 = cell_of(x.hi_u + margin_, g.lo_u, g.cell_u, side);
        const int v0 = cell_of(x.lo_v - margin_, g.lo_v, g.cell_v, side);
        const int v1 = cell_of(x.hi_v + margin_, g.lo_v, g.cell_v, side);
        for (int j = v0; j <= v1; ++j) {
            for (int i = u0; i <= u1; ++i)
                g.cells[static_cast<std::size_t>(j * side + i)].push_back(elements[k]);
        }
    }
    return g;
}

const std::vector<int>& RootPatchLocator::candidates(int piece, const Vec3& x) const {
    const auto p = static_cast<std::size_t>(piece);
    const PieceGrid& g = grids_[p];
    if (g.cells.empty()) return piece_roots_[p];
    const int i = cell_of(dot(x - g.origin, g.u), g.lo_u, g.cell_u, g.n_u);
    const int j = cell_of(dot(x - g.origin, g.v), g.lo_v, g.cell_v, g.n_v);
    return g.cells[static_cast<std::size_t>(j * g.n_u + i)];
}

int RootPatchLocator::locate(const Vec3& x, const Vec3& dir, int piece,
                             std::vector<int>& stack) const {
    for (const int e : candidates(piece, x)) {
        const Element& element = tree_[static_cast<std::size_t>(e)];
        if (holds(element, x, dir)) return element.patch;
    }
    return in_tree(x, dir, stack);
}

int RootPatchLocator::in_tree(const Vec3& x, const Vec3& dir, std::vector<int>& stack) const {
    if (tree_.top() < 0) return -1;
    const double m = margin_;
    stack.assign(1, tree_.top());
    while (!stack.empty()) {
        const Element& e = tree_[static_cast<std::size_t>(stack.back())];
        stack.pop_back();
        if (x.x < e.lo.x - m || x.y < e.lo.y - m || x.z < e.lo.z - m || x.x > e.hi.x + m ||
            x.y > e.hi.y + m || x.z > e.hi.z + m) {
            continue;
        }
        if (e.cluster) {
            stack.insert(stack.end(), e.children.begin(), e.children.end());
        } else if (holds(e, x, dir)) {
            return e.patch;
        }
    }
    return -1;
}

bool RootPatchLocator::holds(const Element& e, const Vec3& x, const Vec3& dir) const {
    if (!(dot(e.normal, dir) < 0) || std::abs(dot(x - e.polygon[0], e.normal)) > margin_)
        return false;
    for (std::size_t i = 0; i < e.polygon.size(); ++i) {
        const Vec3& a = e.polygon[i];
        const Vec3& b = e.polygon[(i + 1) % e.polygon.size()];
        if (dot(cross(b - a, x - a), e.normal) < -margin_ * length(b - a)) return false;
    }
    return true;
}

}  // namespace radiant
