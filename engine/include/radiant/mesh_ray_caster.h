// Nearest-hit rays against a solved mesh, for pictures of a result (Embree underneath).
#pragma once

#include <memory>
#include <optional>

#include "radiant/result.h"

namespace radiant {

class Visibility;

class MeshRayCaster {
public:
    struct Hit {
        int triangle;     ///< index into SolvedMesh::triangles
        double distance;  ///< along the unit ray direction, metres
    };

    /// Builds the acceleration structure once; the mesh must outlive nothing (it is copied).
    explicit MeshRayCaster(const SolvedMesh& mesh);
    ~MeshRayCaster();
    MeshRayCaster(const MeshRayCaster&) = delete;
    MeshRayCaster& operator=(const MeshRayCaster&) = delete;

    /// The first triangle along origin + t·direction (direction unit length, t > 0). Thread-safe.
    std::optional<Hit> intersect(const Vec3& origin, const Vec3& direction) const;

private:
    Vec3 centre_;  ///< rays run in coordinates relative to this, so far-off scenes keep precision
    std::unique_ptr<Visibility> visibility_;
};

}  // namespace radiant
