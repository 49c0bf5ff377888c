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

    tinygltf::BufferView vertex_view;
    vertex_view.buffer = 0;
    vertex_view.byteLength = vertex_bytes;
    model.bufferViews.push_back(vertex_view);
    tinygltf::Accessor vertex_accessor;
    vertex_accessor.bufferView = 0;
    vertex_accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    vertex_accessor.type = TINYGLTF_TYPE_VEC3;
    vertex_accessor.count = positions.size() / 3;
    // glTF requires POSITION bounds.
    vertex_accessor.minValues.assign(3, 1e300);
    vertex_accessor.maxValues.assign(3, -1e300);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        vertex_accessor.minValues[i % 3] =
            std::min<double>(vertex_accessor.minValues[i % 3], positions[i]);
        vertex_accessor.maxValues[i % 3] =
            std::max<double>(vertex_accessor.maxValues[i % 3], positions[i]);
    }
    model.accessors.push_back(vertex_accessor);

    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = 0;
    primitive.mode = mode;
    if (index_bytes > 0) {
        tinygltf::BufferView index_view;
        index_view.buffer = 0;
        index_view.byteOffset = vertex_bytes;
        index_view.byteLength = index_bytes;
        model.bufferViews.push_back(index_view);
        tinygltf::Accessor index_accessor;
        index_accessor.bufferView = 1;
        index_accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        index_accessor.type = TINYGLTF_TYPE_SCALAR;
        index_accessor.count = indices.size();
        model.accessors.push_back(index_accessor);
        primitive.indices = 1;
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
    model.defaultScene = 0;
    model.asset.version = "2.0";
    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, false, true)) {
        ADD_FAILURE() << "tinygltf could not write the test model";
    }
    return out.str();
}

}  // namespace radiant::test
