#include "checks/luminaire_placement.h"

#include "checks/warning_text.h"

namespace radiant {
namespace {

// A luminaire from which no direction leaves the model and most end on black backs is inside
// a closed solid (not all: a desk's bottom lies on the floor, whose front a ray may meet first).
// Above kBehindShare of its light on black backs a surface hides much of it: a luminaire in a
// room sends none there.
constexpr double kInsideDirections = 0.6;
constexpr double kBehindShare = 0.25;
// A luminaire this far outside the model's box (relative to its diagonal) is not a luminaire
// on a surface that rounding put a hair outside.
constexpr double kOutsideMargin = 1e-6;
// A luminaire on a surface that sends this much of its light into it loses a share worth
// saying, as back_face_light does for a surface: a bare lamp's half, or an uplight's part.
constexpr double kTouchingShare = 0.05;
// A luminaire aimed into the surface it hangs under sends most of its light there within a
// few centimetres, and would send little there aimed the other way; a lamp in its shade or a
// downlight in its can sends about as much near either way, and an isotropic source the same.
constexpr double kNearShare = 0.5;
constexpr double kReversedNearRatio = 0.25;

}  // namespace

std::vector<bool> check_luminaire_placement(const CheckedScene& input, const LightPaths& paths,
                                            std::vector<Warning>& out) {
    const Box bounds = model_bounds(input.prepared);
    std::vector<bool> warned(input.prepared.luminaires.size(), false);
    for (std::size_t i = 0; i < input.prepared.luminaires.size(); ++i) {
        const std::string pointer = "/luminaires/" + std::to_string(i) + "/position";
        const std::size_t before = out.size();
        const std::string who = "luminaire " + quoted(input.scene.luminaires[i].name);
        const LuminaireFirstHits& first =
            i < paths.luminaires.size() ? paths.luminaires[i] : LuminaireFirstHits{};
        const std::string surface =
            first.main_surface >= 0
                ? surface_label(input.scene, static_cast<std::size_t>(first.main_surface))
                : std::string();
        if (first.directions_black >= kInsideDirections && first.directions_escaped == 0) {
            // A luminaire without flux has no light to say where it goes.
            out.push_back({"luminaire_inside_solid",
                           who + " is inside a closed solid" +
                               (surface.empty() ? std::string()
                                                : ": " + percent(first.black_back) +
                                                      " of its light falls on the black back of " +
                                                      surface + " and its neighbours"),
                           pointer});
        } else if (first.black_back >= kBehindShare) {
            out.push_back(
                {"luminaire_behind_surface",
                 who + " sends " + percent(first.black_back) +
                     " of its light onto the black back of " +
                     (first.main_share < first.black_back ? surface + " and others" : surface) +
                     ": is it above the ceiling or behind a wall, or is that surface "
                     "wound the wrong way?",
                 pointer});
        } else if (first.touching >= kTouchingShare) {
            out.push_back(
                {"luminaire_faces_surface",
                 who + " lies on " +
                     surface_label(input.scene, static_cast<std::size_t>(first.touching_surface)) +
                     " and sends " + percent(first.touching) +
                     " of its light straight into it, where it is lost: move it a little off the "
                     "surface, or aim it away from it",
                 pointer});
        } else if (first.near >= kNearShare &&
                   first.near_reversed <= kReversedNearRatio * first.near) {
            out.push_back(
                {"luminaire_faces_surface",
                 who + " sends " + percent(first.near) + " of its light onto " +
                     surface_label(input.scene, static_cast<std::size_t>(first.near_surface)) +
                     " within " + length_text(near_distance(input.prepared)) + ", and would send " +
                     percent(first.near_reversed) +
                     " there aimed the other way: is its aim reversed? \"aim\" is the "
                     "direction of its light (its nadir), [0, 0, -1] for a downlight and the "
                     "default",
                 "/luminaires/" + std::to_string(i)});
        } else if (const double outside =
                       distance_outside(bounds, input.prepared.luminaires[i].position);
                   outside > kOutsideMargin * input.prepared.diagonal_m) {
            out.push_back({"luminaire_outside_model",
                           who + " is " + length_text(outside) +
                               " outside the model's bounding box; " + percent(first.escaped) +
                               " of its light leaves the model unseen",
                           pointer});
        }
        warned[i] = out.size() > before;
    }
    return warned;
}

}  // namespace radiant
