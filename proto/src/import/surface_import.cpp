#include "surface_import.h"

#include <cmath>
#include <map>
#include <set>

#include "gltf_import.h"
#include "obj_import.h"
#include "radiant/proto/base64.h"
#include "scene_relative_file.h"

namespace radiant::proto {
namespace {

/// Reads a model file named relative to the scene file; returns the problem, if any.
std::optional<std::string> read_model_file(const ImportRequest& r, std::filesystem::path& path,
                                           std::string& bytes) {
    if (r.scene_directory) path = *r.scene_directory / r.value;
    return read_scene_relative_file(r.scene_directory, r.value, r.max_bytes, bytes);
}

ImportOutcome read_model(const ImportRequest& r) {
    std::filesystem::path path;
    std::string bytes;
    switch (r.kind) {
        case ImportKind::obj:
            return import_obj(r.value, {r.mtl, std::nullopt}, r.budget);
        case ImportKind::gltf: {
            const auto glb = decode_base64(r.value);
            if (!glb) return std::string("gltf must be a base64-encoded .glb file");
            return import_gltf(*glb, r.unit, std::nullopt, r.budget);
        }
        case ImportKind::obj_file: {
            if (auto problem = read_model_file(r, path, bytes)) return *problem;
            return import_obj(bytes, {r.mtl, path.parent_path()}, r.budget);
        }
        case ImportKind::gltf_file: {
            if (auto problem = read_model_file(r, path, bytes)) return *problem;
            return import_gltf({bytes.begin(), bytes.end()}, r.unit, path.parent_path(), r.budget);
        }
    }
    return std::string("unknown import kind");
}

void append(MeshGeometry& to, const MeshGeometry& from) {
    const int offset = static_cast<int>(to.vertices.size());
    to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
    for (std::vector<int> face : from.faces) {
        for (int& v : face) v += offset;
        to.faces.push_back(std::move(face));
    }
}

}  // namespace

std::variant<ImportedSurfaces, std::string> import_surface(const ImportRequest& request) {
    ImportOutcome read = read_model(request);
    if (auto* problem = std::get_if<std::string>(&read)) return *problem;
    const ImportedGeometry& model = std::get<ImportedGeometry>(read);
    ImportedSurfaces out;
    if (request.material) {
        Surface& s = out.surfaces.emplace_back();
        s.name = request.name;
        s.material = *request.material;
        MeshGeometry mesh;
        for (const ImportedPart& part : model.parts) append(mesh, part.mesh);
        s.geometry = std::move(mesh);
        return out;
    }
    std::set<std::string> names;
    std::map<std::string, std::size_t> repeats;  ///< per name: how often it was taken
    for (const ImportedPart& part : model.parts) {
        if (!part.material) {
            return "some faces have no material in the model; give the surface a \"material\"" +
                   model.material_notes;
        }
        const ImportedMaterial& m = model.materials[*part.material];
        for (const double r : m.reflectance) {
            if (!(std::isfinite(r) && r >= 0 && r < 1)) {
                return "material \"" + m.name + "\" has a reflectance of " + std::to_string(r) +
                       ", outside [0, 1); give the surface a \"material\" to override it";
            }
        }
        std::string name = request.name + "/" + m.name;
        if (!names.insert(name).second) {
            // Numbered, not primed: many materials of one name must not grow names quadratically.
            std::size_t& taken = repeats[name];
            std::string numbered;
            do {
                numbered = name + " (" + std::to_string(++taken + 1) + ")";
            } while (!names.insert(numbered).second);
            name = std::move(numbered);
        }
        Material& material = out.materials.emplace_back();
        material.name = name;
        material.reflectance = m.reflectance;
        material.rgb_reflectance =
            m.reflectance[0] != m.reflectance[1] || m.reflectance[1] != m.reflectance[2];
        material.two_sided = m.two_sided;
        Surface& s = out.surfaces.emplace_back();
        s.name = model.parts.size() == 1 ? request.name : name;
        s.material = name;
        s.geometry = part.mesh;
    }
    return out;
}

}  // namespace radiant::proto
