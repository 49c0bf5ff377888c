#include "radiant/picture/room_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "radiant/box.h"
#include "radiant/mesh_ray_caster.h"
#include "radiant/picture/false_colour.h"
#include "radiant/picture/vertex_illuminance.h"

namespace radiant::picture {
namespace {

constexpr Rgb kMissed{48, 52, 60};    // rays that leave the model
constexpr Rgb kBackSide{24, 24, 24};  // back sides reflect nothing
constexpr Rgb kPaper{255, 255, 255};  // behind the legend
constexpr double kMiddleGrey = 0.18;  // where the log-average luminance lands (Reinhard 2002)

const Vec3& corner(const SolvedMesh& mesh, int triangle, int k) {
    return mesh.vertices[static_cast<std::size_t>(
        mesh.triangles[static_cast<std::size_t>(triangle)][static_cast<std::size_t>(k)])];
}

}  // namespace

Camera default_camera(const SolvedMesh& mesh) {
    Box box = bounding_box(mesh.vertices);
    if (box.empty()) box = {{0, 0, 0}, {1, 1, 1}};
    const Vec3 lo = box.lo, size = box.size();
    Camera camera;
    camera.eye = lo + Vec3{0.08 * size.x, 0.08 * size.y, 0.6 * size.z};
    camera.target = lo + Vec3{0.75 * size.x, 0.75 * size.y, 0.25 * size.z};
    return camera;
}

std::optional<std::string> camera_problem(const Camera& camera) {
    const Vec3 view = camera.target - camera.eye;
    const Vec3 side = cross(view, camera.up);
    if (!(length(view) > 0) || !(length(side) > 1e-9 * length(view) * length(camera.up))) {
        return "the camera needs a target away from the eye and an up direction that is not "
               "along the view";
    }
    if (!(camera.vertical_fov_degrees > 0 && camera.vertical_fov_degrees < 180)) {
        return "the field of view must be in (0, 180) degrees";
    }
    return std::nullopt;
}

ViewHits cast_view(const SolvedMesh& mesh, const Camera& camera) {
    if (auto problem = camera_problem(camera)) throw std::invalid_argument(*problem);
    const Vec3 view = camera.target - camera.eye;
    const Vec3 side = cross(view, camera.up);
    const Vec3 forward = normalized(view);
    const Vec3 right = normalized(side);
    const Vec3 up = cross(right, forward);
    const double half_height = std::tan(camera.vertical_fov_degrees * std::numbers::pi / 360);
    const double half_width = half_height * camera.width / camera.height;

    const MeshRayCaster caster(mesh);
    ViewHits hits;
    hits.width = camera.width;
    hits.height = camera.height;
    hits.pixels.resize(static_cast<std::size_t>(camera.width) *
                       static_cast<std::size_t>(camera.height));
    for (int y = 0; y < camera.height; ++y) {
        for (int x = 0; x < camera.width; ++x) {
            const double sx = (2 * (x + 0.5) / camera.width - 1) * half_width;
            const double sy = (1 - 2 * (y + 0.5) / camera.height) * half_height;
            const Vec3 direction = normalized(forward + sx * right + sy * up);
            const auto hit = caster.intersect(camera.eye, direction);
            if (!hit) continue;
            const Vec3& a = corner(mesh, hit->triangle, 0);
            const Vec3& b = corner(mesh, hit->triangle, 1);
            const Vec3& c = corner(mesh, hit->triangle, 2);
            const Vec3 p = camera.eye + hit->distance * direction;
            const Vec3 n = cross(b - a, c - a);
            const double area2 = dot(n, n);
            if (!(area2 > 0)) continue;
            ViewHits::Pixel& pixel =
                hits.pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(camera.width) +
                            static_cast<std::size_t>(x)];
            pixel.triangle = hit->triangle;
            // Barycentric weights from the sub-triangle areas, clamped against float hits
            // landing a hair outside the triangle.
            pixel.w0 = std::clamp(dot(cross(b - p, c - p), n) / area2, 0.0, 1.0);
            pixel.w1 = std::clamp(dot(cross(c - p, a - p), n) / area2, 0.0, 1.0);
            pixel.w2 = std::clamp(1 - pixel.w0 - pixel.w1, 0.0, 1.0);
            pixel.front = dot(n, direction) < 0;
        }
    }
    return hits;
}

double interpolate(const SolvedMesh& mesh, const std::vector<double>& vertex_value,
                   const ViewHits::Pixel& pixel) {
    if (pixel.triangle < 0 || !pixel.front) return 0;
    const auto& t = mesh.triangles[static_cast<std::size_t>(pixel.triangle)];
    return pixel.w0 * vertex_value[static_cast<std::size_t>(t[0])] +
           pixel.w1 * vertex_value[static_cast<std::size_t>(t[1])] +
           pixel.w2 * vertex_value[static_cast<std::size_t>(t[2])];
}

Image luminance_view(const SolvedMesh& mesh, const ViewHits& hits, double white_luminance) {
    std::vector<double> luminance(hits.pixels.size(), 0);
    double log_sum = 0;
    std::size_t seen = 0;
    for (std::size_t i = 0; i < hits.pixels.size(); ++i) {
        if (hits.pixels[i].triangle < 0 || !hits.pixels[i].front) continue;
        luminance[i] = interpolate(mesh, mesh.vertex_radiosity, hits.pixels[i]) / std::numbers::pi;
        log_sum += std::log(luminance[i] + 1e-6);
        ++seen;
    }
    if (!(white_luminance > 0)) {
        white_luminance = seen ? std::exp(log_sum / static_cast<double>(seen)) / kMiddleGrey : 1;
    }
    Image image(hits.width, hits.height, kMissed);
    for (std::size_t i = 0; i < hits.pixels.size(); ++i) {
        const ViewHits::Pixel& pixel = hits.pixels[i];
        if (pixel.triangle < 0) continue;
        const int x = static_cast<int>(i % static_cast<std::size_t>(hits.width));
        const int y = static_cast<int>(i / static_cast<std::size_t>(hits.width));
        if (!pixel.front) {
            image.set(x, y, kBackSide);
            continue;
        }
        const std::uint8_t grey = srgb_byte(luminance[i] / white_luminance);
        image.set(x, y, {grey, grey, grey});
    }
    return image;
}

Image false_colour_view(const SolvedMesh& mesh, const std::vector<double>& vertex_value,
                        const ViewHits& hits, double max, const std::string& unit) {
    const int scale = std::max(1, hits.height / 300);
    const int margin = 8 * scale;
    Image image(hits.width + legend_width(max, scale) + 2 * margin, hits.height, kPaper);
    for (std::size_t i = 0; i < hits.pixels.size(); ++i) {
        const ViewHits::Pixel& pixel = hits.pixels[i];
        const int x = static_cast<int>(i % static_cast<std::size_t>(hits.width));
        const int y = static_cast<int>(i / static_cast<std::size_t>(hits.width));
        if (pixel.triangle < 0) {
            image.set(x, y, kMissed);
        } else if (!pixel.front) {
            image.set(x, y, kBackSide);
        } else {
            image.set(x, y, false_colour(interpolate(mesh, vertex_value, pixel), max));
        }
    }
    draw_legend(image, hits.width + margin, margin, hits.height - 2 * margin, max, unit, scale);
    return image;
}

Image draw_view(const Result& result, const Scene& scene, const Camera& camera,
                const ViewStyle& style) {
    const SolvedMesh& mesh = *result.mesh;
    const ViewHits hits = cast_view(mesh, camera);
    if (!style.falsecolor) return luminance_view(mesh, hits, style.exposure);
    const std::vector<double> lux = vertex_illuminance(result, scene);
    double max = style.max_lux;
    if (!(max > 0) && !lux.empty())
        max = round_scale_max(*std::max_element(lux.begin(), lux.end()));
    return false_colour_view(mesh, lux, hits, max, "lux");
}

}  // namespace radiant::picture
