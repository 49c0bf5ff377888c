// A solved mesh as the service stores and streams it: float32 coordinates and radiosities
// (7 significant digits, plenty for display) and int32 indices. One binary blob per finished
// job in the store instead of a JSON text per snapshot, and the JSON arrays of the `mesh` and
// `radiosity` events and of `?include=mesh` are all written from it, so they agree exactly.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "radiant/result.h"

namespace radiant::server {

struct CompactMesh {
    std::vector<float> vertices;                 ///< x, y, z per vertex, metres
    std::vector<std::int32_t> triangles;         ///< three vertex indices per triangle
    std::vector<std::int32_t> triangle_surface;  ///< index into the result's surfaces
    std::vector<float> triangle_radiosity;       ///< lm/m² (luminance for RGB scenes)
    std::vector<float> vertex_radiosity;         ///< lm/m², for Gouraud shading
};

CompactMesh compact(const SolvedMesh& mesh);
/// Back to the engine's form (doubles), e.g. for writing glTF from a stored mesh.
SolvedMesh expand(const CompactMesh& mesh);

/// Little-endian blob: a magic word, five array lengths, then the arrays in field order.
std::string encode(const CompactMesh& mesh);
/// Nothing for a blob that is not one `encode` wrote (wrong magic, lengths or size).
std::optional<CompactMesh> decode(std::string_view blob);

/// `"vertices":[[x,y,z],…],"triangles":[[a,b,c],…],"triangle_surface":[…]` (no braces).
std::string geometry_json(const CompactMesh& mesh);
/// `"triangle_radiosity":[…],"vertex_radiosity":[…]` (no braces).
std::string radiosity_json(const CompactMesh& mesh);

/// The event stream's compact forms of the two above: each array as one base64 string of its
/// little-endian bytes (float32 coordinates and radiosities, int32 indices) — about a third of
/// the decimal text, and a typed array in a browser without parsing numbers.
std::string geometry_base64_json(const CompactMesh& mesh);
std::string radiosity_base64_json(const CompactMesh& mesh);

}  // namespace radiant::server
