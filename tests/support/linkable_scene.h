// A test scene as the hierarchical pipeline links it: root patches, their cluster tree and the
// visibility of the scene's pieces.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "hierarchy/element_tree.h"
#include "meshing/patch_mesh.h"
#include "scene/prepared_scene.h"
#include "visibility/occluder_triangles.h"
#include "visibility/visibility.h"

namespace radiant::testing {

struct LinkableScene {
    /// Root patches of about `root_edge_m`; elements split down to `min_edge_m`.
    explicit LinkableScene(const Scene& s, double root_edge_m = 1.0, double min_edge_m = 0.25)
        : scene(prepare_scene(s)), roots(scene, {root_edge_m, 3000, 0}) {
        auto [triangles, piece] = occluder_triangles(scene);
        triangle_piece = std::move(piece);
        visibility = make_embree_visibility(triangles);
        tree = std::make_unique<ElementTree>(scene, roots, *visibility, min_edge_m, 1);
    }

    PreparedScene scene;
    PatchMesh roots;
    std::vector<int> triangle_piece;  ///< piece of each of the visibility's triangles
    std::unique_ptr<Visibility> visibility;
    std::unique_ptr<ElementTree> tree;
};

}  // namespace radiant::testing
