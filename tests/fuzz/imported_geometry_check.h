// What the OBJ and glTF targets check of an import: what it promises the scene mapping (faces
// index their part's vertices, materials exist, the budget holds).
#pragma once

#include <cstddef>
#include <string>

#include "import/imported_geometry.h"

namespace radiant::fuzz {

/// The scene defaults (SceneLimits, ParseLimits::max_faces): what a client's scene may import.
inline const proto::ImportBudget kBudget{2000000, 4000000};

inline void check_geometry(const proto::ImportOutcome& outcome) {
    const auto* geometry = std::get_if<proto::ImportedGeometry>(&outcome);
    if (!geometry) return;  // refused with a message
    if (geometry->parts.empty()) __builtin_trap();
    std::size_t vertices = 0, faces = 0;
    for (const proto::ImportedPart& part : geometry->parts) {
        if (part.material && *part.material >= geometry->materials.size()) __builtin_trap();
        for (const auto& face : part.mesh.faces) {
            for (const int v : face) {
                if (v < 0 || static_cast<std::size_t>(v) >= part.mesh.vertices.size()) {
                    __builtin_trap();
                }
            }
        }
        vertices += part.mesh.vertices.size();
        faces += part.mesh.faces.size();
    }
    if (kBudget.refuse(vertices, faces)) __builtin_trap();
}

}  // namespace radiant::fuzz
