// What the engine's data will cost in bytes, estimated before it is allocated, for the
// MemoryBudget. Sizes of our own structures come from sizeof and the counts; a library's
// allocations are measured (Embree's) and kept here with how they were measured.
#pragma once

#include <cstddef>

#include "radiant/scene.h"

namespace radiant {

/// Embree's bytes per triangle with RTC_BUILD_QUALITY_HIGH, once built and at the peak of its
/// build (buffers, BVH with spatial splits, the builder's scratch): 115 and 148 measured through
/// rtcSetDeviceMemoryMonitorFunction on the furnished office and floors.
inline constexpr std::size_t kEmbreeBytesPerTriangle = 120;
inline constexpr std::size_t kEmbreeBuildBytesPerTriangle = 160;
/// A heap block's bookkeeping beside its payload (glibc: 16 bytes, rounded to 16).
inline constexpr std::size_t kHeapBlockBytes = 32;

/// Triangles the scene's surfaces fan into (polygons and mesh faces of n corners: n − 2; a box:
/// 12), the unit the preparation and ray-tracing estimates count in.
std::size_t scene_triangles(const Scene& scene);
/// The scene as the caller holds it while it is solved (surfaces, sensors, tables).
std::size_t scene_bytes(const Scene& scene);
/// Sensor points, grids expanded.
std::size_t scene_sensor_points(const Scene& scene);

/// The prepared scene, its occluder triangles and their Embree scene at its build's peak (the
/// occluder list is freed once Embree has copied it).
std::size_t preparation_peak_bytes(const Scene& scene);
/// What the prepared scene and its ray tracer hold once built.
std::size_t preparation_held_bytes(const Scene& scene);

}  // namespace radiant
