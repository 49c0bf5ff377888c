// glTF is y-up (metres); Radiant scenes are z-up. A quarter turn about x maps one to the other,
// so imported models stand upright and exported ones open upright in glTF viewers.
#pragma once

#include "radiant/vec3.h"

namespace radiant::proto {

inline Vec3 from_gltf_axes(const Vec3& v) { return {v.x, -v.z, v.y}; }
inline Vec3 to_gltf_axes(const Vec3& v) { return {v.x, v.z, -v.y}; }

}  // namespace radiant::proto
