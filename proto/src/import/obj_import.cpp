#include "obj_import.h"

#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <map>
#include <sstream>
#include <string_view>

namespace radiant::proto {
namespace {

/// Serves one MTL text for every `mtllib` statement.
class InlineMtl : public tinyobj::MaterialReader {
public:
    explicit InlineMtl(const std::string& text) : text_(text) {}

    bool operator()(const std::string& /*mtl_name*/, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warning,
                    std::string* error) override {
        std::istringstream in(text_);
        tinyobj::LoadMtl(names, materials, &in, warning, error);
        return true;
    }

private:
    const std::string& text_;
};

/// tinyobjloader reads an unparsable coordinate as 0; refuse it instead, with its line.
std::optional<std::string> bad_vertex_line(const std::string& text) {
    std::istringstream lines(text);
    std::string line;
    for (std::size_t number = 1; std::getline(lines, line); ++number) {
        std::istringstream tokens(line);
        std::string keyword, token;
        if (!(tokens >> keyword) || keyword != "v") continue;
        int count = 0;
        while (tokens >> token) {
            double value = 0;
            const auto [end, ec] =
                std::from_chars(token.data(), token.data() + token.size(), value);
            if (ec != std::errc{} || end != token.data() + token.size() || !std::isfinite(value)) {
                return "line " + std::to_string(number) + ": \"" + token +
                       "\" is not a finite number";
            }
            ++count;
        }
        // x y z, optionally w, or x y z r g b (a common vertex-colour extension).
        if (count < 3 || count == 5 || count > 7) {
            return "line " + std::to_string(number) + ": a vertex needs 3 coordinates";
        }
    }
    return std::nullopt;
}

/// The first line of a tinyobjloader message, with "line N: " in front when it names a line.
std::string tidy(const std::string& message) {
    std::string first = message.substr(0, message.find('\n'));
    const std::size_t at = first.rfind("line ");
    if (at == std::string::npos) return first;
    std::size_t end = at + 5;
    while (end < first.size() && std::isdigit(static_cast<unsigned char>(first[end]))) ++end;
    if (end == at + 5) return first;
    return first.substr(at, end - at) + ": " + first;
}

/// The warnings that explain missing materials (an MTL file not found, an unknown usemtl name).
std::string material_warnings(const std::string& warnings) {
    std::istringstream lines(warnings);
    std::string line, out;
    while (std::getline(lines, line)) {
        if (line.find("aterial") != std::string::npos) out += (out.empty() ? "" : "; ") + line;
    }
    return out.empty() ? "" : " (" + out + ")";
}

}  // namespace

ImportOutcome import_obj(const std::string& obj_text, const MtlSource& mtl,
                         const ImportBudget& budget) {
    if (auto bad = bad_vertex_line(obj_text)) return *bad;
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warning, error;
    std::istringstream in(obj_text);
    std::optional<InlineMtl> inline_mtl;
    std::optional<tinyobj::MaterialFileReader> file_mtl;
    tinyobj::MaterialReader* reader = nullptr;
    if (mtl.text) {
        reader = &inline_mtl.emplace(*mtl.text);
    } else if (mtl.directory) {
        reader = &file_mtl.emplace(mtl.directory->string());
    }
    if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &in, reader,
                          /*triangulate=*/false, /*default_vcols_fallback=*/false)) {
        return tidy(error.empty() ? "the OBJ text cannot be read" : error);
    }
    if (!error.empty()) return tidy(error);

    const std::size_t vertex_count = attrib.vertices.size() / 3;
    std::size_t face_count = 0;
    for (const auto& shape : shapes) face_count += shape.mesh.num_face_vertices.size();
    // A vertex may be copied into each part that uses it; the file's own count is the floor.
    if (auto refused = budget.refuse(vertex_count, face_count)) return *refused;
    ImportedGeometry out;
    for (const auto& m : materials) {
        out.materials.push_back({m.name, Rgb{m.diffuse[0], m.diffuse[1], m.diffuse[2]}});
    }
    // One part per material id (-1: none), vertices renumbered per part.
    std::map<int, std::size_t> part_of_material;
    std::vector<std::map<int, int>> renumbered;
    std::size_t face_number = 0;
    for (const auto& shape : shapes) {
        std::size_t next = 0;
        for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++face_number) {
            const int material = shape.mesh.material_ids[f];
            auto [it, added] = part_of_material.try_emplace(material, out.parts.size());
            if (added) {
                auto& part = out.parts.emplace_back();
                if (material >= 0) part.material = static_cast<std::size_t>(material);
                renumbered.emplace_back();
            }
            ImportedPart& part = out.parts[it->second];
            std::map<int, int>& numbers = renumbered[it->second];
            std::vector<int>& face = part.mesh.faces.emplace_back();
            for (unsigned k = 0; k < shape.mesh.num_face_vertices[f]; ++k, ++next) {
                const int v = shape.mesh.indices[next].vertex_index;
                if (v < 0 || static_cast<std::size_t>(v) >= vertex_count) {
                    return "face " + std::to_string(face_number + 1) + " refers to vertex " +
                           std::to_string(v + 1) + ", but the file has " +
                           std::to_string(vertex_count) + " vertices";
                }
                const auto [slot, is_new] =
                    numbers.try_emplace(v, static_cast<int>(part.mesh.vertices.size()));
                if (is_new) {
                    const auto at = 3 * static_cast<std::size_t>(v);
                    part.mesh.vertices.push_back(
                        {attrib.vertices[at], attrib.vertices[at + 1], attrib.vertices[at + 2]});
                }
                face.push_back(slot->second);
            }
        }
    }
    if (out.parts.empty()) return std::string("the OBJ text has no faces");
    std::size_t part_vertices = 0;
    for (const ImportedPart& part : out.parts) part_vertices += part.mesh.vertices.size();
    if (auto refused = budget.refuse(part_vertices, face_count)) return *refused;
    out.material_notes = material_warnings(warning);
    return out;
}

}  // namespace radiant::proto
