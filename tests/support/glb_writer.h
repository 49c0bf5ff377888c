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
