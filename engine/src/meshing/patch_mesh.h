// Patches: the unknowns of the radiosity system. Every piece of the prepared scene is
// subdivided to the target size, split along the lines where other surfaces touch it (so no
// patch straddles a wall standing on it, the main source of light leaks), and stored in one
// OpenMesh poly mesh whose face properties carry the solver state.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <tuple>
#include <vector>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include "scene/prepared_scene.h"

namespace radiant {

struct PatchTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<PatchTraits>;

/// Immutable geometry of one patch (face i of the mesh is patch i).
struct PatchGeometry {
    std::vector<Vec3> vertices;  ///< convex, counter-clockwise about `normal`
    Vec3 normal;                 ///< unit, the side that receives and emits
    Vec3 centroid;
    double area_m2 = 0;
    double diameter_m = 0;
    int piece = 0;
    int surface = 0;
    int material = 0;
    bool back_side = false;  ///< the back of a two-sided surface
    /// Covered by a smaller coplanar surface facing the same way (a flush panel, a rug): it
    /// neither receives nor emits, but its area still counts in its surface's averages.
    bool hidden = false;
};

struct MeshingOptions {
    double target_edge_m = 1.0;
    std::size_t max_patches = 3000;  ///< the target edge grows until the estimate fits
    /// Parallel pieces nearer than this cut each other's patches along their outlines; 0: half
    /// the patch edge. Patches that are refined further (hierarchical roots) need only the gaps
    /// their refinement cannot resolve, and a gap growing with the patch costs quadratic time
    /// and memory (every parallel piece within it).
    double shading_gap_m = 0;
    /// The plan may hold at most this (its polygons and the pairs of pieces that may touch);
    /// 0: no limit. A plan that would hold more stops there, `exceeded`.
    std::size_t max_plan_bytes = 0;
    /// Asked now and then while the pieces are cut; once it is true (a time limit, a cancel), no
    /// contact cuts them, not even those already cut: the pieces' subdivision alone, for a solve
    /// that stops with what it has.
    std::function<bool()> should_stop = nullptr;
};

/// Target patch edge from the scene's scale and the tolerance: radiosity varies over the mean
/// free path ℓ of light between surfaces, and face means converge as O(h²), so h ∝ ℓ·√tol.
double target_patch_edge(double mean_free_path_m, double tolerance);

/// The polygons of the patches a PatchMesh is made of, planned but not made: about a tenth of
/// the mesh's memory, so that their count can be held against a budget before the mesh is made.
class PatchPlan {
public:
    PatchPlan(const PreparedScene& scene, const MeshingOptions& options);
    /// The patches planned (fewer than a whole plan's when it was exceeded).
    std::size_t count() const { return count_; }
    /// Whether planning stopped at the options' max_plan_bytes, and what it would have held at
    /// least (0 when it did not stop): no mesh may be made from such a plan.
    bool exceeded() const { return least_bytes_ > 0; }
    std::size_t least_bytes() const { return least_bytes_; }
    /// The target edge, grown from the options' until the patches fit max_patches.
    double target_edge_m() const { return target_edge_m_; }

private:
    friend class PatchMesh;
    std::vector<std::vector<std::vector<Vec3>>> polygons_;  ///< per piece
    std::vector<std::vector<int>> overlays_;  ///< per piece: the smaller coplanar pieces on it
    double target_edge_m_;
    double epsilon_;
    std::size_t count_ = 0;
    std::size_t least_bytes_ = 0;
};

class PatchMesh {
public:
    PatchMesh(const PreparedScene& scene, const MeshingOptions& options);
    PatchMesh(const PreparedScene& scene, PatchPlan plan);

    std::size_t size() const { return patches_.size(); }
    const PatchGeometry& patch(std::size_t i) const { return patches_[i]; }
    const std::vector<PatchGeometry>& patches() const { return patches_; }
    const PolyMesh& mesh() const { return mesh_; }
    double target_edge_m() const { return target_edge_m_; }

    /// Per-face solver state, one property per colour channel (contiguous, index = patch).
    std::vector<double>& radiosity(int channel) { return prop(radiosity_[channel]); }
    std::vector<double>& unshot(int channel) { return prop(unshot_[channel]); }
    std::vector<double>& irradiance(int channel) { return prop(irradiance_[channel]); }
    const std::vector<double>& radiosity(int channel) const { return prop(radiosity_[channel]); }
    const std::vector<double>& irradiance(int channel) const { return prop(irradiance_[channel]); }

private:
    using DoubleProp = OpenMesh::FPropHandleT<double>;
    std::vector<double>& prop(DoubleProp h) { return mesh_.property(h).data_vector(); }
    const std::vector<double>& prop(DoubleProp h) const { return mesh_.property(h).data_vector(); }
    using VertexIndex = std::map<
        std::tuple<int, bool, std::tuple<long long, long long, long long>, double, double, double>,
        PolyMesh::VertexHandle>;
    void add_face(const PatchGeometry& patch, VertexIndex& index);

    PolyMesh mesh_;
    std::vector<PatchGeometry> patches_;
    std::array<DoubleProp, 3> radiosity_, unshot_, irradiance_;
    double target_edge_m_ = 1.0;
};

}  // namespace radiant
