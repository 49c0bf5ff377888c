// glTF 2.0 (.glb, or .gltf JSON) → ImportedGeometry, with tinygltf.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "imported_geometry.h"

namespace radiant::proto {

/// Triangle primitives (triangles, strips, fans; indexed or not) of the default scene's nodes,
/// node transforms applied, converted from glTF's y-up metres to the scene's z-up `unit`. A
/// material's reflectance is its baseColorFactor (textures are ignored), and `doubleSided` makes
/// it two-sided. External files (a .gltf's buffers) are read from `directory` only when it is
/// given; otherwise refused.
/// The node graph is walked without recursion, and the JSON is checked against a JsonBudget
/// before tinygltf (whose reader recurses) sees it. Refused when it exceeds `budget`.
ImportOutcome import_gltf(const std::vector<unsigned char>& bytes, LengthUnit unit,
                          const std::optional<std::filesystem::path>& directory,
                          const ImportBudget& budget);

}  // namespace radiant::proto
