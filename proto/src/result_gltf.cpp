#include "radiant/proto/result_gltf.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <sstream>

#include "gltf_axes.h"

namespace radiant::proto {
namespace {

const char* unit_name(LengthUnit unit) {
    switch (unit) {
        case LengthUnit::m:
            return "m";
        case LengthUnit::cm:
            return "cm";
        case LengthUnit::mm:
            return "mm";
        case LengthUnit::ft:
            return "ft";
        case LengthUnit::in:
            return "in";
    }
    return "m";
}

/// Appends vertex or index data to the one buffer as its own view and accessor.
class Writer {
public:
    explicit Writer(tinygltf::Model& model) : model_(model) { model_.buffers.emplace_back(); }

    int floats(const std::vector<float>& values, int type, int components, bool bounds) {
        const int accessor = add(values.data(), values.size() * sizeof(float),
                                 TINYGLTF_TARGET_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_FLOAT, type,
                                 values.size() / static_cast<std::size_t>(components));
        if (bounds) {  // required for POSITION
            auto& a = model_.accessors.back();
            a.minValues.assign(values.begin(), values.begin() + components);
            a.maxValues = a.minValues;
            for (std::size_t k = 0; k < values.size(); ++k) {
                const auto c = k % static_cast<std::size_t>(components);
                a.minValues[c] = std::min<double>(a.minValues[c], values[k]);
                a.maxValues[c] = std::max<double>(a.maxValues[c], values[k]);
            }
        }
        return accessor;
    }

    int indices(const std::vector<std::uint32_t>& values) {
        return add(values.data(), values.size() * sizeof(std::uint32_t),
                   TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                   TINYGLTF_TYPE_SCALAR, values.size());
    }

private:
    int add(const void* data, std::size_t bytes, int target, int component, int type,
            std::size_t count) {
        auto& buffer = model_.buffers[0].data;
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.size();
        view.byteLength = bytes;
        view.target = target;
        buffer.resize(buffer.size() + bytes);
        std::memcpy(buffer.data() + view.byteOffset, data, bytes);
        model_.bufferViews.push_back(view);
        tinygltf::Accessor accessor;
        accessor.bufferView = static_cast<int>(model_.bufferViews.size()) - 1;
        accessor.componentType = component;
        accessor.type = type;
        accessor.count = count;
        model_.accessors.push_back(accessor);
        return static_cast<int>(model_.accessors.size()) - 1;
    }

    tinygltf::Model& model_;
};

void push_position(std::vector<float>& out, const Vec3& metres) {
    const Vec3 p = to_gltf_axes(metres);
    out.insert(out.end(),
               {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
}

/// COLOR_0 (gray, value / scale) and the raw values, as float attributes.
void add_values(Writer& writer, tinygltf::Primitive& primitive, const std::vector<double>& values,
                double scale, const char* semantic) {
    std::vector<float> color, raw;
    for (const double v : values) {
        const auto c = static_cast<float>(scale > 0 ? std::clamp(v / scale, 0.0, 1.0) : 0.0);
        color.insert(color.end(), {c, c, c});
        raw.push_back(static_cast<float>(v));
    }
    primitive.attributes["COLOR_0"] = writer.floats(color, TINYGLTF_TYPE_VEC3, 3, false);
    primitive.attributes[semantic] = writer.floats(raw, TINYGLTF_TYPE_SCALAR, 1, false);
}

void add_node(tinygltf::Model& model, const char* name, tinygltf::Primitive primitive) {
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(std::move(primitive));
    model.meshes.push_back(std::move(mesh));
    tinygltf::Node node;
    node.name = name;
    node.mesh = static_cast<int>(model.meshes.size()) - 1;
    model.nodes.push_back(std::move(node));
    model.scenes[0].nodes.push_back(static_cast<int>(model.nodes.size()) - 1);
}

}  // namespace

std::string result_to_glb(const Result& result, const Scene& scene) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "Radiant";
    model.scenes.emplace_back();
    model.defaultScene = 0;
    // Unlit: viewers show COLOR_0 as it is, without their own lights.
    tinygltf::Material material;
    material.name = "radiosity";
    material.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object{});
    model.materials.push_back(material);
    model.extensionsUsed.push_back("KHR_materials_unlit");
    Writer writer(model);

    double max_radiosity = 0;
    if (result.mesh && !result.mesh->triangles.empty()) {
        const SolvedMesh& mesh = *result.mesh;
        std::vector<float> positions;
        for (const Vec3& v : mesh.vertices) push_position(positions, v);
        std::vector<std::uint32_t> indices;
        for (const auto& t : mesh.triangles)
            for (const int v : t) indices.push_back(static_cast<std::uint32_t>(v));
        for (const double b : mesh.vertex_radiosity) max_radiosity = std::max(max_radiosity, b);
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.material = 0;
        primitive.attributes["POSITION"] = writer.floats(positions, TINYGLTF_TYPE_VEC3, 3, true);
        add_values(writer, primitive, mesh.vertex_radiosity, max_radiosity, "_RADIOSITY");
        primitive.indices = writer.indices(indices);
        add_node(model, "surfaces", std::move(primitive));
    }

    double max_illuminance = 0;
    std::vector<float> points;
    std::vector<double> illuminance;
    const double metres = meters_per_unit(scene.units);
    for (std::size_t s = 0; s < scene.sensors.size() && s < result.sensors.size(); ++s) {
        const auto& values = result.sensors[s].illuminance;
        for (std::size_t k = 0; k < scene.sensors[s].points.size() && k < values.size(); ++k) {
            push_position(points, scene.sensors[s].points[k] * metres);
            illuminance.push_back(values[k]);
            max_illuminance = std::max(max_illuminance, values[k]);
        }
    }
    if (!illuminance.empty()) {
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_POINTS;
        primitive.material = 0;
        primitive.attributes["POSITION"] = writer.floats(points, TINYGLTF_TYPE_VEC3, 3, true);
        add_values(writer, primitive, illuminance, max_illuminance, "_ILLUMINANCE");
        add_node(model, "sensors", std::move(primitive));
    }

    tinygltf::Value::Object extras;
    extras["scene"] = tinygltf::Value(result.scene);
    extras["units"] = tinygltf::Value(std::string("m"));
    extras["scene_units"] = tinygltf::Value(std::string(unit_name(scene.units)));
    extras["radiosity_unit"] = tinygltf::Value(std::string("lm/m2"));
    extras["color_scale_radiosity"] = tinygltf::Value(max_radiosity);
    extras["color_scale_illuminance"] = tinygltf::Value(max_illuminance);
    model.scenes[0].extras = tinygltf::Value(extras);
    model.scenes[0].name = result.scene;
    if (model.buffers[0].data.empty()) model.buffers.clear();  // a buffer may not be empty

    std::ostringstream out;
    tinygltf::TinyGLTF gltf;
    gltf.WriteGltfSceneToStream(&model, out, false, true);
    return out.str();
}

}  // namespace radiant::proto
