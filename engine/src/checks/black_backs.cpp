#include "checks/black_backs.h"

#include <algorithm>
#include <numeric>

#include "checks/warning_text.h"

namespace radiant {
namespace {

// Surfaces named one by one; the rest are summed up in one more warning.
constexpr std::size_t kMaxNamed = 10;

const BoxGeometry* box_facing_in(const Surface& s) {
    const auto* box = std::get_if<BoxGeometry>(&s.geometry);
    return box && box->facing_in ? box : nullptr;
}

bool contains(const BoxGeometry& outer, const BoxGeometry& inner) {
    bool larger = false;
    for (int a = 0; a < 3; ++a) {
        if (inner.min[a] < outer.min[a] || inner.max[a] > outer.max[a]) return false;
        larger = larger || inner.min[a] > outer.min[a] || inner.max[a] < outer.max[a];
    }
    return larger;
}

/// The box facing in that holds `inner` (engine surface index), or −1.
int room_around(const Scene& scene, const BoxGeometry& inner, std::size_t self) {
    for (std::size_t j = 0; j < scene.surfaces.size(); ++j) {
        const BoxGeometry* outer = box_facing_in(scene.surfaces[j]);
        if (j != self && outer && contains(*outer, inner)) return static_cast<int>(j);
    }
    return -1;
}

std::size_t sensor_points_inside(const Scene& scene, const BoxGeometry& box) {
    std::size_t count = 0;
    for (const SensorSet& set : scene.sensors) {
        for (const Vec3& p : set.points) {
            bool inside = true;
            for (int a = 0; a < 3; ++a) inside = inside && p[a] > box.min[a] && p[a] < box.max[a];
            count += inside ? 1 : 0;
        }
    }
    return count;
}

}  // namespace

void check_black_backs(const CheckedScene& input, const LightPaths& paths,
                       const std::vector<bool>& misplaced,
                       const std::vector<bool>& misplaced_emitters, std::vector<Warning>& out) {
    const Scene& scene = input.scene;
    const std::vector<double> share =
        black_back_shares(paths, scene.surfaces.size(), misplaced, misplaced_emitters);
    const double lost = std::accumulate(share.begin(), share.end(), 0.0);
    const double named_share = lost >= kMuchLost ? kLostShareWhenMuchIsLost : kLostShare;

    // A box that is most of the model is its room, not an object wrongly facing in.
    const double meters = meters_per_unit(scene.units);
    const Box model = model_bounds(input.prepared);
    std::vector<std::size_t> others;
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const double surface_share = share[s];
        const BoxGeometry* box = box_facing_in(scene.surfaces[s]);
        const int room = box ? room_around(scene, *box, s) : -1;
        const bool object = box && !is_room_sized((box->max - box->min) * meters, model);
        if (box && (room >= 0 || (object && surface_share >= named_share))) {
            std::string message = "box " + quoted(scene.surfaces[s].name) + " faces in, as a room";
            if (room >= 0) {
                message += ", but lies inside the room " +
                           surface_label(scene, static_cast<std::size_t>(room));
            }
            message += ": its outside is black";
            if (surface_share >= 0.01)
                message += " and takes " + percent(surface_share) + " of the light";
            if (const std::size_t n = sensor_points_inside(scene, *box)) {
                message += ", and " + std::to_string(n) + " sensor points inside it are measured";
            }
            message += "; an object needs \"facing\": \"out\"";
            out.push_back({"box_faces_in", std::move(message), surface_pointer(scene, s) + "/box"});
        } else if (surface_share >= named_share) {
            others.push_back(s);
        }
    }
    std::stable_sort(others.begin(), others.end(),
                     [&](std::size_t a, std::size_t b) { return share[a] > share[b]; });
    for (std::size_t k = 0; k < std::min(others.size(), kMaxNamed); ++k) {
        const std::size_t s = others[k];
        out.push_back({"back_face_light",
                       percent(share[s]) + " of the emitted light falls on the black back of " +
                           surface_label(scene, s) +
                           ": is it wound the wrong way (reverse its vertices), or should its "
                           "material be two_sided?",
                       surface_pointer(scene, s)});
    }
    if (others.size() > kMaxNamed) {
        double rest = 0;
        for (std::size_t k = kMaxNamed; k < others.size(); ++k) rest += share[others[k]];
        out.push_back({"back_face_light",
                       std::to_string(others.size() - kMaxNamed) + " more surfaces lose " +
                           percent(rest) + " of the emitted light into their black backs",
                       "/surfaces"});
    }
}

}  // namespace radiant
