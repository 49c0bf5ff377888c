#include "scene/check_lighting_design.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "design/light_components.h"
#include "design/requirements.h"
#include "scene/json_pointer.h"

namespace radiant {
namespace {

// A line of sight or a vertical sensor's facing needs this much of a horizontal part (the
// Guth position index and the vertical kinds are defined about the vertical).
constexpr double kMinHorizontal = 1e-6;

bool horizontal_part(const Vec3& v) { return std::hypot(v.x, v.y) > kMinHorizontal * length(v); }

class DesignChecker {
public:
    DesignChecker(const Scene& scene, const SceneLimits& limits, std::vector<Problem>& problems)
        : scene_(scene), limits_(limits), problems_(problems) {}

    void run() {
        // Over a limit the other checks would cost as much as the limit saves.
        if (!within_limits()) return;
        for (std::size_t i = 0; i < scene_.luminaires.size(); ++i)
            source(scene_.luminaires[i].design, at("/luminaires", i));
        for (const Material& m : scene_.materials) {
            if (m.emission)
                source(m.emission->design,
                       "/materials/" + escape_pointer_token(m.name) + "/emission");
        }
        if (scene_.settings.maintenance_factor)
            factor(*scene_.settings.maintenance_factor, "/settings/maintenance_factor");
        luminous_areas();
        sensors();
        observers();
        light_scenes();
        method();
    }

private:
    void report(std::string pointer, std::string message) {
        problems_.push_back({std::move(pointer), std::move(message)});
    }

    void factor(double f, const std::string& pointer) {
        if (!(std::isfinite(f) && f > 0 && f <= 1))
            report(pointer, "maintenance_factor must be in (0, 1]");
    }

    void ra(double r, const std::string& pointer) {
        if (!(std::isfinite(r) && r >= 0 && r <= 100)) report(pointer, "ra must be in [0, 100]");
    }

    void source(const SourceDesign& d, const std::string& base) {
        if (d.group && d.group->empty()) report(base + "/group", "group must not be empty");
        if (d.maintenance_factor) factor(*d.maintenance_factor, base + "/maintenance_factor");
        if (d.ra) ra(*d.ra, base + "/ra");
    }

    /// Whether the solve rates glare: observers given, or a requirement limits UGR.
    bool rates_glare() const {
        if (!scene_.observers.empty()) return true;
        return std::any_of(scene_.sensors.begin(), scene_.sensors.end(), [](const SensorSet& s) {
            return s.requirement && apply_requirement(*s.requirement).ugr_l;
        });
    }

    void luminous_areas() {
        const bool glare = rates_glare();
        for (std::size_t i = 0; i < scene_.luminaires.size(); ++i) {
            const Luminaire& l = scene_.luminaires[i];
            const std::string base = at("/luminaires", i);
            if (l.luminous_area) {
                const LuminousShape& a = *l.luminous_area;
                const std::string p = base + "/luminous_area";
                for (const auto& [key, value] :
                     {std::pair{a.round ? "diameter" : "length", a.length}, {"width", a.width}}) {
                    if (!(std::isfinite(value) && value > 0))
                        report(p + (a.round ? "/diameter" : std::string("/") + key),
                               std::string(key) + " must be a finite number > 0");
                    if (a.round) break;
                }
                if (!(std::isfinite(a.height) && a.height >= 0))
                    report(p + "/height", "height must be a finite number >= 0");
            } else if (glare && l.distribution != Distribution::photometric) {
                // A photometric file that declares a point source gets CIE 147's small-source
                // form; a made-up distribution has no size to rate at all.
                report(base,
                       "UGR needs the luminaire's luminous area: give luminous_area (an " +
                           std::string(l.distribution == Distribution::isotropic ? "isotropic"
                                                                                 : "lambertian") +
                           " luminaire has no photometric data to take it from)");
            }
        }
    }

    void requirement(const SensorSet& s, const std::string& base) {
        const Requirement& r = *s.requirement;
        const std::string p = base + "/requirement";
        if (!s.grid_area && !s.workplane && !s.grid) {
            report(p,
                   "a requirement applies to a task area: give the sensor set a grid or "
                   "workplane");
        }
        if (r.activity && !find_activity(*r.activity)) {
            std::string known;
            for (const Activity& a : en12464_activities())
                known += (known.empty() ? "" : ", ") + std::string(a.reference);
            report(p + "/activity",
                   "unknown activity \"" + *r.activity + "\" (known: " + known + ")");
        }
        if (!r.activity && !r.em_lx && !r.u0 && !r.ugr_l && !r.ra)
            report(p, "a requirement needs an activity or at least one of em_lx, u0, ugr_l, ra");
        if (r.em_lx && !(std::isfinite(*r.em_lx) && *r.em_lx > 0))
            report(p + "/em_lx", "em_lx must be a finite number > 0");
        if (r.u0 && !(std::isfinite(*r.u0) && *r.u0 > 0 && *r.u0 <= 1))
            report(p + "/u0", "u0 must be in (0, 1]");
        if (r.ugr_l && !(std::isfinite(*r.ugr_l) && *r.ugr_l > 0))
            report(p + "/ugr_l", "ugr_l must be a finite number > 0");
        if (r.ra) ra(*r.ra, p + "/ra");
    }

    void sensors() {
        std::set<std::string> names;
        for (std::size_t i = 0; i < scene_.sensors.size(); ++i) {
            const SensorSet& s = scene_.sensors[i];
            const std::string base = at("/sensors", i);
            const bool facing =
                s.kind == SensorKind::vertical || s.kind == SensorKind::semi_cylindrical;
            if (facing && is_finite(s.normal) && !horizontal_part(s.normal)) {
                report(base + "/normal", std::string("a ") + to_string(s.kind) +
                                             " sensor set faces the horizontal part of its "
                                             "normal, and this normal has none");
            }
            if (s.requirement) requirement(s, base);
            // Bands, observers' tasks and the plan name task areas by their sensor set's name.
            if (s.requirement && !names.insert(s.name).second)
                report(base + "/name", "another sensor set with a requirement has this name");
        }
    }

    void observers() {
        std::set<std::string> names;
        for (std::size_t i = 0; i < scene_.observers.size(); ++i) {
            const Observer& o = scene_.observers[i];
            const std::string base = at("/observers", i);
            if (!names.insert(o.name).second) report(base + "/name", "duplicate observer name");
            for (int c = 0; c < 3; ++c) {
                if (!std::isfinite(o.position[c]))
                    report(at(base + "/position", static_cast<std::size_t>(c)),
                           "coordinate must be a finite number");
                if (!std::isfinite(o.view[c]))
                    report(at(base + "/view", static_cast<std::size_t>(c)),
                           "component must be a finite number");
            }
            if (is_finite(o.view) && !horizontal_part(o.view)) {
                report(base + "/view",
                       "view must not be vertical: UGR rates glare about a line of sight that "
                       "has a horizontal part");
            }
            if (o.task) {
                const bool known = std::any_of(
                    scene_.sensors.begin(), scene_.sensors.end(),
                    [&](const SensorSet& s) { return s.name == *o.task && s.requirement; });
                if (!known)
                    report(base + "/task",
                           "no sensor set with a requirement is named \"" + *o.task + "\"");
            }
        }
    }

    void light_scenes() {
        const LightComponents components = light_components(scene_);
        std::set<std::string> names;
        for (std::size_t i = 0; i < scene_.light_scenes.size(); ++i) {
            const LightScene& ls = scene_.light_scenes[i];
            const std::string base = at("/light_scenes", i);
            if (ls.name.empty()) report(base + "/name", "a light scene needs a name");
            if (!names.insert(ls.name).second) report(base + "/name", "duplicate light scene name");
            for (const auto& [group, dimming] : ls.dimming) {
                const std::string p = base + "/dimming/" + escape_pointer_token(group);
                if (std::find(components.groups.begin(), components.groups.end(), group) ==
                    components.groups.end()) {
                    std::string known;
                    for (const std::string& g : components.groups)
                        known += (known.empty() ? "\"" : ", \"") + g + "\"";
                    report(p, "no luminaire or emitting material is in group \"" + group +
                                  "\" (groups: " + (known.empty() ? "none" : known) + ")");
                }
                if (!(std::isfinite(dimming) && dimming >= 0 && dimming <= 1))
                    report(p, "a dimming must be in [0, 1]");
            }
        }
    }

    void method() {
        const std::string& m = scene_.settings.method;
        if (m == "auto" || m == "monte-carlo") return;
        const std::string why = monte_carlo_only_reason(scene_);
        if (!why.empty()) report("/settings/method", why + ", not \"" + m + "\"");
    }

    bool within_limits() {
        const std::size_t problems = problems_.size();
        const LightComponents lc = light_components(scene_);
        if (lc.components.size() > limits_.max_light_components) {
            // Point at the first source that opens a component over the limit.
            const int limit = static_cast<int>(limits_.max_light_components);
            std::string pointer = "/luminaires";
            const auto l =
                std::find_if(lc.luminaire_component.begin(), lc.luminaire_component.end(),
                             [&](int c) { return c >= limit; });
            const auto m = std::find_if(lc.material_component.begin(), lc.material_component.end(),
                                        [&](int c) { return c >= limit; });
            if (l != lc.luminaire_component.end()) {
                pointer =
                    at("/luminaires", static_cast<std::size_t>(l - lc.luminaire_component.begin()));
            } else if (m != lc.material_component.end()) {
                pointer =
                    "/materials/" +
                    escape_pointer_token(
                        scene_
                            .materials[static_cast<std::size_t>(m - lc.material_component.begin())]
                            .name) +
                    "/emission";
            }
            report(pointer, std::to_string(lc.components.size()) +
                                " light components (each group with each maintenance factor, "
                                "solved apart), over the limit of " +
                                std::to_string(limits_.max_light_components));
        }
        over("/light_scenes", scene_.light_scenes.size(), limits_.max_light_scenes, "light scenes");
        over("/observers", scene_.observers.size(), limits_.max_observers, "observers");
        for (Problem& p : check_sensor_totals(scene_, limits_)) problems_.push_back(std::move(p));
        return problems_.size() == problems;
    }

    void over(const char* pointer, std::size_t count, std::size_t limit, const char* what) {
        if (count > limit) {
            report(pointer, std::to_string(count) + " " + what + ", over the limit of " +
                                std::to_string(limit));
        }
    }

    const Scene& scene_;
    const SceneLimits& limits_;
    std::vector<Problem>& problems_;
};

}  // namespace

void check_lighting_design(const Scene& scene, const SceneLimits& limits,
                           std::vector<Problem>& problems) {
    DesignChecker(scene, limits, problems).run();
}

std::vector<Problem> check_sensor_totals(const Scene& scene, const SceneLimits& limits) {
    std::size_t points = 0;
    for (const SensorSet& s : scene.sensors) points += s.points.size();
    const LightComponents lc = light_components(scene);
    const bool kept = lc.named_groups || !scene.light_scenes.empty();
    const std::size_t copies = kept ? 1 + lc.groups.size() + scene.light_scenes.size() : 1;
    // Saturating: engine users may pass any counts.
    const std::size_t values = points > limits.max_kept_sensor_values / copies
                                   ? limits.max_kept_sensor_values + 1
                                   : points * copies;
    std::vector<Problem> out;
    if (values > limits.max_kept_sensor_values) {
        out.push_back({"/sensors", std::to_string(points) + " sensor points × (1 + " +
                                       std::to_string(lc.groups.size()) + " groups + " +
                                       std::to_string(scene.light_scenes.size()) +
                                       " light scenes) values to keep, over the limit of " +
                                       std::to_string(limits.max_kept_sensor_values)});
    }
    const std::size_t luminaires = scene.luminaires.size();
    if (luminaires > 0 && points > limits.max_luminaire_sensor_pairs / luminaires) {
        out.push_back({"/sensors", std::to_string(points) + " sensor points × " +
                                       std::to_string(luminaires) +
                                       " luminaires (a shadow ray each), over the limit of " +
                                       std::to_string(limits.max_luminaire_sensor_pairs)});
    }
    return out;
}

}  // namespace radiant
