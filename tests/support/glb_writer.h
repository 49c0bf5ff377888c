// Test models as binary glTF: one mesh with one primitive under one node, written with tinygltf.
#pragma once

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace radiant::test {

/// A buffer view of `length` bytes at `offset` in buffer 0 and an accessor of `count` items over
/// it; returns the accessor's index.
inline int add_accessor(tinygltf::Model& model, std::size_t offset, std::size_t length,
                        int component_type, int type, std::size_t count) {
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = length;
    model.bufferViews.push_back(view);
    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model.bufferViews.size() - 1);
    accessor.componentType = component_type;
    accessor.type = type;
    accessor.count = count;
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size() - 1);
}

/// Standard base64 with padding, as a scene's "gltf" key holds a .glb.
inline std::string base64(const std::string& bytes) {
    static const char* alphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t k = 0;
    for (; k + 2 < bytes.size(); k += 3) {
        const auto b = [&](std::size_t i) { return static_cast<unsigned char>(bytes[k + i]); };
        const unsigned v = (b(0) << 16) | (b(1) << 8) | b(2);
        for (int shift = 18; shift >= 0; shift -= 6) out += alphabet[(v >> shift) & 63];
    }
    if (k < bytes.size()) {
        unsigned v = static_cast<unsigned char>(bytes[k]) << 16;
        if (k + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[k + 1]) << 8;
        out += alphabet[(v >> 18) & 63];
        out += alphabet[(v >> 12) & 63];
        out += k + 1 < bytes.size() ? alphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

inline std::string glb_of(tinygltf::Model& model) {
    model.defaultScene = 0;
    model.asset.version = "2.0";
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, false, true)) {
        ADD_FAILURE() << "tinygltf could not write the test model";
    }
    return out.str();
}

/// The .glb bytes. `positions`: x, y, z per vertex in glTF axes (y up, metres); `indices` may be
/// empty (non-indexed); `mode` a TINYGLTF_MODE_*; `node_scale` empty or three factors.
inline std::string single_primitive_glb(const std::vector<float>& positions,
                                        const std::vector<std::uint32_t>& indices, int mode,
                                        const std::vector<double>& node_scale = {}) {
    tinygltf::Model model;
    tinygltf::Buffer buffer;
    const std::size_t vertex_bytes = positions.size() * sizeof(float);
    const std::size_t index_bytes = indices.size() * sizeof(std::uint32_t);
    buffer.data.resize(vertex_bytes + index_bytes);
    std::memcpy(buffer.data.data(), positions.data(), vertex_bytes);
    if (index_bytes > 0)
        std::memcpy(buffer.data.data() + vertex_bytes, indices.data(), index_bytes);
    model.buffers.push_back(buffer);

    tinygltf::Primitive primitive;
    primitive.mode = mode;
    primitive.attributes["POSITION"] =
        add_accessor(model, 0, vertex_bytes, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                     positions.size() / 3);
    // glTF requires POSITION bounds.
    tinygltf::Accessor& vertices = model.accessors.back();
    vertices.minValues.assign(3, 1e300);
    vertices.maxValues.assign(3, -1e300);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        vertices.minValues[i % 3] = std::min<double>(vertices.minValues[i % 3], positions[i]);
        vertices.maxValues[i % 3] = std::max<double>(vertices.maxValues[i % 3], positions[i]);
    }
    if (index_bytes > 0) {
        primitive.indices =
            add_accessor(model, vertex_bytes, index_bytes, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                         TINYGLTF_TYPE_SCALAR, indices.size());
    }
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(primitive);
    model.meshes.push_back(mesh);
    tinygltf::Node node;
    node.mesh = 0;
    node.scale = node_scale;
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    model.scenes.push_back(scene);
    return glb_of(model);
}

/// One triangle's mesh, used by the last of a chain of `depth` nodes (node k's child is node
/// k + 1) and by `instances` root nodes beside the chain.
inline std::string node_graph_glb(std::size_t depth, std::size_t instances) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    const std::string one_triangle =
        single_primitive_glb({0, 0, 0, 1, 0, 0, 0, 1, 0}, {}, TINYGLTF_MODE_TRIANGLES);
    tinygltf::TinyGLTF reader;
    std::string error, warning;
    reader.LoadBinaryFromMemory(&model, &error, &warning,
                                reinterpret_cast<const unsigned char*>(one_triangle.data()),
                                static_cast<unsigned>(one_triangle.size()));
    model.nodes.clear();
    model.scenes[0].nodes.clear();
    for (std::size_t k = 0; k < depth; ++k) {
        tinygltf::Node node;
        if (k + 1 < depth) node.children.push_back(static_cast<int>(k + 1));
        if (k + 1 == depth) node.mesh = 0;
        model.nodes.push_back(node);
    }
    if (depth > 0) model.scenes[0].nodes.push_back(0);
    for (std::size_t k = 0; k < instances; ++k) {
        tinygltf::Node node;
        node.mesh = 0;
        node.translation = {static_cast<double>(k), 0, 0};
        model.scenes[0].nodes.push_back(static_cast<int>(model.nodes.size()));
        model.nodes.push_back(node);
    }
    return glb_of(model);
}

}  // namespace radiant::test
