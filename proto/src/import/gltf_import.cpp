#include "gltf_import.h"

#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "gltf_axes.h"
#include "json_text.h"

namespace radiant::proto {
namespace {

using Mat4 = std::array<double, 16>;  // column-major, as glTF stores it

constexpr Mat4 kIdentity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Mat4 multiply(const Mat4& a, const Mat4& b) {
    Mat4 c{};
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
            for (int k = 0; k < 4; ++k) c[col * 4 + row] += a[k * 4 + row] * b[col * 4 + k];
    return c;
}

/// The node's local matrix: `matrix`, else translation · rotation · scale.
Mat4 local_matrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        Mat4 m;
        std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
        return m;
    }
    Mat4 m = kIdentity;
    if (node.rotation.size() == 4) {
        const double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2],
                     w = node.rotation[3];
        m = {1 - 2 * (y * y + z * z),
             2 * (x * y + z * w),
             2 * (x * z - y * w),
             0,
             2 * (x * y - z * w),
             1 - 2 * (x * x + z * z),
             2 * (y * z + x * w),
             0,
             2 * (x * z + y * w),
             2 * (y * z - x * w),
             1 - 2 * (x * x + y * y),
             0,
             0,
             0,
             0,
             1};
    }
    if (node.scale.size() == 3) {
        for (int col = 0; col < 3; ++col)
            for (int row = 0; row < 3; ++row) m[col * 4 + row] *= node.scale[col];
    }
    if (node.translation.size() == 3) {
        for (int row = 0; row < 3; ++row) m[12 + row] = node.translation[row];
    }
    return m;
}

Vec3 transform(const Mat4& m, const Vec3& p) {
    return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12],
            m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
            m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
}

double determinant3(const Mat4& m) {
    return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) +
           m[8] * (m[1] * m[6] - m[5] * m[2]);
}

/// Refuses every file access: inline models must be self-contained.
tinygltf::FsCallbacks no_files() {
    tinygltf::FsCallbacks fs{};
    fs.FileExists = [](const std::string&, void*) { return false; };
    fs.ExpandFilePath = [](const std::string& path, void*) { return path; };
    fs.ReadWholeFile = [](std::vector<unsigned char>*, std::string* err, const std::string& path,
                          void*) {
        if (err) *err += "an inline glTF cannot refer to the file \"" + path + "\"\n";
        return false;
    };
    fs.WriteWholeFile = [](std::string*, const std::string&, const std::vector<unsigned char>&,
                           void*) { return false; };
    return fs;
}

class Reader {
public:
    Reader(const tinygltf::Model& model, double units_per_metre, const ImportBudget& budget)
        : model_(model), units_per_metre_(units_per_metre), budget_(budget) {}

    /// Empty on success, else the problem.
    std::string read_scene(ImportedGeometry& out);

private:
    std::string node(int index, const Mat4& m, ImportedGeometry& out);
    std::string primitive(const tinygltf::Primitive& p, const Mat4& m, const std::string& where,
                          ImportedGeometry& out);
    /// Start of element k of an accessor after bounds checks, or an error.
    std::string view(int accessor, int type, std::size_t element_size, const char* what,
                     const unsigned char*& base, std::size_t& stride, std::size_t& count);

    const tinygltf::Model& model_;
    double units_per_metre_;
    const ImportBudget& budget_;
    std::size_t vertices_ = 0, faces_ = 0;  ///< expanded so far, against budget_
    std::map<int, std::size_t> part_of_material_;
};

std::string Reader::read_scene(ImportedGeometry& out) {
    if (!model_.extensionsRequired.empty()) {
        return "the glTF requires the extension " + model_.extensionsRequired.front() +
               ", which is not supported";
    }
    if (model_.scenes.empty()) return "the glTF has no scene";
    const auto scene = static_cast<std::size_t>(model_.defaultScene);
    const tinygltf::Scene& s = model_.scenes[scene < model_.scenes.size() ? scene : 0];
    for (const auto& m : model_.materials) {
        const auto& f = m.pbrMetallicRoughness.baseColorFactor;
        out.materials.push_back(
            {m.name.empty() ? "material " + std::to_string(out.materials.size()) : m.name,
             f.size() >= 3 ? Rgb{f[0], f[1], f[2]} : Rgb{1, 1, 1}, m.doubleSided});
    }
    // Depth first with an explicit stack: a chain of nodes as long as the file allows must not
    // recurse once per node. Each node is visited at most once, so the walk ends.
    std::vector<std::pair<int, Mat4>> pending;
    for (auto it = s.nodes.rbegin(); it != s.nodes.rend(); ++it)
        pending.emplace_back(*it, kIdentity);
    std::vector<bool> visited(model_.nodes.size(), false);
    while (!pending.empty()) {
        const auto [index, parent] = pending.back();
        pending.pop_back();
        if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size())
            return "node " + std::to_string(index) + " does not exist";
        if (visited[static_cast<std::size_t>(index)])
            return "node " + std::to_string(index) + " appears twice in the scene's node tree";
        visited[static_cast<std::size_t>(index)] = true;
        const tinygltf::Node& n = model_.nodes[static_cast<std::size_t>(index)];
        const Mat4 m = multiply(parent, local_matrix(n));
        if (std::string e = node(index, m, out); !e.empty()) return e;
        for (auto it = n.children.rbegin(); it != n.children.rend(); ++it) {
            pending.emplace_back(*it, m);
        }
    }
    if (out.parts.empty()) return "the glTF scene has no triangles";
    return {};
}

/// The mesh of node `index`, if it has one, with the node's world matrix `m`.
std::string Reader::node(int index, const Mat4& m, ImportedGeometry& out) {
    const tinygltf::Node& n = model_.nodes[static_cast<std::size_t>(index)];
    if (n.mesh < 0) return {};
    if (static_cast<std::size_t>(n.mesh) >= model_.meshes.size())
        return "node " + std::to_string(index) + " refers to a missing mesh";
    const tinygltf::Mesh& mesh = model_.meshes[static_cast<std::size_t>(n.mesh)];
    const std::string name =
        "mesh \"" + (mesh.name.empty() ? std::to_string(n.mesh) : mesh.name) + "\"";
    for (std::size_t k = 0; k < mesh.primitives.size(); ++k) {
        const std::string where = name + " primitive " + std::to_string(k);
        if (std::string e = primitive(mesh.primitives[k], m, where, out); !e.empty()) return e;
    }
    return {};
}

std::string Reader::view(int accessor, int type, std::size_t element_size, const char* what,
                         const unsigned char*& base, std::size_t& stride, std::size_t& count) {
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= model_.accessors.size())
        return std::string(what) + " accessor does not exist";
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(accessor)];
    if (a.sparse.isSparse) return std::string(what) + " accessor is sparse (not supported)";
    if (a.type != type) return std::string(what) + " accessor has the wrong type";
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model_.bufferViews.size())
        return std::string(what) + " accessor has no buffer view";
    const tinygltf::BufferView& v = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= model_.buffers.size())
        return std::string(what) + " buffer view has no buffer";
    const std::vector<unsigned char>& data =
        model_.buffers[static_cast<std::size_t>(v.buffer)].data;
    stride = v.byteStride ? v.byteStride : element_size;
    count = a.count;
    const bool fits =
        v.byteOffset <= data.size() && v.byteLength <= data.size() - v.byteOffset &&
        stride >= element_size && a.byteOffset <= v.byteLength &&
        (count == 0 || ((count - 1) <= (v.byteLength - a.byteOffset) / stride &&
                        (count - 1) * stride + element_size <= v.byteLength - a.byteOffset));
    if (!fits) return std::string(what) + " accessor runs past the end of its buffer";
    base = data.data() + v.byteOffset + a.byteOffset;
    return {};
}

std::string Reader::primitive(const tinygltf::Primitive& p, const Mat4& m, const std::string& where,
                              ImportedGeometry& out) {
    if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        p.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        return where + ": mode " + std::to_string(p.mode) + " is not a triangle mode";
    }
    const auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) return where + ": no POSITION attribute";
    const unsigned char* base = nullptr;
    std::size_t stride = 0, count = 0;
    if (std::string e =
            view(position->second, TINYGLTF_TYPE_VEC3, 12, "POSITION", base, stride, count);
        !e.empty()) {
        return where + ": " + e;
    }
    if (model_.accessors[static_cast<std::size_t>(position->second)].componentType !=
        TINYGLTF_COMPONENT_TYPE_FLOAT) {
        return where + ": POSITION must be float";
    }
    // Before anything is copied: nodes that instance one mesh multiply its vertices.
    vertices_ += count;
    if (auto refused = budget_.refuse(vertices_, faces_)) return *refused;
    std::vector<Vec3> points(count);
    for (std::size_t k = 0; k < count; ++k) {
        float xyz[3];
        std::memcpy(xyz, base + k * stride, sizeof xyz);
        points[k] = from_gltf_axes(transform(m, {xyz[0], xyz[1], xyz[2]})) * units_per_metre_;
    }
    // Faces count against the budget before the indices are copied.
    const auto count_faces = [&](std::size_t n) {
        faces_ += p.mode == TINYGLTF_MODE_TRIANGLES ? n / 3 : (n > 2 ? n - 2 : 0);
        return budget_.refuse(vertices_, faces_);
    };
    std::vector<std::uint32_t> indices;
    if (p.indices >= 0) {
        const auto& a = model_.accessors.size() > static_cast<std::size_t>(p.indices)
                            ? model_.accessors[static_cast<std::size_t>(p.indices)]
                            : tinygltf::Accessor{};
        const std::size_t size = a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                                 : a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                                 : a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                             : 0;
        if (size == 0) return where + ": indices must be unsigned integers";
        std::size_t index_count = 0;
        if (std::string e =
                view(p.indices, TINYGLTF_TYPE_SCALAR, size, "indices", base, stride, index_count);
            !e.empty()) {
            return where + ": " + e;
        }
        if (auto refused = count_faces(index_count)) return *refused;
        indices.resize(index_count);
        for (std::size_t k = 0; k < index_count; ++k) {
            std::uint32_t value = 0;
            if (size == 1) value = base[k * stride];
            if (size == 2) {
                std::uint16_t v16;
                std::memcpy(&v16, base + k * stride, 2);
                value = v16;
            }
            if (size == 4) std::memcpy(&value, base + k * stride, 4);
            if (value >= count) {
                return where + ": index " + std::to_string(value) + " is out of range (" +
                       std::to_string(count) + " vertices)";
            }
            indices[k] = value;
        }
    } else {
        if (auto refused = count_faces(count)) return *refused;
        indices.resize(count);
        for (std::size_t k = 0; k < count; ++k) indices[k] = static_cast<std::uint32_t>(k);
    }

    const std::size_t n = indices.size();
    const auto [slot, added] = part_of_material_.try_emplace(p.material, out.parts.size());
    if (added) {
        ImportedPart& part = out.parts.emplace_back();
        if (p.material >= 0) {
            if (static_cast<std::size_t>(p.material) >= out.materials.size())
                return where + ": material " + std::to_string(p.material) + " does not exist";
            part.material = static_cast<std::size_t>(p.material);
        }
    }
    MeshGeometry& mesh = out.parts[slot->second].mesh;
    const int offset = static_cast<int>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), points.begin(), points.end());
    const bool mirrored = determinant3(m) < 0;
    auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (a == b || b == c || a == c) return;  // degenerate by construction (strip stitching)
        if (mirrored) std::swap(b, c);
        mesh.faces.push_back({offset + static_cast<int>(a), offset + static_cast<int>(b),
                              offset + static_cast<int>(c)});
    };
    if (p.mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3 != 0) return where + ": the vertex count is not a multiple of 3";
        for (std::size_t k = 0; k + 2 < n; k += 3) add(indices[k], indices[k + 1], indices[k + 2]);
    } else if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t k = 0; k + 2 < n; ++k) {
            if (k % 2 == 0)
                add(indices[k], indices[k + 1], indices[k + 2]);
            else
                add(indices[k + 1], indices[k], indices[k + 2]);
        }
    } else {
        for (std::size_t k = 1; k + 1 < n; ++k) add(indices[0], indices[k], indices[k + 1]);
    }
    return {};
}

/// The JSON part of a glTF file: all of a .gltf, the first chunk of a .glb (when it is JSON).
std::string_view json_part(const std::vector<unsigned char>& bytes) {
    const std::string_view all(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    if (!all.starts_with("glTF")) return all;
    constexpr std::size_t kHeader = 12, kChunkHeader = 8;
    if (bytes.size() < kHeader + kChunkHeader || all.substr(16, 4) != "JSON") return {};
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + kHeader, sizeof length);
    return all.substr(kHeader + kChunkHeader, length);
}

}  // namespace

ImportOutcome import_gltf(const std::vector<unsigned char>& bytes, LengthUnit unit,
                          const std::optional<std::filesystem::path>& directory,
                          const ImportBudget& budget) {
    if (bytes.size() > std::numeric_limits<unsigned>::max()) return std::string("file too large");
    // tinygltf reads extras and extensions recursively: bound the nesting before it parses.
    if (const std::string_view json = json_part(bytes); !json.empty()) {
        if (auto refused = check_json_text(json)) {
            return "the glTF's JSON at " +
                   (refused->problem.pointer.empty() ? std::string("its start")
                                                     : refused->problem.pointer) +
                   ": " + refused->problem.message;
        }
    }
    tinygltf::TinyGLTF loader;
    if (!directory) loader.SetFsCallbacks(no_files());
    // Only geometry and material factors are used: images are neither decoded nor checked.
    loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int,
                             const unsigned char*, int, void*) { return true; },
                          nullptr);
    tinygltf::Model model;
    std::string error, warning;
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    const std::string base = directory ? directory->string() : "";
    const auto size = static_cast<unsigned>(bytes.size());
    const bool ok =
        binary
            ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), size, base)
            : loader.LoadASCIIFromString(&model, &error, &warning,
                                         reinterpret_cast<const char*>(bytes.data()), size, base);
    if (!ok) {
        error = error.substr(0, error.find('\n'));
        return error.empty() ? "not a glTF 2.0 file" : error;
    }
    ImportedGeometry out;
    Reader reader(model, 1.0 / meters_per_unit(unit), budget);
    if (std::string e = reader.read_scene(out); !e.empty()) return e;
    return out;
}

}  // namespace radiant::proto
