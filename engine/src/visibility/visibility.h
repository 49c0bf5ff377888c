// Visibility between points: the interface, and the two implementations (Embree 3 for solves,
// brute force as the test oracle). Geometry is given once as triangles in the engine's local
// frame (metres, centred near the origin) and never changes afterwards.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "radiant/vec3.h"

namespace radiant {

struct Triangle {
    Vec3 a, b, c;
};

/// A segment query: is the open segment from `from` to `to` free of any triangle?
/// Callers offset both endpoints off their surfaces along the surface normals by `epsilon()`.
struct SegmentQuery {
    Vec3 from;
    Vec3 to;
};

struct RayHit {
    int triangle = -1;
    double t = 0;
};

class Visibility {
public:
    virtual ~Visibility() = default;

    /// True when no triangle intersects the segment strictly between its endpoints (a tiny
    /// relative margin at `to` is excluded, so the target surface itself never blocks).
    /// Thread-safe.
    virtual bool visible(const Vec3& from, const Vec3& to) const = 0;

    /// Batched form of `visible`: out[i] = 1 when queries[i] is unblocked, else 0.
    /// Implementations may use packets. Thread-safe.
    virtual void visible_batch(std::span<const SegmentQuery> queries,
                               std::span<std::uint8_t> out) const;

    /// The first triangle hit by the ray origin + t·direction for t in (0, t_max]: its index
    /// (into the constructor's triangle list) and t, or triangle −1. `direction` need not be
    /// unit length. Thread-safe.
    virtual RayHit intersect(const Vec3& origin, const Vec3& direction, double t_max) const = 0;

    /// Index of the first triangle hit (see intersect), or −1.
    int first_hit(const Vec3& origin, const Vec3& direction, double t_max) const {
        return intersect(origin, direction, t_max).triangle;
    }

    /// Offset (metres) to lift ray endpoints off surfaces: scale-aware, see ray_epsilon().
    double epsilon() const { return epsilon_; }

protected:
    explicit Visibility(double epsilon) : epsilon_(epsilon) {}

private:
    double epsilon_;
};

/// True for triangles no implementation can hit: a non-finite vertex or (near) zero area,
/// |(b−a)×(c−a)| ≤ 1e-12 · (longest edge)². Both implementations skip exactly these, so
/// their answers stay comparable; indices of the remaining triangles are unchanged.
bool is_degenerate(const Triangle& t);

/// max(1e-6 · scene diagonal, 32 float ulps of the largest coordinate): large enough to avoid
/// self-hits with Embree's single-precision rays, small enough for millimetre features.
double ray_epsilon(std::span<const Triangle> triangles);

/// Embree 3 implementation (one committed scene; queries from many threads).
std::unique_ptr<Visibility> make_embree_visibility(std::span<const Triangle> triangles);

/// Double-precision brute-force implementation: O(triangles) per query; the tests' oracle.
std::unique_ptr<Visibility> make_brute_force_visibility(std::span<const Triangle> triangles);

}  // namespace radiant
