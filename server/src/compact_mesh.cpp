#include "radiant/server/compact_mesh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

#include "radiant/proto/base64.h"

namespace radiant::server {
namespace {

static_assert(std::endian::native == std::endian::little, "the blob layout is little-endian");

constexpr std::uint32_t kMagic = 0x31484d52;  // "RMH1"
constexpr std::size_t kHeaderWords = 6;       // magic and five array lengths

template <typename T>
void append_raw(std::string& out, const std::vector<T>& values) {
    out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

template <typename T>
bool read_raw(std::string_view& blob, std::size_t count, std::vector<T>& values) {
    if (count > blob.size() / sizeof(T)) return false;
    values.resize(count);
    std::memcpy(values.data(), blob.data(), count * sizeof(T));
    blob.remove_prefix(count * sizeof(T));
    return true;
}

/// Shortest text that reads back as the same float; finite by construction (compact() clamps).
void append_number(std::string& out, float value) {
    std::array<char, 32> text{};
    const auto [end, ec] = std::to_chars(text.data(), text.data() + text.size(), value);
    out.append(text.data(), ec == std::errc{} ? end : text.data());
}

void append_number(std::string& out, std::int32_t value) {
    std::array<char, 16> text{};
    const auto [end, ec] = std::to_chars(text.data(), text.data() + text.size(), value);
    out.append(text.data(), ec == std::errc{} ? end : text.data());
}

/// [v0,v1,…], or with `group` > 1, [[v0,v1,v2],…].
template <typename T>
void append_array(std::string& out, const char* key, const std::vector<T>& values,
                  std::size_t group = 1) {
    out += '"';
    out += key;
    out += "\":[";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i > 0) out += ',';
        if (group > 1 && i % group == 0) out += '[';
        append_number(out, values[i]);
        if (group > 1 && i % group == group - 1) out += ']';
    }
    out += ']';
}

/// `"key":"<base64 of the values' bytes>"`.
template <typename T>
void append_base64(std::string& out, const char* key, const std::vector<T>& values) {
    out += '"';
    out += key;
    out += "\":\"";
    out += proto::encode_base64(
        std::string_view(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T)));
    out += '"';
}

float to_float(double value) {
    // The engine never hands out NaN; a value beyond float range is clamped, not made infinite.
    constexpr double kMax = 3.4e38;
    return std::isfinite(value) ? static_cast<float>(std::clamp(value, -kMax, kMax)) : 0.0f;
}

}  // namespace

CompactMesh compact(const SolvedMesh& mesh) {
    CompactMesh out;
    out.vertices.reserve(3 * mesh.vertices.size());
    for (const Vec3& v : mesh.vertices) {
        out.vertices.push_back(to_float(v.x));
        out.vertices.push_back(to_float(v.y));
        out.vertices.push_back(to_float(v.z));
    }
    out.triangles.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        out.triangles.insert(out.triangles.end(), t.begin(), t.end());
    out.triangle_surface.assign(mesh.triangle_surface.begin(), mesh.triangle_surface.end());
    for (double b : mesh.triangle_radiosity) out.triangle_radiosity.push_back(to_float(b));
    for (double b : mesh.vertex_radiosity) out.vertex_radiosity.push_back(to_float(b));
    return out;
}

SolvedMesh expand(const CompactMesh& mesh) {
    SolvedMesh out;
    for (std::size_t i = 0; i + 2 < mesh.vertices.size(); i += 3) {
        out.vertices.push_back({mesh.vertices[i], mesh.vertices[i + 1], mesh.vertices[i + 2]});
    }
    for (std::size_t i = 0; i + 2 < mesh.triangles.size(); i += 3) {
        out.triangles.push_back({mesh.triangles[i], mesh.triangles[i + 1], mesh.triangles[i + 2]});
    }
    out.triangle_surface.assign(mesh.triangle_surface.begin(), mesh.triangle_surface.end());
    out.triangle_radiosity.assign(mesh.triangle_radiosity.begin(), mesh.triangle_radiosity.end());
    out.vertex_radiosity.assign(mesh.vertex_radiosity.begin(), mesh.vertex_radiosity.end());
    return out;
}

std::string encode(const CompactMesh& mesh) {
    const std::array<std::uint32_t, kHeaderWords> header = {
        kMagic,
        static_cast<std::uint32_t>(mesh.vertices.size()),
        static_cast<std::uint32_t>(mesh.triangles.size()),
        static_cast<std::uint32_t>(mesh.triangle_surface.size()),
        static_cast<std::uint32_t>(mesh.triangle_radiosity.size()),
        static_cast<std::uint32_t>(mesh.vertex_radiosity.size())};
    std::string out(reinterpret_cast<const char*>(header.data()), sizeof header);
    append_raw(out, mesh.vertices);
    append_raw(out, mesh.triangles);
    append_raw(out, mesh.triangle_surface);
    append_raw(out, mesh.triangle_radiosity);
    append_raw(out, mesh.vertex_radiosity);
    return out;
}

std::optional<CompactMesh> decode(std::string_view blob) {
    std::array<std::uint32_t, kHeaderWords> header{};
    if (blob.size() < sizeof header) return std::nullopt;
    std::memcpy(header.data(), blob.data(), sizeof header);
    blob.remove_prefix(sizeof header);
    if (header[0] != kMagic) return std::nullopt;
    CompactMesh mesh;
    const bool ok = read_raw(blob, header[1], mesh.vertices) &&
                    read_raw(blob, header[2], mesh.triangles) &&
                    read_raw(blob, header[3], mesh.triangle_surface) &&
                    read_raw(blob, header[4], mesh.triangle_radiosity) &&
                    read_raw(blob, header[5], mesh.vertex_radiosity);
    if (!ok || !blob.empty()) return std::nullopt;
    return mesh;
}

std::string geometry_json(const CompactMesh& mesh) {
    std::string out;
    out.reserve(12 * (mesh.vertices.size() + mesh.triangles.size()));
    append_array(out, "vertices", mesh.vertices, 3);
    out += ',';
    append_array(out, "triangles", mesh.triangles, 3);
    out += ',';
    append_array(out, "triangle_surface", mesh.triangle_surface);
    return out;
}

std::string radiosity_json(const CompactMesh& mesh) {
    std::string out;
    out.reserve(10 * (mesh.triangle_radiosity.size() + mesh.vertex_radiosity.size()));
    append_array(out, "triangle_radiosity", mesh.triangle_radiosity);
    out += ',';
    append_array(out, "vertex_radiosity", mesh.vertex_radiosity);
    return out;
}

std::string geometry_base64_json(const CompactMesh& mesh) {
    std::string out;
    append_base64(out, "vertices", mesh.vertices);
    out += ',';
    append_base64(out, "triangles", mesh.triangles);
    out += ',';
    append_base64(out, "triangle_surface", mesh.triangle_surface);
    return out;
}

std::string radiosity_base64_json(const CompactMesh& mesh) {
    std::string out;
    append_base64(out, "triangle_radiosity", mesh.triangle_radiosity);
    out += ',';
    append_base64(out, "vertex_radiosity", mesh.vertex_radiosity);
    return out;
}

}  // namespace radiant::server
