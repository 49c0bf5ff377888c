// Geometry read from an OBJ or glTF file, before it becomes scene surfaces: one mesh per material
// of the file, in the scene's length unit, counter-clockwise front faces.
#pragma once

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "radiant/scene.h"

namespace radiant::proto {

/// A material as the file states it (MTL `Kd`, glTF `baseColorFactor`): linear RGB reflectance.
struct ImportedMaterial {
    std::string name;
    Rgb reflectance{0, 0, 0};
};

/// The faces of the file that share one material.
struct ImportedPart {
    std::optional<std::size_t> material;  ///< index into ImportedGeometry::materials; none given
    MeshGeometry mesh;
};

struct ImportedGeometry {
    std::vector<ImportedMaterial> materials;
    std::vector<ImportedPart> parts;  ///< never empty
    std::string material_notes;       ///< why faces may lack a material, e.g. an MTL not found
};

/// The geometry, or why the file cannot be used ("line 17: ...", "mesh \"desk\": ...").
using ImportOutcome = std::variant<ImportedGeometry, std::string>;

}  // namespace radiant::proto
