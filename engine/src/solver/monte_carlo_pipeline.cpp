// The Monte Carlo path of the pipeline, in named stages: elements and their ray tracer; then
// rounds of photons (the reflected light field) and sensor ray sets (the final gather), each
// round priced by the error it leaves, until the estimate meets the tolerance.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

#include "design/glare.h"
#include "design/lighting_assembly.h"
#include "montecarlo/channel_product.h"
#include "montecarlo/element_mesh.h"
#include "montecarlo/light_sources.h"
#include "montecarlo/monte_carlo_error.h"
#include "montecarlo/photon_field.h"
#include "montecarlo/sensor_gather.h"
#include "montecarlo/surface_error.h"
#include "solution/result_difference.h"
#include "solution/sensors.h"
#include "solution/surface_summary.h"
#include "solver/memory_estimates.h"
#include "solver/pipeline.h"

namespace radiant {
namespace {

// Elements are at most this share of the mean free path: the reflected light they carry varies
// over about a free path, and the gather reads it at the coarser level too, to measure the
// discretisation.
constexpr double kEdgeOfFreePath = 0.25;
// Nearer than this many first-level edges to a compact light, elements shrink with the distance
// (ElementSizing), at every level alike. At one edge the lounge's points beside its table lamps
// still read their shades 0.4 % bright at times, and one seed in four ended under its error.
constexpr double kLightReachOfEdge = 2;
// A surface this near in front of an element's point, in mean free paths, hides it: light
// reaches into such a gap (a ceiling panel hung 1 cm under the ceiling) only near its rim, while
// an element that straddles the rim spread what it gets over its hidden part too, reading the
// ceiling around the classroom's panels dark enough to put its work plane 0.055 % low.
constexpr double kNearOfFreePath = 0.02;
// The first round: a few photons per element side and 8 ray sets per point at tolerance 0.01,
// fewer at looser ones (noise falls as 1/√samples, and a loose tolerance must not be met ten
// times over), but at least one chunk of photons per batch, and ray sets enough for their spread
// to mean something: a set's points together give as many degrees of freedom as 8 sets give one
// point. Eyes are sets of one and keep 8.
constexpr std::size_t kMinInitialPhotons = PhotonField::kBatches * PhotonField::kChunkPhotons;
constexpr double kInitialPhotonsPerSide = 2;
constexpr double kInitialTolerance = 0.01;
constexpr int kInitialSets = 8;
constexpr int kMinGatherDegrees = kInitialSets - 1;
// Rounds aim this far under the tolerance, so that the next estimate, itself noisy, meets it.
constexpr double kTargetShare = 0.8;
// A discretisation estimate above the target cuts every element's edges by this, at most
// this many times.
constexpr double kRefinementRatio = 0.5;
constexpr int kMaxRefinements = 3;
// Mesh versions: one per level of elements.
constexpr std::uint64_t kFirstMeshVersion = 1;
// The error an answer without one complete round claims: twice its own size (a dark answer is
// off by the RMS of the truth over its mean: 1.05 on the furnished office's work plane).
constexpr double kUnmeasuredEstimate = 2;
// An observer's background luminance moves its UGR by 8·log10(1 + δ) when off by δ: it is held
// to the δ that moves UGR by this much (5.9 %), or to the tolerance where that is finer. UGR
// is read in whole units; its light, all reflected, would otherwise cost ten times the photons.
constexpr double kUgrErrorTarget = 0.2;

// One light component's light through a level's mesh: its sources, its photons, and the
// gathers at its sensors and at the observers' eyes, each to its own budget (a scene without
// groups has one component, of every source). The eyes are few and need their own number of
// ray sets: their light is all reflected, noisier than a sensor's.
struct ComponentLight {
    ComponentLight(const PreparedScene& scene, const ElementMesh& mesh,
                   const Visibility& visibility, int which, double factor, std::uint64_t seed)
        : sources(scene, visibility.epsilon(), which),
          field(scene, mesh, seed),
          direct(scene, mesh, sources, visibility, seed),
          gather(scene, mesh, sources, direct, visibility, seed),
          eyes(scene, mesh, sources, direct, visibility, seed, SensorGather::Points::eyes),
          component(which),
          maintenance_factor(factor) {}
    LightSources sources;
    PhotonField field;
    SideDirectCache direct;  ///< the gathers' control variate
    SensorGather gather, eyes;
    int component;  ///< −1: every source
    double maintenance_factor;
    std::size_t photon_budget = 0;
    std::vector<int> set_sets;  ///< each sensor set's ray sets per point, on average
    int eye_sets = kInitialSets;
    MonteCarloError error, eye_error;  ///< the eyes': scaled to the tolerance
    std::vector<SetError> set_errors, eye_errors;
    std::vector<GatheredPoint> points, eye_points;
    double reported = std::numeric_limits<double>::infinity();
    double eye_reported = std::numeric_limits<double>::infinity();
    bool complete() const {
        return field.photons() >= photon_budget && gather.reached() && eyes.reached();
    }
    /// Keeps this share of the budgeted ray sets (never fewer than are gathered): what fits in
    /// memory.
    void cut_sets(double share) {
        const std::vector<int> gathered = gather.set_means();
        for (std::size_t s = 0; s < set_sets.size(); ++s)
            set_sets[s] = std::max(gathered[s], static_cast<int>(share * set_sets[s]));
        eye_sets = std::max(eyes.sets(), static_cast<int>(share * eye_sets));
    }
};

// The first round's ray sets per sensor point: kInitialSets scaled by `share`, but enough for
// the smallest sensor set's spread to have kMinGatherDegrees degrees of freedom.
int first_round_sets(double share, const std::vector<std::size_t>& set_sizes) {
    std::size_t smallest = std::numeric_limits<std::size_t>::max();
    for (const std::size_t size : set_sizes) {
        if (size > 0) smallest = std::min(smallest, size);
    }
    const auto spread_sets =
        1 + static_cast<int>(std::ceil(kMinGatherDegrees / static_cast<double>(smallest)));
    const auto scaled = static_cast<int>(std::ceil(kInitialSets * share));
    return std::min(kInitialSets, std::max(spread_sets, scaled));
}

// The next round's photons and ray sets: each sensor set's least-cost budget for its own error
// (its sets cost in proportion to its points), and photons the most any set asks for; a set
// already within `target` keeps its sets (a work plane need not gather as long as the noisy
// worktop under the cabinets' strip lights does). Without sensors, the surfaces' error prices
// the photons.
void next_budgets(ComponentLight& light, double target, double per_photon, double per_set) {
    const SampleBudget now{light.field.photons(), light.gather.sets()};
    if (light.set_errors.empty()) {
        light.photon_budget = next_budget(light.error, now, target, per_photon, per_set).photons;
        return;
    }
    const std::vector<int> means = light.gather.set_means();
    const std::vector<std::size_t>& sizes = light.gather.set_sizes();
    double points = 0;
    for (const std::size_t size : sizes) points += static_cast<double>(size);
    std::size_t photons = now.photons;
    for (std::size_t s = 0; s < sizes.size(); ++s) {
        const SetError& e = light.set_errors[s];
        light.set_sets[s] = std::max(light.set_sets[s], means[s]);
        if (!(e.mean > 0) || e.error.total <= target) continue;
        const SampleBudget next = next_budget(e.error, {now.photons, means[s]}, target, per_photon,
                                              per_set * static_cast<double>(sizes[s]) / points);
        light.set_sets[s] = next.sets;
        photons = std::max(photons, next.photons);
    }
    light.photon_budget = photons;
}

// One level of elements with everything that refers to them. Its elements' open areas are
// measured before the photon fields that spread flux over them: hidden parts of an element
// nearer than `near_m` to a surface in front count no area (see measure_open_areas).
struct MonteCarloLevel {
    MonteCarloLevel(const PreparedScene& scene, const ElementSizing& sizing,
                    const ElementCount& counted, double near_m, std::uint64_t seed,
                    const std::function<bool()>& stop, std::uint64_t& rays)
        : mesh(scene, sizing, stop, counted), visibility(make_embree_visibility(mesh.triangles())) {
        mesh.measure_open_areas(*visibility, near_m, rays);
        const std::vector<LightComponent>& components = scene.components.components;
        if (components.size() <= 1) {
            const double mf = components.empty() ? 1.0 : components.front().maintenance_factor;
            lights.push_back(
                std::make_unique<ComponentLight>(scene, mesh, *visibility, -1, mf, seed));
            return;
        }
        for (std::size_t c = 0; c < components.size(); ++c) {
            lights.push_back(
                std::make_unique<ComponentLight>(scene, mesh, *visibility, static_cast<int>(c),
                                                 components[c].maintenance_factor, seed));
        }
    }
    ElementMesh mesh;
    std::unique_ptr<Visibility> visibility;
    std::vector<std::unique_ptr<ComponentLight>> lights;
};

// The ray sets of every light component at its sensors and eyes: as this round's budgets ask
// for them, or as gathered so far.
enum class RaySets { budgeted, gathered };
std::size_t sets_bytes(const MonteCarloLevel& level, RaySets which) {
    std::size_t bytes = 0;
    for (const auto& light : level.lights) {
        const bool budgeted = which == RaySets::budgeted;
        const std::vector<int> sets = budgeted ? light->set_sets : light->gather.set_means();
        const std::vector<std::size_t>& sizes = light->gather.set_sizes();
        std::size_t point_sets = 0;
        for (std::size_t s = 0; s < sets.size(); ++s)
            point_sets += static_cast<std::size_t>(sets[s]) * sizes[s];
        bytes += point_sets * light->gather.bytes_per_set() +
                 static_cast<std::size_t>(budgeted ? light->eye_sets : light->eyes.sets()) *
                     light->eyes.points() * light->eyes.bytes_per_set();
    }
    return bytes;
}

// A display triangle: three vertices with their radiosity, its corners, surface and radiosity.
constexpr std::size_t kDisplayBytesPerElement =
    3 * (sizeof(Vec3) + sizeof(double)) + sizeof(std::array<int, 3>) + sizeof(int) + sizeof(double);

// What one level of elements holds while its rounds run: the elements and their sides, the ray
// tracer over them, each light component's photon tallies and sensor and eye points before their
// ray sets, a wave's deposits (components trace one after another); and at its peak either the
// ray tracer's build (with the triangle list it copies) or the display meshes and the sides'
// summaries that snapshots and the result are made of (a snapshot is built while the one it
// replaces is still shown; the result's mesh is a copy).
std::size_t level_bytes(const ElementCount& count, std::size_t points, std::size_t components,
                        std::size_t surface_tallies, std::size_t source_lists, double survival,
                        int display_copies) {
    const std::size_t build = count.elements * (sizeof(Triangle) + kEmbreeBuildBytesPerTriangle -
                                                kEmbreeBytesPerTriangle);
    const std::size_t display =
        static_cast<std::size_t>(display_copies) *
        (count.elements * kDisplayBytesPerElement + count.sides * sizeof(SolvedElement));
    const std::size_t per_component =
        count.sides * (PhotonField::kBytesPerSide + SideDirectCache::kBytesPerSide) +
        surface_tallies +
        points * (SensorGather::bytes_per_point() + 4 * kHeapBlockBytes + sizeof(GatheredPoint));
    return count.elements * (sizeof(MeshElement) + kEmbreeBytesPerTriangle) +
           count.sides * sizeof(ElementSide) + components * per_component +
           PhotonField::wave_bytes(survival) + source_lists + std::max(build, display);
}

// A receiver without one tangent plane (cylindrical kinds) keeps every emitting piece of its
// component, not the light tree's cut: the bytes of those lists, over every component.
std::size_t source_list_bytes(const PreparedScene& scene) {
    std::size_t points = 0;
    for (const PreparedSensorSet& set : scene.sensors) {
        if (set.kind == SensorKind::cylindrical || set.kind == SensorKind::semi_cylindrical)
            points += set.points.size();
    }
    std::size_t emitting = 0;
    for (const Piece& p : scene.pieces)
        emitting += scene.materials[static_cast<std::size_t>(p.material)].emits() ? 1 : 0;
    return points * emitting * sizeof(std::size_t);
}

// What a photon field's tallies of the surfaces' means cost (PhotonField::counted_surfaces).
std::size_t surface_tally_bytes(const PreparedScene& scene) {
    const std::vector<bool> counted = counted_surfaces(scene.surface_area_m2);
    return counted.size() * 2 * sizeof(int) +
           static_cast<std::size_t>(std::count(counted.begin(), counted.end(), true)) *
               PhotonField::kBytesPerCountedSurface;
}

// How likely a photon survives a bounce, on average over the surfaces' area.
double mean_survival(const PreparedScene& scene) {
    double weighted = 0, area = 0;
    for (const Piece& p : scene.pieces) {
        const Rgb& rho = scene.materials[static_cast<std::size_t>(p.material)].reflectance;
        weighted += p.area_m2 * std::min(1.0, std::max({rho[0], rho[1], rho[2]}));
        area += p.area_m2;
    }
    return area > 0 ? weighted / area : 0;
}

// Every element side as the surface summaries need it: irradiance from all photons, radiosity
// emitted (front) plus reflected; maintained, each component times its factor.
std::vector<SolvedElement> solved_sides(const PreparedScene& scene, const ElementMesh& mesh,
                                        const MonteCarloLevel& level) {
    std::vector<SolvedElement> out;
    out.reserve(mesh.sides().size());
    for (std::size_t s = 0; s < mesh.sides().size(); ++s) {
        const ElementSide& side = mesh.sides()[s];
        const MeshElement& e = mesh[static_cast<std::size_t>(side.element)];
        const PreparedMaterial& m = scene.materials[static_cast<std::size_t>(e.material)];
        Rgb h{0, 0, 0}, b{0, 0, 0};
        for (const auto& light : level.lights) {
            const double mf = light->maintenance_factor;
            const Rgb hc = light->field.total(static_cast<int>(s));
            Rgb bc = times(m.reflectance, hc);
            if (!side.back && (light->component < 0 || light->component == m.component)) {
                for (int c = 0; c < 3; ++c) bc[c] += m.exitance_lm_m2[c];
            }
            for (int c = 0; c < 3; ++c) {
                h[c] += mf * hc[c];
                b[c] += mf * bc[c];
            }
        }
        out.push_back({e.surface, e.material, e.area_m2, side.back, false, h, b});
    }
    return out;
}

// The maintained sensor values, Σ factor × component, of the sensor sets (not the observers).
std::vector<double> maintained_values(const MonteCarloLevel& level, std::size_t sensor_points) {
    std::vector<double> out(sensor_points, 0.0);
    for (const auto& light : level.lights) {
        for (std::size_t i = 0; i < sensor_points; ++i)
            out[i] += light->maintenance_factor * light->points[i].illuminance;
    }
    return out;
}

// Every light component's photons, weighted by its maintenance factor.
std::vector<WeightedField> weighted_fields(const MonteCarloLevel& level) {
    std::vector<WeightedField> out;
    for (const auto& light : level.lights)
        out.push_back({&light->field, light->maintenance_factor, light->component});
    return out;
}

// The estimate of the maintained values: per set, Σ factor × each component's RMS error over
// Σ factor × its mean, a bound for any correlation between them (Minkowski); the worst set. A
// scene without sensors: the same sum over its surfaces (surface_error). One component's is its
// own.
MonteCarloError maintained_error(const PreparedScene& scene, const MonteCarloLevel& level,
                                 bool on_surfaces) {
    if (level.lights.size() == 1) return level.lights.front()->error;
    if (on_surfaces) return surface_error(scene, weighted_fields(level));
    MonteCarloError worst;
    for (std::size_t s = 0; s < level.lights.front()->set_errors.size(); ++s) {
        double mean = 0;
        MonteCarloError sum;
        for (const auto& light : level.lights) {
            const SetError& e = light->set_errors[s];
            const double scale = light->maintenance_factor * e.mean;
            mean += scale;
            sum.total += scale * e.error.total;
            sum.parts.gather_noise += scale * e.error.parts.gather_noise;
            sum.parts.photon_noise += scale * e.error.parts.photon_noise;
            sum.parts.discretisation += scale * e.error.parts.discretisation;
        }
        if (!(mean > 0)) continue;
        sum.total /= mean;
        sum.parts.gather_noise /= mean;
        sum.parts.photon_noise /= mean;
        sum.parts.discretisation /= mean;
        if (!(sum.total <= worst.total)) worst = sum;
    }
    return worst;
}

// The elements' front sides, flat-shaded, in world coordinates.
SolvedMesh display_mesh(const PreparedScene& scene, const ElementMesh& mesh,
                        const std::vector<SolvedElement>& sides) {
    SolvedMesh out;
    // Reserved exactly, as kDisplayBytesPerElement counts them.
    out.vertices.reserve(3 * mesh.size());
    out.vertex_radiosity.reserve(3 * mesh.size());
    out.triangles.reserve(mesh.size());
    out.triangle_surface.reserve(mesh.size());
    out.triangle_radiosity.reserve(mesh.size());
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const MeshElement& e = mesh[i];
        const double b =
            photometric(sides[static_cast<std::size_t>(e.front)].radiosity, scene.channels);
        const int first = static_cast<int>(out.vertices.size());
        for (const Vec3& v : {e.triangle.a, e.triangle.b, e.triangle.c}) {
            out.vertices.push_back(v + scene.world_origin);
            out.vertex_radiosity.push_back(b);
        }
        out.triangles.push_back({first, first + 1, first + 2});
        out.triangle_surface.push_back(e.surface);
        out.triangle_radiosity.push_back(b);
    }
    return out;
}

/// What progress reports of the estimate: nothing before a level's first round has one.
std::optional<double> estimate_so_far(double reported) {
    return std::isfinite(reported) ? std::optional<double>(reported) : std::nullopt;
}

std::vector<SensorResult> sensor_results(const PreparedScene& scene,
                                         const std::vector<double>& values) {
    std::vector<SensorResult> out;
    std::size_t next = 0;
    for (const PreparedSensorSet& set : scene.sensors) {
        SensorResult r = sensor_result_for(set, scene.world_origin);
        for (double& v : r.illuminance) v = values[next++];
        fill_sensor_statistics(r);
        out.push_back(std::move(r));
    }
    return out;
}

// What each component's light gives the lighting designer's results: its values at the sensor
// sets and observers' eyes, their errors, and its luminaires' glare at every observer.
std::vector<ComponentValues> component_values(const PreparedScene& scene,
                                              const MonteCarloLevel& level,
                                              const Visibility& visibility, std::uint64_t& rays) {
    std::vector<ComponentValues> out;
    for (const auto& light : level.lights) {
        ComponentValues& v = out.emplace_back();
        std::size_t next = 0;
        for (std::size_t s = 0; s < scene.sensors.size(); ++s) {
            std::vector<double>& set = v.sets.emplace_back();
            for (std::size_t k = 0; k < scene.sensors[s].points.size(); ++k)
                set.push_back(light->points[next++].illuminance);
            const SetError& e = light->set_errors[s];
            v.set_error_lx.push_back(e.error.total * e.mean);
        }
        for (std::size_t k = 0; k < scene.observers.size(); ++k) {
            const PreparedObserver& o = scene.observers[k];
            const SetError& e = light->eye_errors[k];
            v.eye_indirect_lx.push_back(light->eye_points[k].illuminance);
            v.eye_indirect_error_lx.push_back(e.error.total * e.mean);
            v.glare_sums.push_back(glare_sum(scene, o, visibility, light->component, rays));
        }
    }
    return out;
}

}  // namespace

Result Pipeline::run_monte_carlo(const PreparedSolve& input) {
    Result result;
    result.scene = scene_.name;
    const PreparedScene& scene = input.scene;
    std::vector<std::size_t> set_sizes;
    std::size_t sensor_points = 0;
    for (const PreparedSensorSet& set : scene.sensors) {
        set_sizes.push_back(set.points.size());
        sensor_points += set.points.size();
    }
    // Without sensors the error is stated on the surfaces' means (surface_error).
    const bool on_surfaces = sensor_points == 0;
    // Each observer's eye is a set of one: its background luminance is measured like a
    // sensor's value, to its own target.
    const std::vector<std::size_t> eye_sizes(scene.observers.size(), 1);
    const double eye_scale =
        options_.tolerance / std::max(options_.tolerance, std::pow(10.0, kUgrErrorTarget / 8) - 1);

    // A level's first round's samples are what any estimate of its answer is made of: at the
    // time limit it may run the grace past it to complete them.
    bool measured = false;
    const auto stop = [this, &measured] {
        return measured ? should_stop() : should_stop_after_grace();
    };
    StageStats meshing{"meshing", 0, 0, 0}, photons{"photons", 0, 0, 0};
    StageStats gathering{"gather", 0, 0, 0}, estimating{"estimate", 0, 0, 0};
    std::uint64_t eye_rays = 0;
    MonteCarloError error;
    double reported = std::numeric_limits<double>::infinity();
    std::unique_ptr<MonteCarloLevel> level;
    // Each component's samples at the coarser level, and its points' values there.
    struct Carried {
        std::size_t photons = 0;
        std::vector<int> set_sets;
        int eye_sets = 0;
        std::vector<GatheredPoint> points, eye_points;
    };
    std::vector<Carried> carried;
    std::size_t rounds = 0;
    bool stopped = false;
    std::uint64_t mesh_version = kFirstMeshVersion;
    // Memory: each level is estimated from its element count before it is built; ray sets are
    // added only as far as they fit.
    const double survival = mean_survival(scene);
    const std::size_t source_lists = source_list_bytes(scene);
    const std::size_t surface_tallies = surface_tally_bytes(scene);
    const int display_copies = (observer_ ? 2 : 1) + (options_.want_mesh ? 1 : 0);
    const std::size_t components = std::max<std::size_t>(1, scene.components.components.size());
    auto bytes_of = [&](const ElementCount& count) {
        return level_bytes(count, sensor_points + eye_sizes.size(), components, surface_tallies,
                           source_lists, survival, display_copies);
    };
    double edge = kEdgeOfFreePath * input.mean_free_path_m;
    const double light_reach = kLightReachOfEdge * edge;
    const auto sized = [light_reach](double max_edge) {
        return ElementSizing{max_edge, light_reach};
    };
    // A component is done once its own estimates meet the tolerance: every sum of components
    // with weights in [0, 1] then does too.
    const double tolerance = options_.tolerance;
    const auto done = [tolerance](const ComponentLight& light) {
        return light.reported <= tolerance && light.eye_reported <= tolerance;
    };
    ElementCount count = ElementMesh::count(scene, sized(edge));
    const std::size_t natural_bytes = bytes_of(count);
    // Coarser elements than the light's variation asks for, if the budget needs it: the
    // discretisation estimate then says what that costs, and the result is `stopped` if it
    // misses the tolerance.
    while (!memory_->fits(bytes_of(count))) {
        const ElementCount coarser = ElementMesh::count(scene, sized(2 * edge));
        if (coarser.elements >= count.elements) {
            result.error = "memory budget: " +
                           memory_->refusal(
                               "monte-carlo's coarsest elements (one per triangle), their ray "
                               "tracer, photons and sensors",
                               bytes_of(count));
            return result;
        }
        stop_for_memory(memory_->refusal(
            "monte-carlo's elements at a quarter of the mean free path", natural_bytes));
        edge *= 2;
        count = coarser;
    }
    // A finer level starts over with the samples of the level it replaces, so its first round
    // takes about as long as that level took: where this would not end by the time limit (and
    // its grace) the finer level would be cut short unmeasured, and the kitchen at 0.002 with a
    // 60 s limit answered 26 % off where its first level stood at 0.25 %. That level stands.
    const auto in_time = [this](Clock::time_point level_start) {
        const std::optional<Clock::time_point> deadline = graced_deadline();
        const Clock::time_point now = Clock::now();
        return !deadline || now + (now - level_start) <= *deadline;
    };
    MemoryHold level_hold(*memory_, bytes_of(count));
    MemoryHold sets_hold(*memory_, 0);
    MemoryHold aims_hold(*memory_, 0);  // the sensor points' aimed sides (SensorGather)
    // Each level's first round: the same share of the samples asked at tolerance 0.01.
    const double share = std::min(1.0, std::pow(kInitialTolerance / options_.tolerance, 2));
    const int initial_sets = first_round_sets(share, set_sizes);
    for (int refinements = 0;; ++refinements, edge *= kRefinementRatio) {
        // Stage: meshing — elements, and a ray tracer over them so that a hit names its element.
        const Clock::time_point level_start = Clock::now();
        Clock::time_point stage_start = level_start;
        report("meshing", 0.02, rounds, estimate_so_far(reported));
        level.reset();  // the finer level replaces it (its estimate was held in its place)
        aims_hold.resize(0);
        measured = false;
        std::uint64_t meshing_rays = 0;
        // Cut short by the time limit or a cancel, a level holds no elements: its rounds then
        // gather nothing, and the answer is unmeasured.
        level = std::make_unique<MonteCarloLevel>(scene, sized(edge), count,
                                                  kNearOfFreePath * input.mean_free_path_m,
                                                  options_.seed, stop, meshing_rays);
        meshing.rays += meshing_rays;
        rays_ += meshing_rays;
        elements_ = level->mesh.size();
        mesh_version = kFirstMeshVersion + static_cast<std::uint64_t>(refinements);
        meshing.seconds += seconds_since(stage_start);
        meshing.memory_bytes = level->mesh.size() * sizeof(MeshElement) +
                               level->mesh.sides().size() * sizeof(ElementSide);
        for (std::size_t c = 0; c < level->lights.size(); ++c) {
            ComponentLight& light = *level->lights[c];
            if (c < carried.size()) {
                // The coarser level's values stand in for this level's until its first
                // estimate: their spread allots its first ray sets (SensorGather::gather).
                light.photon_budget = carried[c].photons;
                light.set_sets = std::move(carried[c].set_sets);
                light.eye_sets = carried[c].eye_sets;
                light.points = std::move(carried[c].points);
                light.eye_points = std::move(carried[c].eye_points);
            }
            light.photon_budget = std::max(
                {light.photon_budget, kMinInitialPhotons,
                 static_cast<std::size_t>(kInitialPhotonsPerSide * share *
                                          static_cast<double>(level->mesh.sides().size()))});
            light.set_sets.resize(set_sizes.size(), initial_sets);
            for (int& sets : light.set_sets) sets = std::max(sets, initial_sets);
        }
        bool refine = false;
        for (;; ++rounds) {
            // Stage: photons — the reflected light field, to this round's budget.
            stage_start = Clock::now();
            report("photons", 0.1, rounds, estimate_so_far(reported));
            for (const auto& light : level->lights) {
                if (done(*light)) continue;
                const std::uint64_t photon_rays = light->field.trace(
                    light->photon_budget - std::min(light->photon_budget, light->field.photons()),
                    light->sources, *level->visibility, stop);
                rays_ += photon_rays;
                photons.rays += photon_rays;
            }
            photons.seconds += seconds_since(stage_start);
            // Stage: gather — the sensors' and eyes' ray sets, to this round's budget, as far as
            // they fit. The first field shows which sides are bright enough to aim rays at,
            // where the aims fit in memory.
            stage_start = Clock::now();
            std::size_t aims_bytes = 0;
            for (const auto& light : level->lights) {
                if (light->gather.sets() == 0) {
                    light->gather.aim_at_bright_sides(
                        light->field, memory_->available_bytes() + aims_hold.bytes());
                }
                aims_bytes += light->gather.aims_bytes();
            }
            aims_hold.resize(aims_bytes);
            gathering.seconds += seconds_since(stage_start);
            const std::size_t wanted_bytes = sets_bytes(*level, RaySets::budgeted);
            const std::size_t room_bytes = memory_->available_bytes() + sets_hold.bytes();
            bool sets_cut = false;
            if (wanted_bytes > room_bytes) {
                stop_for_memory(memory_->refusal(
                    "ray sets at " + std::to_string(sensor_points + eye_sizes.size()) +
                        " sensor and eye points for each of " +
                        std::to_string(level->lights.size()) + " light components",
                    wanted_bytes - sets_bytes(*level, RaySets::gathered)));
                const double fitting =
                    static_cast<double>(room_bytes) / static_cast<double>(wanted_bytes);
                for (const auto& light : level->lights) light->cut_sets(fitting);
                sets_cut = true;
            }
            sets_hold.resize(sets_bytes(*level, RaySets::budgeted));
            stage_start = Clock::now();
            report("gather", 0.5, rounds, estimate_so_far(reported));
            for (const auto& light : level->lights) {
                if (done(*light)) continue;
                // Each round's sets go mostly to the points whose sets spread most so far.
                const std::uint64_t gather_rays =
                    light->gather.gather(light->set_sets, stop, light->points);
                const std::uint64_t eye_gather_rays = light->eyes.gather(light->eye_sets, stop);
                rays_ += gather_rays + eye_gather_rays;
                gathering.rays += gather_rays + eye_gather_rays;
                eye_rays += eye_gather_rays;
            }
            gathering.seconds += seconds_since(stage_start);
            // Stage: estimate — every point's value and error parts on the field so far.
            stage_start = Clock::now();
            const auto estimate = [&](ComponentLight& light) {
                light.points = light.gather.evaluate(light.field);
                light.set_errors = set_errors(light.points, set_sizes);
                light.error = on_surfaces
                                  ? surface_error(scene, {{&light.field, 1.0, light.component}})
                                  : worst_error(light.set_errors);
                light.eye_points = light.eyes.evaluate(light.field);
                light.eye_errors = set_errors(light.eye_points, eye_sizes);
                // The eyes' are budgeted at the tolerance over their own target.
                light.eye_error = worst_error(light.eye_errors, eye_scale);
                // A later round never claims a larger error for its better answer.
                light.reported = std::min(light.reported, light.error.total);
                light.eye_reported = std::min(light.eye_reported, light.eye_error.total);
            };
            for (const auto& light : level->lights) {
                if (!done(*light)) estimate(*light);
            }
            error = maintained_error(scene, *level, on_surfaces);
            reported = std::min(reported, error.total);
            estimating.seconds += seconds_since(stage_start);
            snapshots_.offer(std::make_shared<const SolvedMesh>(display_mesh(
                                 scene, level->mesh, solved_sides(scene, level->mesh, *level))),
                             mesh_version,
                             std::make_shared<const std::vector<SensorResult>>(
                                 sensor_results(scene, maintained_values(*level, sensor_points))));
            report("estimate", 0.9, rounds + 1, estimate_so_far(reported));
            // A round cut short by a cancel or the time limit has not earned `converged`.
            const bool complete = std::all_of(level->lights.begin(), level->lights.end(),
                                              [](const auto& light) { return light->complete(); });
            measured = measured || complete;
            if (complete && std::all_of(level->lights.begin(), level->lights.end(),
                                        [&](const auto& light) { return done(*light); })) {
                break;
            }
            if (!complete || should_stop()) {
                stopped = true;
                break;
            }
            if (sets_cut) {
                stopped = true;
                break;
            }
            // Bias does not fall with samples: a finer mesh does, once it stands out of the
            // noise (see MonteCarloError::discretisation_significant).
            const double bias_target = kTargetShare * options_.tolerance;
            const auto biased_by = [&](const MonteCarloError& e) {
                return !(e.parts.discretisation < bias_target) && e.discretisation_significant;
            };
            const bool biased =
                std::any_of(level->lights.begin(), level->lights.end(), [&](const auto& light) {
                    return !done(*light) &&
                           (biased_by(light->error) || biased_by(light->eye_error));
                });
            if (biased) {
                refine = refinements < kMaxRefinements;
                if (refine && !in_time(level_start)) {
                    refine = false;
                    char reason[128];
                    std::snprintf(reason, sizeof reason,
                                  "the finer mesh it needs would not be sampled within the time "
                                  "limit of %g s",
                                  *options_.max_seconds);
                    result.stop_reason = reason;
                }
                if (refine) {
                    // The finer level replaces this one, with the ray sets this one has.
                    const ElementCount finer =
                        ElementMesh::count(scene, sized(edge * kRefinementRatio));
                    const std::size_t finer_bytes =
                        bytes_of(finer) + sets_bytes(*level, RaySets::gathered);
                    if (!memory_->fits(
                            finer_bytes -
                            std::min(finer_bytes, level_hold.bytes() + sets_hold.bytes()))) {
                        stop_for_memory(
                            memory_->refusal("monte-carlo's finer elements", finer_bytes));
                        refine = false;
                    } else {
                        level_hold.resize(bytes_of(finer));
                        count = finer;
                    }
                }
                stopped = !refine;
                break;
            }
            // Stage: gather — after a level's first round, its pilot, the points whose sets a
            // control variate pays for take cheap rays, their sets so far included, and the
            // next round is budgeted on those sets' spread.
            stage_start = Clock::now();
            report("gather", 0.5, rounds + 1, estimate_so_far(reported));
            bool cheapened = false;
            for (const auto& light : level->lights) {
                if (done(*light)) continue;
                const std::uint64_t sensor_rays =
                    light->gather.take_cheap_rays(stop, memory_->available_bytes());
                const std::uint64_t eye_cheap_rays =
                    light->eyes.take_cheap_rays(stop, memory_->available_bytes());
                rays_ += sensor_rays + eye_cheap_rays;
                gathering.rays += sensor_rays + eye_cheap_rays;
                eye_rays += eye_cheap_rays;
                if (sensor_rays + eye_cheap_rays == 0) continue;
                estimate(*light);
                cheapened = true;
            }
            if (cheapened) {
                error = maintained_error(scene, *level, on_surfaces);
                reported = std::min(reported, error.total);
            }
            gathering.seconds += seconds_since(stage_start);
            std::size_t traced = 0;
            int sets = 0, eye_sets = 0;
            for (const auto& light : level->lights) {
                traced += light->field.photons();
                sets += light->gather.sets();
                eye_sets += light->eyes.sets();
            }
            const double per_photon = static_cast<double>(photons.rays) /
                                      static_cast<double>(std::max<std::size_t>(traced, 1));
            const double per_set =
                static_cast<double>(gathering.rays - eye_rays) / std::max(sets, 1);
            const double per_eye_set = static_cast<double>(eye_rays) / std::max(eye_sets, 1);
            for (const auto& light : level->lights) {
                if (done(*light)) continue;
                if (!(light->reported <= tolerance) || scene.observers.empty())
                    next_budgets(*light, bias_target, per_photon, per_set);
                if (!(light->eye_reported <= tolerance)) {
                    const SampleBudget eyes =
                        next_budget(light->eye_error, {light->field.photons(), light->eyes.sets()},
                                    bias_target, per_photon, per_eye_set);
                    light->photon_budget = std::max(light->photon_budget, eyes.photons);
                    light->eye_sets = eyes.sets;
                }
            }
        }
        if (!refine) break;
        // The finer level starts afresh; its noise needs the samples the coarser one had.
        carried.clear();
        for (const auto& light : level->lights) {
            carried.push_back({light->field.photons(), light->gather.set_means(),
                               light->eyes.sets(), std::move(light->points),
                               std::move(light->eye_points)});
        }
        reported = std::numeric_limits<double>::infinity();
    }
    ++rounds;
    const ElementMesh& mesh = level->mesh;
    for (const auto& light : level->lights) {
        photons.memory_bytes += light->field.memory_bytes();
        gathering.memory_bytes += light->gather.memory_bytes() + light->eyes.memory_bytes() +
                                  light->direct.memory_bytes();
    }
    for (const StageStats& st : {meshing, photons, gathering, estimating}) stages_.push_back(st);

    result.sensors = sensor_results(scene, maintained_values(*level, sensor_points));
    const std::vector<SolvedElement> sides = solved_sides(scene, mesh, *level);
    SurfaceSummary summary = summarise_surfaces(scene, sides, scene.channels);
    result.surfaces = std::move(summary.surfaces);
    result.stats.emitted_flux_lm = summary.emitted_flux_lm;
    result.stats.absorbed_flux_lm = summary.absorbed_flux_lm;
    const auto solved = std::make_shared<const SolvedMesh>(display_mesh(scene, mesh, sides));
    if (options_.want_mesh) result.mesh = *solved;
    // Without one complete round of its level (a cancel, or a grace too short) the spread of the
    // samples measures nothing: with none the answer is dark and its error at least its size.
    if (!measured) reported = std::max(reported, kUnmeasuredEstimate);
    finish_stats(result, "monte-carlo", mesh.size(), rounds, reported, 0, scene.channels, stopped);
    result.stats.error_parts = error.parts;
    assemble_lighting(scene_, scene, component_values(scene, *level, *input.visibility, rays_),
                      result);
    if (!measured) {
        for (SensorResult& set : result.sensors)
            set.error_estimate = std::max(set.error_estimate, kUnmeasuredEstimate);
    }
    result.stats.rays = rays_;
    final_mesh_ = solved;
    final_mesh_version_ = mesh_version;
    return result;
}

}  // namespace radiant
