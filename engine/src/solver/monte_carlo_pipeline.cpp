// The Monte Carlo path of the pipeline, in named stages: elements and their ray tracer; then
// rounds of photons (the reflected light field) and sensor ray sets (the final gather), each
// round priced by the error it leaves, until the estimate meets the tolerance.
#include <algorithm>
#include <cmath>
#include <limits>

#include "montecarlo/element_mesh.h"
#include "montecarlo/light_sources.h"
#include "montecarlo/monte_carlo_error.h"
#include "montecarlo/photon_field.h"
#include "montecarlo/sensor_gather.h"
#include "solution/sensors.h"
#include "solution/surface_summary.h"
#include "solver/pipeline.h"

namespace radiant {
namespace {

// Elements are at most this share of the mean free path: the reflected light they carry varies
// over about a free path, and the gather reads it at the coarser level too, to measure the
// discretisation.
constexpr double kEdgeOfFreePath = 0.25;
// The first round: a few photons per element side at tolerance 0.01, fewer at looser ones (noise
// falls as 1/√photons), at least one chunk per batch; and ray sets enough for their spread to
// mean something.
constexpr std::size_t kMinInitialPhotons = PhotonField::kBatches * PhotonField::kChunkPhotons;
constexpr double kInitialPhotonsPerSide = 2;
constexpr double kInitialTolerance = 0.01;
constexpr int kInitialSets = 8;
// Rounds aim this far under the tolerance, so that the next estimate, itself noisy, meets it.
constexpr double kTargetShare = 0.8;
// A discretisation estimate above the target cuts every element's edges by this, at most
// this many times.
constexpr double kRefinementRatio = 0.5;
constexpr int kMaxRefinements = 3;
// Mesh versions: one per level of elements.
constexpr std::uint64_t kFirstMeshVersion = 1;

// One level of elements with everything that refers to them.
struct MonteCarloLevel {
    MonteCarloLevel(const PreparedScene& scene, double edge, std::uint64_t seed)
        : mesh(scene, edge),
          visibility(make_embree_visibility(mesh.triangles())),
          sources(scene, visibility->epsilon()),
          field(scene, mesh, seed),
          gather(scene, mesh, sources, *visibility, seed) {}
    ElementMesh mesh;
    std::unique_ptr<Visibility> visibility;
    LightSources sources;
    PhotonField field;
    SensorGather gather;
};

Rgb times(const Rgb& a, const Rgb& b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }

// Every element side as the surface summaries need it: irradiance from all photons, radiosity
// emitted (front) plus reflected.
std::vector<SolvedElement> solved_sides(const PreparedScene& scene, const ElementMesh& mesh,
                                        const PhotonField& field) {
    std::vector<SolvedElement> out;
    out.reserve(mesh.sides().size());
    for (std::size_t s = 0; s < mesh.sides().size(); ++s) {
        const ElementSide& side = mesh.sides()[s];
        const Element& e = mesh[static_cast<std::size_t>(side.element)];
        const PreparedMaterial& m = scene.materials[static_cast<std::size_t>(e.material)];
        const Rgb h = field.total(static_cast<int>(s));
        Rgb b = times(m.reflectance, h);
        if (!side.back) {
            for (int c = 0; c < 3; ++c) b[c] += m.exitance_lm_m2[c];
        }
        out.push_back({e.surface, e.material, e.area_m2, side.back, false, h, b});
    }
    return out;
}

// The elements' front sides, flat-shaded, in world coordinates.
SolvedMesh display_mesh(const PreparedScene& scene, const ElementMesh& mesh,
                        const std::vector<SolvedElement>& sides) {
    SolvedMesh out;
    out.vertices.reserve(3 * mesh.size());
    for (std::size_t i = 0; i < mesh.size(); ++i) {
        const Element& e = mesh[i];
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
                                         const std::vector<GatheredPoint>& points) {
    std::vector<SensorResult> out;
    std::size_t next = 0;
    for (const PreparedSensorSet& set : scene.sensors) {
        SensorResult r = sensor_result_for(set, scene.world_origin);
        for (double& v : r.illuminance) v = points[next++].illuminance;
        fill_sensor_statistics(r);
        out.push_back(std::move(r));
    }
    return out;
}

}  // namespace

Result Pipeline::run_monte_carlo(const PreparedSolve& input) {
    Result result;
    result.scene = scene_.name;
    const PreparedScene& scene = input.scene;
    std::vector<std::size_t> set_sizes;
    for (const PreparedSensorSet& set : scene.sensors) set_sizes.push_back(set.points.size());
    if (std::all_of(set_sizes.begin(), set_sizes.end(), [](std::size_t n) { return n == 0; })) {
        result.error =
            "method \"monte-carlo\" measures its error at the sensors, and the scene has none";
        return result;
    }

    const auto stop = [this] { return should_stop(); };
    SampleBudget budget{0, kInitialSets};
    StageStats meshing{"meshing", 0, 0, 0}, photons{"photons", 0, 0, 0};
    StageStats gathering{"gather", 0, 0, 0}, estimating{"estimate", 0, 0, 0};
    MonteCarloError error;
    double reported = std::numeric_limits<double>::infinity();
    std::vector<GatheredPoint> points;
    std::unique_ptr<MonteCarloLevel> level;
    std::size_t rounds = 0;
    bool stopped = false;
    std::uint64_t mesh_version = kFirstMeshVersion;
    double edge = kEdgeOfFreePath * input.mean_free_path_m;
    for (int refinements = 0;; ++refinements, edge *= kRefinementRatio) {
        // Stage: meshing — elements, and a ray tracer over them so that a hit names its element.
        Clock::time_point stage_start = Clock::now();
        report("meshing", 0.02, rounds, estimate_so_far(reported));
        level = std::make_unique<MonteCarloLevel>(scene, edge, options_.seed);
        elements_ = level->mesh.size();
        mesh_version = kFirstMeshVersion + static_cast<std::uint64_t>(refinements);
        meshing.seconds += seconds_since(stage_start);
        meshing.memory_bytes =
            level->mesh.size() * sizeof(Element) + level->mesh.sides().size() * sizeof(ElementSide);
        const double share = std::min(1.0, std::pow(kInitialTolerance / options_.tolerance, 2));
        budget.photons =
            std::max({budget.photons, kMinInitialPhotons,
                      static_cast<std::size_t>(kInitialPhotonsPerSide * share *
                                               static_cast<double>(level->mesh.sides().size()))});
        PhotonField& field = level->field;
        SensorGather& gather = level->gather;
        bool refine = false;
        for (;; ++rounds) {
            // Stage: photons — the reflected light field, to this round's budget.
            stage_start = Clock::now();
            report("photons", 0.1, rounds, estimate_so_far(reported));
            const std::uint64_t photon_rays =
                field.trace(budget.photons - std::min(budget.photons, field.photons()),
                            level->sources, *level->visibility, stop);
            rays_ += photon_rays;
            photons.rays += photon_rays;
            photons.seconds += seconds_since(stage_start);
            // Stage: gather — the sensors' ray sets, to this round's budget.
            stage_start = Clock::now();
            report("gather", 0.5, rounds, estimate_so_far(reported));
            const std::uint64_t gather_rays = gather.gather(budget.sets, stop);
            rays_ += gather_rays;
            gathering.rays += gather_rays;
            gathering.seconds += seconds_since(stage_start);
            // Stage: estimate — every point's value and error parts on the field so far.
            stage_start = Clock::now();
            points = gather.evaluate(field);
            error = combine_errors(points, set_sizes);
            // A later round never claims a larger error for its better answer.
            reported = std::min(reported, error.total);
            estimating.seconds += seconds_since(stage_start);
            snapshots_.offer(
                std::make_shared<const SolvedMesh>(
                    display_mesh(scene, level->mesh, solved_sides(scene, level->mesh, field))),
                mesh_version,
                std::make_shared<const std::vector<SensorResult>>(sensor_results(scene, points)));
            report("estimate", 0.9, rounds + 1, estimate_so_far(reported));
            // A round cut short by a cancel or the time limit has not earned `converged`.
            const bool complete = field.photons() >= budget.photons && gather.sets() >= budget.sets;
            if (!complete || should_stop()) {
                stopped = true;
                break;
            }
            if (reported <= options_.tolerance) break;
            // Bias does not fall with samples: a finer mesh does.
            if (!(error.parts.discretisation < kTargetShare * options_.tolerance)) {
                refine = refinements < kMaxRefinements;
                stopped = !refine;
                break;
            }
            const double per_photon =
                static_cast<double>(photons.rays) /
                static_cast<double>(std::max<std::size_t>(field.photons(), 1));
            const double per_set = static_cast<double>(gathering.rays) / gather.sets();
            budget = next_budget(error, {field.photons(), gather.sets()},
                                 kTargetShare * options_.tolerance, per_photon, per_set);
        }
        if (!refine) break;
        // The finer level starts afresh; its noise needs the samples the coarser one had.
        budget = {level->field.photons(), level->gather.sets()};
        reported = std::numeric_limits<double>::infinity();
    }
    ++rounds;
    const ElementMesh& mesh = level->mesh;
    const PhotonField& field = level->field;
    photons.memory_bytes = field.memory_bytes();
    gathering.memory_bytes = level->gather.memory_bytes();
    for (const StageStats& st : {meshing, photons, gathering, estimating}) stages_.push_back(st);

    result.sensors = sensor_results(scene, points);
    const std::vector<SolvedElement> sides = solved_sides(scene, mesh, field);
    SurfaceSummary summary = summarise_surfaces(scene, sides, scene.channels);
    result.surfaces = std::move(summary.surfaces);
    result.stats.emitted_flux_lm = summary.emitted_flux_lm;
    result.stats.absorbed_flux_lm = summary.absorbed_flux_lm;
    const auto solved = std::make_shared<const SolvedMesh>(display_mesh(scene, mesh, sides));
    if (options_.want_mesh) result.mesh = *solved;
    finish_stats(result, "monte-carlo", mesh.size(), rounds, reported, 0, scene.channels, stopped);
    result.stats.error_parts = error.parts;
    final_mesh_ = solved;
    final_mesh_version_ = mesh_version;
    return result;
}

}  // namespace radiant
