// Geometry read from an OBJ or glTF file, before it becomes scene surfaces: one mesh per material
// of the file, in the scene's length unit, counter-clockwise front faces.
#pragma once

#include <cstddef>
#include <limits>
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
    bool two_sided = false;  ///< glTF `doubleSided`: the back is lit and reflects as the front
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

/// The most geometry an import may produce: what is left of the scene's limits (SceneLimits).
/// Readers check it before they expand each part, since a glTF mesh instanced by many nodes
/// multiplies its triangles.
struct ImportBudget {
    std::size_t max_vertices = std::numeric_limits<std::size_t>::max();
    std::size_t max_faces = std::numeric_limits<std::size_t>::max();

    /// Why `vertices` and `faces` in all do not fit, if they do not.
    std::optional<std::string> refuse(std::size_t vertices, std::size_t faces) const {
        if (vertices > max_vertices) {
            return "the model has more than " + std::to_string(max_vertices) +
                   " vertices, what is left of the scene's limit";
        }
        if (faces > max_faces) {
            return "the model has more than " + std::to_string(max_faces) +
                   " faces, what is left of the scene's limit";
        }
        return std::nullopt;
    }
};

/// The geometry, or why the file cannot be used ("line 17: ...", "mesh \"desk\": ...").
using ImportOutcome = std::variant<ImportedGeometry, std::string>;

}  // namespace radiant::proto
