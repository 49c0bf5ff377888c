// Wavefront OBJ (+ MTL) → ImportedGeometry, with tinyobjloader.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "imported_geometry.h"

namespace radiant::proto {

/// What answers the OBJ's `mtllib` statements: inline MTL text (whatever file name they give),
/// else MTL files in `directory` (the OBJ file's own), else nothing (faces have no material).
struct MtlSource {
    std::optional<std::string> text;
    std::optional<std::filesystem::path> directory;
};

/// Faces keep their polygons (no triangulation) and their orientation; coordinates are taken in
/// the scene's unit. A material's reflectance is its `Kd`. Errors name the OBJ line when known.
/// Refused when the file's vertices or faces exceed `budget`.
ImportOutcome import_obj(const std::string& obj_text, const MtlSource& mtl,
                         const ImportBudget& budget);

}  // namespace radiant::proto
