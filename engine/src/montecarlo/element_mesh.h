// The Monte Carlo path's elements: every piece of the prepared scene cut into triangles no
// longer than a target edge (shorter near lamps, see ElementSizing): a narrow piece (a
// board's edge, a rack's beam) as a strip of cells along it, two triangles each, any other by
// bisecting longest edges. Rays find an element by its triangle index, so looking up what a ray
// lands on costs nothing beyond the ray itself.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "scene/prepared_scene.h"
#include "visibility/visibility.h"

namespace radiant {

struct MeshElement {
    Triangle triangle;  ///< counter-clockwise about `normal`, local frame, metres
    Vec3 normal;        ///< unit, the front side
    double area_m2 = 0;
    int piece = 0;
    int surface = 0;
    int material = 0;
    /// The other half of the bisection or strip cell that made this element, when that half was
    /// not split further, else −1: the two make the coarser level the discretisation estimate
    /// reads.
    int sibling = -1;
    int front = -1;  ///< index of its front side among the sides
    int back = -1;   ///< of its back side; −1 when the back is black (one-sided material)
};

/// One side of an element that light can land on and leave.
struct ElementSide {
    int element = 0;
    bool back = false;
    /// The part of the element's area that light reaches on this side (see measure_open_areas):
    /// the photons' flux is spread over it, not over the part a surface right in front hides.
    double open_area_m2 = 0;
};

/// How long an element's edges may be: `max_edge_m`, and nearer than `light_reach_m` to a
/// compact light (a luminaire; an emitting surface at most half the reach across, or within a
/// quarter of it of a segment along it: a strip light) that times its distance over the reach,
/// down to kFinest of it. A lamp's light, and what its shade and the table under it reflect,
/// varies over its distance from it, not over the room's free path: a lounge's points beside
/// table lamps read their shades' element averages 0.7 % bright at the free path's elements,
/// which no estimate of a few such points tells from noise. What lies wholly behind a light that
/// shines to one side only (a downlight dark above the horizontal, a flat emitter) keeps
/// `max_edge_m`.
struct ElementSizing {
    static constexpr double kFinest = 1.0 / 8;
    double max_edge_m = 0;
    double light_reach_m = 0;  ///< 0: the same edge everywhere
};

struct ElementCount {
    std::size_t elements = 0;
    std::size_t sides = 0;  ///< two per element of a two-sided material, else one
};

class ElementMesh {
public:
    /// What ElementMesh(scene, sizing) would hold, without holding it.
    static ElementCount count(const PreparedScene& scene, const ElementSizing& sizing);
    /// Cuts every piece of `scene` to edges as `sizing` asks. Linear in the output. Once `stop`
    /// says so (a time limit, a cancel) it holds no elements. `counted` is what count(scene,
    /// sizing) said, where the caller has it; else the pieces are counted here first.
    ElementMesh(const PreparedScene& scene, const ElementSizing& sizing,
                const std::function<bool()>& stop = {},
                std::optional<ElementCount> counted = std::nullopt);

    std::size_t size() const { return elements_.size(); }
    const MeshElement& operator[](std::size_t i) const { return elements_[i]; }
    const std::vector<MeshElement>& elements() const { return elements_; }
    const std::vector<ElementSide>& sides() const { return sides_; }

    /// One triangle per element for the ray tracer (index = element).
    std::vector<Triangle> triangles() const;

    /// Each side's open area, from four points of its element, each looking along the side's
    /// normal on `visibility` (over triangles()): a point is hidden when a surface lies within
    /// `near_m` in front of it (a ceiling panel hung 1 cm under the ceiling, a book against its
    /// neighbour, a cabinet's bottom on the floor). A surface farther away hides nothing, even
    /// by its black back: a ceiling wound the wrong way must not darken the floor. Counts the
    /// rays.
    void measure_open_areas(const Visibility& visibility, double near_m, std::uint64_t& rays);

    /// The side a ray travelling along `direction` lands on when it hits `element`: its front
    /// when it arrives against the normal, else its back (−1 if black).
    int side_hit(int element, const Vec3& direction) const {
        const MeshElement& e = elements_[static_cast<std::size_t>(element)];
        return dot(direction, e.normal) < 0 ? e.front : e.back;
    }
    /// Unit normal of a side: the element's, reversed for a back side.
    Vec3 side_normal(int side) const {
        const ElementSide& s = sides_[static_cast<std::size_t>(side)];
        const Vec3 n = elements_[static_cast<std::size_t>(s.element)].normal;
        return s.back ? -n : n;
    }

private:
    std::vector<MeshElement> elements_;
    std::vector<ElementSide> sides_;
};

}  // namespace radiant
