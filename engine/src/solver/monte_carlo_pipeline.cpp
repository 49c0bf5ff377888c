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
#include "solver/memory_estimates.h"
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

// A display triangle: three vertices with their radiosity, its corners, surface and radiosity.
constexpr std::size_t kDisplayBytesPerElement =
    3 * (sizeof(Vec3) + sizeof(double)) + sizeof(std::array<int, 3>) + sizeof(int) + sizeof(double);

// What one level of elements holds while its rounds run: the elements and their sides, the ray
// tracer over them, the photon tallies and a wave's deposits, the sensor points before their
// ray sets; and at its peak either the ray tracer's build (with the triangle list it copies) or
// the display meshes and the sides' summaries that snapshots and the result are made of (a
// snapshot is built while the one it replaces is still shown; the result's mesh is a copy).
std::size_t level_bytes(const ElementCount& count, std::size_t points, double survival,
                        int display_copies) {
    const std::size_t build = count.elements * (sizeof(Triangle) + kEmbreeBuildBytesPerTriangle -
                                                kEmbreeBytesPerTriangle);
    const std::size_t display =
        static_cast<std::size_t>(display_copies) *
        (count.elements * kDisplayBytesPerElement + count.sides * sizeof(SolvedElement));
    return count.elements * (sizeof(MeshElement) + kEmbreeBytesPerTriangle) +
           count.sides * (sizeof(ElementSide) + PhotonField::kBytesPerSide) +
           PhotonField::wave_bytes(survival) +
           points *
               (SensorGather::bytes_per_point() + 2 * kHeapBlockBytes + sizeof(GatheredPoint)) +
           std::max(build, display);
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

Rgb times(const Rgb& a, const Rgb& b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }

// Every element side as the surface summaries need it: irradiance from all photons, radiosity
// emitted (front) plus reflected.
std::vector<SolvedElement> solved_sides(const PreparedScene& scene, const ElementMesh& mesh,
                                        const PhotonField& field) {
    std::vector<SolvedElement> out;
    out.reserve(mesh.sides().size());
    for (std::size_t s = 0; s < mesh.sides().size(); ++s) {
        const ElementSide& side = mesh.sides()[s];
        const MeshElement& e = mesh[static_cast<std::size_t>(side.element)];
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

std::vector<SensorResult> sensor_results(const PreparedScene& scene,
                                         const std::vector<GatheredPoint>& points) {
    std::vector<SensorResult> out;
    std::size_t next = 0;
    for (const PreparedSensorSet& set : scene.sensors) {
        SensorResult r = sensor_result_for(set);
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
    // Memory: each level is estimated from its element count before it is built; ray sets are
    // added only as far as they fit.
    std::size_t sensor_points = 0;
    for (const std::size_t n : set_sizes) sensor_points += n;
    const double survival = mean_survival(scene);
    const int display_copies = (observer_ ? 2 : 1) + (options_.want_mesh ? 1 : 0);
    auto bytes_of = [&](const ElementCount& count) {
        return level_bytes(count, sensor_points, survival, display_copies);
    };
    double edge = kEdgeOfFreePath * input.mean_free_path_m;
    ElementCount count = ElementMesh::count(scene, edge);
    const std::size_t natural_bytes = bytes_of(count);
    // Coarser elements than the light's variation asks for, if the budget needs it: the
    // discretisation estimate then says what that costs, and the result is `stopped` if it
    // misses the tolerance.
    while (!memory_->fits(bytes_of(count))) {
        const ElementCount coarser = ElementMesh::count(scene, 2 * edge);
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
    MemoryHold level_hold(*memory_, bytes_of(count));
    MemoryHold sets_hold(*memory_, 0);
    for (int refinements = 0;; ++refinements, edge *= kRefinementRatio) {
        // Stage: meshing — elements, and a ray tracer over them so that a hit names its element.
        Clock::time_point stage_start = Clock::now();
        report("meshing", 0.02, rounds, reported);
        level.reset();  // the finer level replaces it (its estimate was held in its place)
        level = std::make_unique<MonteCarloLevel>(scene, edge, options_.seed);
        elements_ = level->mesh.size();
        mesh_version = kFirstMeshVersion + static_cast<std::uint64_t>(refinements);
        meshing.seconds += seconds_since(stage_start);
        meshing.memory_bytes = level->mesh.size() * sizeof(MeshElement) +
                               level->mesh.sides().size() * sizeof(ElementSide);
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
            report("photons", 0.1, rounds, reported);
            const std::uint64_t photon_rays =
                field.trace(budget.photons - std::min(budget.photons, field.photons()),
                            level->sources, *level->visibility, stop);
            rays_ += photon_rays;
            photons.rays += photon_rays;
            photons.seconds += seconds_since(stage_start);
            // Stage: gather — the sensors' ray sets, to this round's budget, as far as they fit.
            const std::size_t set_bytes = sensor_points * SensorGather::kBytesPerSet;
            const std::size_t fitting_sets =
                set_bytes == 0 ? static_cast<std::size_t>(budget.sets)
                               : (memory_->available_bytes() + sets_hold.bytes()) / set_bytes;
            bool sets_cut = false;
            if (fitting_sets < static_cast<std::size_t>(budget.sets)) {
                stop_for_memory(memory_->refusal(
                    std::to_string(budget.sets) + " ray sets at " + std::to_string(sensor_points) +
                        " sensor points",
                    (static_cast<std::size_t>(budget.sets) - gather.sets()) * set_bytes));
                budget.sets = std::max(gather.sets(), static_cast<int>(fitting_sets));
                sets_cut = true;
            }
            sets_hold.resize(static_cast<std::size_t>(budget.sets) * set_bytes);
            stage_start = Clock::now();
            report("gather", 0.5, rounds, reported);
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
            report("estimate", 0.9, rounds + 1, reported);
            // A round cut short by a cancel or the time limit has not earned `converged`.
            const bool complete = field.photons() >= budget.photons && gather.sets() >= budget.sets;
            if (!complete || should_stop()) {
                stopped = true;
                break;
            }
            if (reported <= options_.tolerance) break;
            if (sets_cut) {
                stopped = true;
                break;
            }
            // Bias does not fall with samples: a finer mesh does.
            if (!(error.parts.discretisation < kTargetShare * options_.tolerance)) {
                refine = refinements < kMaxRefinements;
                if (refine) {
                    // The finer level replaces this one, with the ray sets this one has.
                    const ElementCount finer = ElementMesh::count(scene, edge * kRefinementRatio);
                    const std::size_t finer_bytes =
                        bytes_of(finer) + static_cast<std::size_t>(gather.sets()) * set_bytes;
                    if (!memory_->fits(
                            finer_bytes -
                            std::min(finer_bytes, level_hold.bytes() + sets_hold.bytes()))) {
                        stop_for_memory(
                            memory_->refusal("monte-carlo's finer elements", finer_bytes));
                        refine = false;
                    } else {
                        level_hold.resize(bytes_of(finer));
                    }
                }
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
