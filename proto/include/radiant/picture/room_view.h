// Perspective pictures of a solved mesh: primary rays from a pinhole camera, values interpolated
// over each triangle from its vertices (Gouraud), shown as tone-mapped luminance or false colour.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "radiant/picture/image.h"
#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant::picture {

struct Camera {
    Vec3 eye;
    Vec3 target;
    Vec3 up{0, 0, 1};
    double vertical_fov_degrees = 60;
    int width = 800;
    int height = 600;
};

/// A camera inside the mesh's bounding box: eye near one lower corner at 3/5 of the height,
/// looking at the centre of the opposite half — a sensible first look into a room.
Camera default_camera(const SolvedMesh& mesh);

/// What the primary ray of every pixel hit (row-major, top row first).
struct ViewHits {
    struct Pixel {
        int triangle = -1;              ///< −1: nothing
        double w0 = 0, w1 = 0, w2 = 0;  ///< barycentric weights of the triangle's vertices
        bool front = false;             ///< the triangle's front side faces the camera
    };
    int width = 0, height = 0;
    std::vector<Pixel> pixels;
};

/// Why `camera` cannot take a picture (eye = target, up along the view, field of view out of
/// (0, 180)), or nothing.
std::optional<std::string> camera_problem(const Camera& camera);

/// Throws std::invalid_argument with camera_problem's message for a degenerate camera.
ViewHits cast_view(const SolvedMesh& mesh, const Camera& camera);

/// The value at a hit pixel from per-vertex values; back sides read 0 (they do not reflect).
double interpolate(const SolvedMesh& mesh, const std::vector<double>& vertex_value,
                   const ViewHits::Pixel& pixel);

/// Luminance picture: L = B/π per pixel, scaled so that `white_luminance` (cd/m²) is white;
/// white_luminance ≤ 0 picks it automatically (the log-average maps to 18 % grey).
Image luminance_view(const SolvedMesh& mesh, const ViewHits& hits, double white_luminance);

/// False-colour picture of per-vertex values on [0, max] with a legend titled `unit`.
Image false_colour_view(const SolvedMesh& mesh, const std::vector<double>& vertex_value,
                        const ViewHits& hits, double max, const std::string& unit);

/// How draw_view shows the room.
struct ViewStyle {
    bool falsecolor = false;  ///< illuminance (lux) with a legend instead of luminance
    double max_lux = 0;       ///< top of the false-colour scale; 0 = the largest value, rounded up
    double exposure = 0;      ///< luminance (cd/m²) shown as white; 0 = automatic
};

/// The picture `camera` takes of `result.mesh` (which must be set); `scene` tells which surfaces
/// emit (see vertex_illuminance). Throws std::invalid_argument for a degenerate camera.
Image draw_view(const Result& result, const Scene& scene, const Camera& camera,
                const ViewStyle& style);

}  // namespace radiant::picture
