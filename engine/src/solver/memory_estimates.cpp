#include "solver/memory_estimates.h"

#include <algorithm>
#include <variant>

#include "scene/prepared_scene.h"
#include "visibility/visibility.h"

namespace radiant {
namespace {

std::size_t fan_triangles(std::size_t corners) { return corners >= 3 ? corners - 2 : 0; }

// A piece is a convex polygon of a few corners (a triangle of a mesh, a quad of a wall): its
// vertex list is a heap block of its own.
constexpr std::size_t kPieceBytes = sizeof(Piece) + 4 * sizeof(Vec3) + kHeapBlockBytes;
// Preparing splits and copies polygons before it keeps the pieces: at its peak it holds about
// twice what it keeps (measured on the furnished floors: 184 bytes per triangle at the peak).
constexpr std::size_t kPreparationPeakFactor = 2;
// Each occluder triangle and its piece index; the list is built exactly (reserved).
constexpr std::size_t kOccluderBytes = sizeof(Triangle) + sizeof(int);

}  // namespace

std::size_t scene_triangles(const Scene& scene) {
    std::size_t n = 0;
    for (const Surface& s : scene.surfaces) {
        if (const auto* polygon = std::get_if<Polygon>(&s.geometry)) {
            n += fan_triangles(polygon->size());
        } else if (const auto* mesh = std::get_if<MeshGeometry>(&s.geometry)) {
            for (const auto& face : mesh->faces) n += fan_triangles(face.size());
        } else {
            n += 12;
        }
    }
    return n;
}

std::size_t scene_bytes(const Scene& scene) {
    auto vector_bytes = [](std::size_t n, std::size_t each) {
        return n == 0 ? 0 : n * each + kHeapBlockBytes;
    };
    std::size_t bytes = sizeof(Scene) + scene.materials.size() * sizeof(Material);
    for (const Surface& s : scene.surfaces) {
        bytes += sizeof(Surface) + s.name.capacity() + s.material.capacity();
        if (const auto* polygon = std::get_if<Polygon>(&s.geometry)) {
            bytes += vector_bytes(polygon->size(), sizeof(Vec3));
        } else if (const auto* mesh = std::get_if<MeshGeometry>(&s.geometry)) {
            bytes += vector_bytes(mesh->vertices.size(), sizeof(Vec3));
            for (const auto& face : mesh->faces)
                bytes += sizeof(face) + vector_bytes(face.size(), sizeof(int));
        }
    }
    for (const Luminaire& l : scene.luminaires) {
        bytes += sizeof(Luminaire) + l.name.capacity();
        if (l.photometry) {
            bytes += vector_bytes(l.photometry->candela.size() + l.photometry->gamma_deg.size() +
                                      l.photometry->c_deg.size(),
                                  sizeof(double));
        }
    }
    for (const SensorSet& set : scene.sensors) {
        bytes += sizeof(SensorSet) + vector_bytes(set.points.size(), sizeof(Vec3));
        if (set.grid) {
            bytes += vector_bytes(set.grid->points.size(), sizeof(Vec3)) +
                     vector_bytes(set.grid->cells.size(), sizeof(set.grid->cells[0]));
        }
    }
    return bytes;
}

std::size_t scene_sensor_points(const Scene& scene) {
    std::size_t n = 0;
    for (const SensorSet& set : scene.sensors) n += set.points.size();
    return n;
}

std::size_t preparation_held_bytes(const Scene& scene) {
    const std::size_t triangles = scene_triangles(scene);
    return triangles * (kPieceBytes + sizeof(int) + kEmbreeBytesPerTriangle) +
           scene_sensor_points(scene) * sizeof(Vec3);
}

std::size_t preparation_peak_bytes(const Scene& scene) {
    // Preparing peaks before the occluder list exists; the build of their ray tracer after.
    const std::size_t triangles = scene_triangles(scene);
    return triangles * std::max(kPreparationPeakFactor * kPieceBytes,
                                kPieceBytes + kOccluderBytes + kEmbreeBuildBytesPerTriangle) +
           scene_sensor_points(scene) * sizeof(Vec3);
}

}  // namespace radiant
