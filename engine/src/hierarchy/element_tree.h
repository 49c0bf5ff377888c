// The hierarchy the hierarchical solver links: a cluster tree (bounding-volume hierarchy) over
// the root patches, and under every root patch a quadtree of surface elements made on demand.
// Light can be linked at any level: clusters (Smits, Arvo & Greenberg 1994) keep the initial
// linking far from quadratic in the number of input polygons, sub-elements resolve detail.
#pragma once

#include <cstdint>
#include <vector>

#include "meshing/patch_mesh.h"
#include "scene/prepared_scene.h"
#include "visibility/visibility.h"

namespace radiant {

/// A point that stands for a piece of an element: where it is, which way it faces, how much
/// area it carries (the weights of an element sum to its area).
struct SamplePoint {
    Vec3 position;
    Vec3 normal;
    double weight;
    int root = -1;  ///< cluster samples: the root element (patch) the point lies on
};

/// Form factor from a point x (unit normal n) to the area a sample point stands for: the
/// point-to-disk kernel A cosθ cosθ' / (πr² + A), bounded as r → 0; 0 when either faces away.
double sample_kernel(const Vec3& x, const Vec3& n, const SamplePoint& y);

struct Element {
    std::vector<Vec3> polygon;  ///< surface elements: convex, counter-clockwise about `normal`
    Vec3 normal;                ///< surface elements only
    Vec3 lo, hi;                ///< bounding box
    double area_m2 = 0;         ///< clusters: the area of everything in them
    double diameter_m = 0;      ///< bounding-box diagonal
    int parent = -1;
    std::vector<int> children;
    int patch = -1;  ///< root patch of a surface element; −1 for clusters
    int depth = 0;   ///< subdivisions below the root patch
    bool cluster = false;
    bool emits = false;                ///< some emitter is in it
    std::vector<SamplePoint> samples;  ///< receiver points (surfaces: quadrature; clusters: spread)
    Rgb reflectance{0, 0, 0};          ///< surfaces: their material; clusters: the largest inside
    Rgb exitance{0, 0, 0};             ///< emitted, lm/m² (surfaces only)
    Rgb luminaire_irradiance{0, 0, 0};  ///< direct from point luminaires, area average
    Rgb radiosity{0, 0, 0};             ///< current solution; interior nodes: area average
    Rgb gathered{0, 0, 0};              ///< irradiance through this element's own links
    double link_factor_sum = 0;         ///< Σ K over this element's own links
    double radiosity_max = 0;           ///< largest photometric radiosity of any leaf below
    double radiosity_min = 0;           ///< smallest photometric radiosity of any leaf below
    bool leaf() const { return children.empty(); }
};

/// What a surface element sends before any interreflection: its emission plus the luminaires'
/// light it reflects.
inline Rgb source_radiosity(const Element& e) {
    Rgb b;
    for (std::size_t c = 0; c < 3; ++c)
        b[c] = e.exitance[c] + e.reflectance[c] * e.luminaire_irradiance[c];
    return b;
}

class ElementTree {
public:
    /// Roots are the visible patches of `patches`; hidden ones (under coplanar overlays) are
    /// left out. `min_edge_m` stops subdivision.
    ElementTree(const PreparedScene& scene, const PatchMesh& patches, const Visibility& visibility,
                double min_edge_m, std::uint64_t seed);

    std::size_t size() const { return elements_.size(); }
    Element& operator[](std::size_t i) { return elements_[i]; }
    const Element& operator[](std::size_t i) const { return elements_[i]; }
    int top() const { return top_; }

    bool can_subdivide(int e) const;
    /// Splits surface element `e` into its quadtree children (no-op if it has them); they start
    /// with the parent's radiosity and no luminaire light. Not thread-safe.
    void subdivide(int e);

    /// Direct light from the luminaires on the elements from index `first` on (parallel).
    std::uint64_t light_from(std::size_t first);

    /// First guess of the radiosity of the leaves from `first` on, for the linking oracle:
    /// emission plus reflected direct light (luminaires, and emitting patches unoccluded) and an
    /// ambient irradiance; a leaf's maximum and minimum span the guess over its points.
    void estimate_from(std::size_t first, double ambient_irradiance, int channels);

    /// Area-weighted radiosity of interior nodes and the per-node maximum, from the leaves.
    void pull_up(int channels);

    std::size_t leaf_count() const;

    /// Memory the tree holds (elements, their polygons, samples and child lists), in bytes.
    std::size_t bytes() const {
        return footprint_ + (elements_.capacity() - elements_.size()) * sizeof(Element);
    }

private:
    void append(Element&& e);
    int add_surface(std::vector<Vec3> polygon, const Vec3& normal, int patch, int parent,
                    int depth);
    int build_clusters(std::vector<int>& items, std::size_t begin, std::size_t end);
    void light_from_luminaires(Element& e, std::uint64_t& rays) const;
    void pull(int e, int channels, bool keep_leaf_range);
    Rgb emitter_light_at(const Vec3& x, const Vec3& n, int patch) const;
    void fill_bounds(Element& e) const;

    const PreparedScene& scene_;
    const PatchMesh& patches_;
    const Visibility& visibility_;
    double min_edge_m_;
    std::uint64_t seed_;
    std::vector<Element> elements_;
    std::vector<int> emitters_;  // root elements that emit, for the estimates' direct light
    std::size_t footprint_ = 0;  // Σ over elements of what each holds
    int top_ = -1;
};

}  // namespace radiant
