// Which root patch holds a point a ray hit: among the patches of the piece hit (directly for a
// few, through a grid in the piece's plane for many), down the cluster tree when none of them
// does (the point lies on a coplanar cover, whose hidden patch underneath has no element).
#pragma once

#include <vector>

#include "hierarchy/element_tree.h"
#include "meshing/patch_mesh.h"
#include "scene/prepared_scene.h"

namespace radiant {

class RootPatchLocator {
public:
    /// `margin`: how far off its patch a hit point may lie (metres).
    RootPatchLocator(const PreparedScene& scene, const PatchMesh& roots, const ElementTree& tree,
                     double margin);

    /// The root patch facing against `dir` whose polygon holds x, which lies on piece `piece`;
    /// −1 if none does. `stack` is scratch space for the tree search. Thread-safe.
    int locate(const Vec3& x, const Vec3& dir, int piece, std::vector<int>& stack) const;

private:
    // A uniform grid over the piece's root elements in its plane (pieces with many of them).
    struct PieceGrid {
        Vec3 origin, u, v;
        double lo_u = 0, lo_v = 0, cell_u = 1, cell_v = 1;
        int n_u = 0, n_v = 0;
        std::vector<std::vector<int>> cells;  // elements whose box overlaps each cell
    };
    PieceGrid make_grid(const Piece& piece, const std::vector<int>& elements) const;
    const std::vector<int>& candidates(int piece, const Vec3& x) const;
    int in_tree(const Vec3& x, const Vec3& dir, std::vector<int>& stack) const;
    bool holds(const Element& e, const Vec3& x, const Vec3& dir) const;

    const ElementTree& tree_;
    double margin_;
    std::vector<std::vector<int>> piece_roots_;  // root elements of each piece
    std::vector<PieceGrid> grids_;               // per piece; empty cells: listed directly
};

}  // namespace radiant
