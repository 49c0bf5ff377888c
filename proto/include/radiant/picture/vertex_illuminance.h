// Illuminance (lux) at the vertices of a solved mesh, for false-colour pictures. The mesh carries
// radiosity B; on a surface that does not emit, B = ρ·E, so E follows B's shape scaled by the
// surface's own Ē/B̄ (exact for gray surfaces, exact on average for coloured ones). Emitting or
// black surfaces show their average irradiance, since B there says nothing about E.
#pragma once

#include <vector>

#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant::picture {

/// One value per SolvedMesh vertex; requires result.mesh.
std::vector<double> vertex_illuminance(const Result& result, const Scene& scene);

}  // namespace radiant::picture
