// A scene surface whose geometry comes from an OBJ or glTF model instead of polygon/mesh/box:
// reads the model (inline or from a file next to the scene) and turns it into engine surfaces.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "imported_geometry.h"
#include "radiant/scene.h"

namespace radiant::proto {

/// The surface key that names the model: "obj" (OBJ text), "obj_file" (path), "gltf" (base64
/// .glb), "gltf_file" (path to a .glb or .gltf).
enum class ImportKind { obj, obj_file, gltf, gltf_file };

struct ImportRequest {
    ImportKind kind = ImportKind::obj;
    std::string value;                    ///< the key's string
    std::optional<std::string> mtl;       ///< "mtl": MTL text for an OBJ's mtllib statements
    std::string name;                     ///< the surface's name
    std::optional<std::string> material;  ///< the surface's "material": overrides the model's
    LengthUnit unit = LengthUnit::m;      ///< the scene's
    std::optional<std::filesystem::path> scene_directory;  ///< none: file keys are refused
    std::size_t max_bytes = 0;                             ///< largest model file read
    ImportBudget budget;  ///< what is left of the scene's vertex and face limits
};

/// The engine surfaces (one per material of the model, or one with the override material) and
/// the materials made from the model's own (named "<surface>/<model material>").
struct ImportedSurfaces {
    std::vector<Surface> surfaces;
    std::vector<Material> materials;
};

/// The surfaces, or the problem as a message for the key's pointer ("line 17: ...").
std::variant<ImportedSurfaces, std::string> import_surface(const ImportRequest& request);

}  // namespace radiant::proto
