// Quadrature points on convex planar polygons (triangles, quads, split patches).
#pragma once

#include <span>
#include <vector>

#include "radiant/vec3.h"

namespace radiant {

struct QuadraturePoint {
    Vec3 position;
    double weight;  ///< m²; the weights of one polygon sum to its area
};

/// Points strictly inside a convex planar polygon integrating polynomials of degree `degree`
/// (1..5) exactly over it; quads use a tensor Gauss–Legendre rule on the bilinear map,
/// other polygons a Dunavant rule on a fan of triangles. No point lies on an edge.
std::vector<QuadraturePoint> polygon_quadrature(std::span<const Vec3> polygon, int degree);

/// `n` stratified points inside a convex polygon, area-uniform, jittered by the unit-square
/// samples `u` (pairs in [0,1)², size 2n); used as shadow-ray targets. Deterministic in `u`.
std::vector<Vec3> stratified_points(std::span<const Vec3> polygon, int n,
                                    std::span<const double> u);

/// Area (m²) and unit normal (Newell's method, robust for slightly non-planar input).
double polygon_area(std::span<const Vec3> polygon);
Vec3 polygon_normal(std::span<const Vec3> polygon);
Vec3 polygon_centroid(std::span<const Vec3> polygon);

}  // namespace radiant
