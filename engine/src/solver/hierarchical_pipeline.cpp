// The hierarchical path of the pipeline: root patches, element tree, links, sweeps, gather.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "formfactor/enclosure.h"
#include "hierarchy/element_tree.h"
#include "hierarchy/emitter_shot.h"
#include "hierarchy/hierarchical_gather.h"
#include "hierarchy/hierarchical_solver.h"
#include "hierarchy/leaf_mesh.h"
#include "hierarchy/link_refinement.h"
#include "hierarchy/sensor_importance.h"
#include "meshing/patch_mesh.h"
#include "solution/gouraud.h"
#include "solution/result_difference.h"
#include "solution/sensors.h"
#include "solution/surface_summary.h"
#include "solver/pipeline.h"
#include "visibility/occlusion_culling.h"

namespace radiant {
namespace {

// Root patches are this many times the dense path's patch edge; links refine below them.
constexpr double kRootEdgeFactor = 4;
// Elements stop splitting at this fraction of the dense path's patch edge.
constexpr double kMinEdgeFactor = 0.25;
// A link may leave this fraction of tolerance × the power leaving all surfaces uncertain
// (RenderPark's default relative threshold is 1e-5 of the power at a 1 % tolerance).
constexpr double kLinkPowerFraction = 2.5e-4;
// A node may add this fraction of tolerance × the mean irradiance to a sensor unopened.
constexpr double kGatherIrradianceFraction = 0.02;
// The patch-wise completion (see HierarchicalSystem::patchwise_completed) is one other answer,
// not a bracket: the truth lies beyond it as often as between (a unit cube's ceiling at tolerance
// 0.01: the alternative moved it by 0.34 %, its error was 0.43 %), so the difference counts twice.
constexpr double kCompletionMargin = 2;
// Share of the tolerance the linked system is solved to (a closed room's energy balance is
// then within a tenth of the tolerance: the engine core's bar).
constexpr double kSystemToleranceShare = 0.02;
// Snapshots' sensor values gather this much coarser than the result's, and only while a gather
// takes at most this share of the snapshot interval, so that they never slow the sweeps much.
constexpr double kSnapshotGatherCoarsening = 10;
constexpr double kSnapshotGatherShare = 0.25;
// The answer with the light of links never made filled in gathers this much coarser (on 150 000
// scattered triangles stopped at 5 s, as finely as the answer: 4.5 s).
constexpr double kUnlinkedGatherCoarsening = 10;
// Memory per root patch: the patch mesh with its OpenMesh faces and the enclosure and
// front-share tables (1.7 KB measured on the furnished office, resident), and the element tree
// as first built (its bytes() per root patch: 2.6 KB there).
constexpr std::size_t kRootPatchBytes = 2048;
constexpr std::size_t kFirstTreeBytesPerRoot = 3072;
// What the solve holds per element of the tree once it is linked: the linked system's arrays
// (≈ 100 B), the leaf meshes of a snapshot, the one it replaces, the result's and its copy
// (≈ 180 B each per leaf), and the leaves' summaries twice (≈ 80 B each); about half the
// elements are leaves.
constexpr std::size_t kLaterBytesPerElement = 512;
// Root patches beyond this would not fit the element budget.
constexpr std::size_t kMaxRootPatches = 2'000'000;
// Snapshots show the root patches until the links are refined (the leaves lit by the emitters'
// shot between the two stages of linking), then the leaves of the hierarchy.
constexpr std::uint64_t kRootMeshVersion = 1;
constexpr std::uint64_t kEmitterShotMeshVersion = 2;
constexpr std::uint64_t kLeafMeshVersion = 3;

// `light` with each leaf's missing factor (its patch's front share beyond its links' sum) filled
// with light of radiosity `fill`.
HierarchicalSystem::LeafLight with_missing_factors_filled(const ElementTree& tree,
                                                          const HierarchicalSystem& system,
                                                          const std::vector<double>& front_share,
                                                          HierarchicalSystem::LeafLight light,
                                                          double fill) {
    for (std::size_t e = 0; e < tree.size(); ++e) {
        const Element& x = tree[e];
        if (x.cluster || !x.leaf()) continue;
        const double missing =
            std::max(0.0, front_share[static_cast<std::size_t>(x.patch)] - system.factor_sum(e));
        for (std::size_t c = 0; c < 3; ++c) {
            light.irradiance[e][c] += missing * fill;
            light.radiosity[e][c] += x.reflectance[c] * missing * fill;
        }
    }
    return light;
}

}  // namespace

Result Pipeline::run_hierarchical(const PreparedSolve& input) {
    // Stage: meshing — the root patches, which of them are enclosed, and the element tree with
    // the luminaires' light on it.
    const StageStart meshing = begin_stage();
    Result result;
    result.scene = scene_.name;
    const PreparedScene& scene = input.scene;
    const Visibility& visibility = *input.visibility;
    const int channels = scene.channels;
    const double patch_edge = target_patch_edge(input.mean_free_path_m, options_.tolerance);

    // Only gaps narrower than the smallest element must cut the roots: wider ones are resolved
    // by refinement, as the dense path resolves those wider than half its patch.
    const MeshingOptions root_options{kRootEdgeFactor * patch_edge, kMaxRootPatches,
                                      0.5 * kMinEdgeFactor * patch_edge};
    // Memory: the plan of the roots, then the roots and the first tree must fit, or the solve
    // fails before building them; refinement then splits elements and makes links only while
    // they fit.
    std::optional<PatchPlan> root_plan =
        plan_within_limits(scene, root_options, "the hierarchical solver's root patches", result);
    if (!root_plan) return result;
    const std::size_t root_count = root_plan->count();
    const std::size_t first_bytes =
        root_count * (kRootPatchBytes + kFirstTreeBytesPerRoot + kLaterBytesPerElement);
    if (!memory_->fits(first_bytes)) {
        fail_for_memory(result,
                        memory_->refusal("the hierarchical solver's " + std::to_string(root_count) +
                                             " root patches and their element tree",
                                         first_bytes));
        return result;
    }
    MemoryHold roots_hold(*memory_, root_count * kRootPatchBytes);
    MemoryHold tree_hold(*memory_, first_bytes - roots_hold.bytes());
    const PatchMesh roots(scene, std::move(*root_plan));
    const auto stop = [this] { return should_stop(); };
    const std::vector<char> enclosed = enclosed_patches(
        scene, roots, visibility, input.triangle_piece, options_.seed, rays_, stop);
    const std::vector<double> front_share =
        front_shares(scene, roots, visibility, input.triangle_piece, options_.seed, enclosed,
                     kMinFrontShare, rays_, stop);
    std::vector<char> completed(roots.size());
    for (std::size_t i = 0; i < roots.size(); ++i) completed[i] = completes(front_share[i]);
    ElementTree tree(scene, roots, visibility, kMinEdgeFactor * patch_edge, options_.seed);
    rays_ += tree.light_from(0);

    // Scale of the light: emitted power, and the reflected irradiance it would make in a closed
    // room of this area and mean reflectance — a first guess of every element's radiosity.
    double emitted = 0, rho_area = 0, area = 0;
    for (std::size_t i = 0; i < roots.size(); ++i) {
        const PatchGeometry& p = roots.patch(i);
        const PreparedMaterial& m = scene.materials[static_cast<std::size_t>(p.material)];
        area += p.area_m2;
        rho_area += p.area_m2 * photometric(m.reflectance, channels);
        if (!p.back_side && !p.hidden)
            emitted += p.area_m2 * photometric(m.exitance_lm_m2, channels);
    }
    for (const PreparedLuminaire& l : scene.luminaires) emitted += photometric(l.flux_lm, channels);
    const double rho_mean = area > 0 ? std::min(rho_area / area, 0.999) : 0;
    const double ambient = area > 0 ? emitted * rho_mean / (area * (1 - rho_mean)) : 0;
    tree.estimate_from(0, ambient, channels);

    // The root patches lit by their source term (emission and reflected luminaire light) are
    // what the first sweep starts from; a viewer sees them while the links are refined.
    if (observer_) {
        std::vector<double> source(roots.size(), 0.0);
        for (std::size_t e = 0; e < tree.size(); ++e) {
            const Element& x = tree[e];
            if (x.cluster || x.depth > 0) continue;
            source[static_cast<std::size_t>(x.patch)] = photometric(source_radiosity(x), channels);
        }
        snapshots_.offer(
            std::make_shared<const SolvedMesh>(gouraud_mesh(roots, source, scene.world_origin)),
            kRootMeshVersion);
    }

    end_stage("meshing", meshing);
    // Stage: linking — which elements and clusters exchange light, and their form factors.
    const StageStart linking = begin_stage();
    report("form factors", 0.05);
    RefinementCriteria criteria;
    // Relative to all the light leaving surfaces (emitted and reflected), as the solution's error.
    double radiant_power = 0;
    for (std::size_t e = 0; e < tree.size(); ++e) {
        if (!tree[e].cluster)
            radiant_power += tree[e].area_m2 * photometric(tree[e].radiosity, channels);
    }
    criteria.power_epsilon_lm = kLinkPowerFraction * options_.tolerance * radiant_power;
    criteria.mean_radiosity = area > 0 ? radiant_power / area : 0;
    criteria.seed = options_.seed;
    criteria.ambient_irradiance = ambient;
    criteria.channels = channels;
    criteria.completed_patch = completed;
    // In a convex scene (a plain room, a sphere) whatever faces each other sees each other.
    const bool unoccluded = nothing_can_occlude(scene);
    criteria.unoccluded = unoccluded;
    // Surfaces the sensors cannot see, directly or by reflection, need not be refined as finely.
    const ImportanceEstimate importance = estimate_sensor_importance(
        scene, roots, tree, visibility, input.triangle_piece, options_.seed, stop);
    rays_ += importance.rays;
    criteria.receiver_weight = importance.refinement_weight;
    criteria.should_stop = stop;
    const std::uint64_t rays_before_links = rays_;
    criteria.on_round = [&](int rounds, std::uint64_t rays, std::size_t links) {
        rays_ = rays_before_links + rays;
        elements_ = tree.leaf_count();
        links_ = links;
        report("form factors", std::min(0.55, 0.05 + 0.02 * rounds));
    };
    // The tree's own estimate gives way to the refinement's accounting of it.
    tree_hold.resize(0);
    criteria.max_bytes = memory_->available_bytes();
    criteria.later_bytes_per_element = kLaterBytesPerElement;
    // Links are made lazily, as their sources come to shoot: the emitting patches' first; the
    // rest once the emitters have sent their light, which a viewer sees meanwhile.
    std::vector<char> emitting(roots.size(), 0);
    for (std::size_t e = 0; e < tree.size(); ++e) {
        const Element& x = tree[e];
        if (!x.cluster && x.depth == 0 && x.emits) emitting[static_cast<std::size_t>(x.patch)] = 1;
    }
    if (std::find(emitting.begin(), emitting.end(), 1) != emitting.end())
        criteria.ready_source = emitting;
    RefinementOutcome linked = refine_links(tree, visibility, criteria);
    if (!linked.deferred.empty() && !linked.stopped) {
        if (observer_) {
            // With the ambient guess of the reflected light, as the shooting snapshots show it.
            const std::vector<Rgb> shot = emitter_shot(tree, linked.links);
            std::vector<double> shown(tree.size(), 0.0);
            for (std::size_t e = 0; e < tree.size(); ++e) {
                const Element& x = tree[e];
                Rgb b;
                for (std::size_t c = 0; c < 3; ++c) {
                    b[c] = x.exitance[c] +
                           x.reflectance[c] * (x.luminaire_irradiance[c] + shot[e][c] + ambient);
                }
                shown[e] = photometric(b, channels);
            }
            snapshots_.offer(std::make_shared<const SolvedMesh>(
                                 leaf_mesh(tree, roots, shown, scene.world_origin)),
                             kEmitterShotMeshVersion);
        }
        criteria.ready_source = {};
        resume_links(linked, tree, visibility, criteria);
    }
    rays_ = rays_before_links + linked.rays;
    elements_ = tree.leaf_count();
    links_ = linked.links.size();
    tree_hold.resize(tree.bytes() + tree.size() * kLaterBytesPerElement +
                     linked.links.capacity() * sizeof(Link));
    if (linked.budget_reached) {
        stop_for_memory("the hierarchical solver's elements stopped splitting when they, their " +
                        std::to_string(linked.links.size()) +
                        " links and what the rest of the solve needs for them reached the budget "
                        "of " +
                        mebibytes_text(memory_->limit_bytes()));
    }
    end_stage("linking", linking);

    // Stage: solving — the linked system, and its answer with each patch's factors completed.
    const StageStart solving = begin_stage();
    // Linking cut short (cancelled, out of time) left pairs unlinked, whose receivers' factor
    // sums are short: completing them would hand the few links made, the emitters' first, the
    // light of the whole hemisphere (the furnished office stopped at 8 s: 4.5 times the emitted
    // light absorbed). Nothing is completed then; the estimate covers the missing factors.
    const bool cut_short = linked.stopped;
    const std::vector<char> none_enclosed(cut_short ? roots.size() : 0, 0);
    const std::vector<double> none_completed(cut_short ? roots.size() : 0, 0.0);
    HierarchicalSystem system(tree, linked.links, cut_short ? none_enclosed : enclosed,
                              cut_short ? none_completed : front_share, channels);
    // Sensors gather down the tree from the current radiosity, opening nodes that could add more
    // than a share of the tolerance × the mean irradiance (`coarsening` times that for previews),
    // with the luminaires' light or (`with_luminaires` false) without; the mean irradiance is
    // the solution's unless given.
    // The leaves' area-weighted mean of `irradiance(e)` (photometric).
    auto mean_leaf_irradiance = [&](auto&& irradiance) {
        double sum = 0;
        for (std::size_t e = 0; e < tree.size(); ++e) {
            const Element& x = tree[e];
            if (!x.cluster && x.leaf()) sum += x.area_m2 * photometric(irradiance(e), channels);
        }
        return area > 0 ? sum / area : 0;
    };
    auto gather_sensors = [&](double coarsening, bool with_luminaires = true,
                              std::optional<double> given_mean = std::nullopt) {
        const double mean_irradiance =
            given_mean ? *given_mean : mean_leaf_irradiance([&](std::size_t e) {
                return system.leaf_irradiance(static_cast<int>(e));
            });
        GatherCriteria gather;
        gather.irradiance_epsilon =
            coarsening * kGatherIrradianceFraction * options_.tolerance * mean_irradiance;
        gather.noise_share = coarsening * kSensorNoiseShare * options_.tolerance;
        gather.seed = options_.seed;
        gather.unoccluded = unoccluded;
        gather.with_luminaires = with_luminaires;
        return gather_sensors_from_tree(scene, tree, visibility, gather, channels, rays_);
    };
    report("solving", 0.6);
    // Sweeps are cheap next to linking: solve the linked system far below the tolerance, leaving
    // it to the links, and an unconverged iterate's missing light (absorbed < emitted) with it.
    SolverControl control = solving_control(kSystemToleranceShare * options_.tolerance);
    grant_sweep_grace(control);
    std::function<void()> publish;
    bool preview_sensors = !scene.sensors.empty();
    if (observer_) {
        publish = [&] {
            std::shared_ptr<const std::vector<SensorResult>> sensors;
            if (preview_sensors) {
                const auto begin = Clock::now();
                sensors = std::make_shared<const std::vector<SensorResult>>(
                    gather_sensors(kSnapshotGatherCoarsening));
                preview_sensors =
                    Clock::now() - begin <= kSnapshotGatherShare * control.snapshot_interval;
            }
            snapshots_.offer(std::make_shared<const SolvedMesh>(
                                 leaf_mesh(tree, roots, channels, scene.world_origin)),
                             kLeafMeshVersion, std::move(sensors));
        };
    }
    const HierarchicalOutcome outcome = system.solve(control, publish);

    auto solved_leaves = [&](const HierarchicalSystem::LeafLight& light) {
        std::vector<SolvedElement> solved;
        for (std::size_t e = 0; e < tree.size(); ++e) {
            const Element& x = tree[e];
            if (x.cluster || !x.leaf()) continue;
            const PatchGeometry& p = roots.patch(static_cast<std::size_t>(x.patch));
            solved.push_back({p.surface, p.material, x.area_m2, p.back_side, false,
                              light.irradiance[e], light.radiosity[e]});
        }
        for (std::size_t i = 0; i < roots.size(); ++i) {
            const PatchGeometry& p = roots.patch(i);
            if (p.hidden)
                solved.push_back({p.surface, p.material, p.area_m2, p.back_side, true, {}, {}});
        }
        return solved;
    };
    const HierarchicalSystem::LeafLight light = system.light();
    const std::vector<SolvedElement> solved = solved_leaves(light);
    // Completing each leaf's factor sum or each patch's gives two answers of the same links; the
    // estimate covers their difference (see HierarchicalSystem::patchwise_completed).
    std::optional<HierarchicalSystem::LeafLight> other;
    if (outcome.converged) other = system.patchwise_completed(control, criteria.receiver_weight);
    const auto mesh =
        std::make_shared<const SolvedMesh>(leaf_mesh(tree, roots, channels, scene.world_origin));
    end_stage("solving", solving);
    // Stage: gather — the sensors' light down the tree, from both answers.
    const StageStart gather = begin_stage();
    // The radiosity is final from here on; the heartbeat shows it while the sensors gather.
    snapshots_.offer(mesh, kLeafMeshVersion);
    report("sensors", 0.9, outcome.iterations);
    result.sensors = gather_sensors(1);
    // The other answer is compared where the error is stated, at the sensors (gathered alike),
    // or on the surfaces where there are none. What the sensors gather from the two answers'
    // difference on every leaf, taken with one sign, is how far apart they could be were every
    // leaf's answer off the same way (see below).
    std::optional<Result> patchwise;
    std::vector<SensorResult> one_signed;
    if (other) {
        patchwise.emplace();
        if (result.sensors.empty()) {
            patchwise->surfaces =
                summarise_surfaces(scene, solved_leaves(*other), channels).surfaces;
        } else {
            system.show_radiosity(*other);
            patchwise->sensors = gather_sensors(1);
            // show_radiosity reads the radiosity only.
            HierarchicalSystem::LeafLight gap;
            gap.radiosity = other->radiosity;
            for (std::size_t e = 0; e < tree.size(); ++e) {
                for (std::size_t c = 0; c < 3; ++c)
                    gap.radiosity[e][c] = std::abs(light.radiosity[e][c] - gap.radiosity[e][c]);
            }
            system.show_radiosity(gap);
            one_signed = gather_sensors(1, false);
            system.show_radiosity(light);
        }
    }

    SurfaceSummary summary = summarise_surfaces(scene, solved, channels);
    result.surfaces = std::move(summary.surfaces);
    result.stats.emitted_flux_lm = summary.emitted_flux_lm;
    result.stats.absorbed_flux_lm = summary.absorbed_flux_lm;
    // In a closed scene every lumen emitted is absorbed, and in none is more absorbed: an
    // imbalance is error of the links (and the estimate above bounds the linked system's only),
    // so the estimate may not claim less — nor less than the light the links lost before the
    // solver restored it. Light made shows where leaves' links miss much of what they face and
    // the completion of their factor sums fills it with the light of the rest (books packed on a
    // shelf: their links summed to 0.34 of the 0.91 their hemispheres face, and the furnished
    // office absorbed 8 % more than it emitted); no finer solve mends that.
    double error_estimate = std::max(outcome.error_estimate, outcome.conservation_defect);
    const bool closed = std::all_of(enclosed.begin(), enclosed.end(), [](char c) { return c; });
    const double made =
        summary.emitted_flux_lm > 0 ? summary.absorbed_flux_lm / summary.emitted_flux_lm - 1 : 0.0;
    error_estimate = std::max(error_estimate, closed ? std::abs(made) : made);
    const bool stopped = linked.stopped || linked.budget_reached || !outcome.converged ||
                         !(error_estimate <= options_.tolerance);
    if (!closed && made > options_.tolerance) {
        char share[32];
        std::snprintf(share, sizeof share, "%.1f %%", 100 * made);
        result.stop_reason = std::string("the hierarchical solver's links made ") + share +
                             " more light than the sources emit, as among densely packed small "
                             "objects; the monte-carlo method solves such scenes, with or "
                             "without sensors";
    }
    // Errors of the links that the mesh check cannot see; not of the iteration, so they do not
    // stop the result here: a finer solve can be asked for (refine_to_tolerance), and only a
    // result that still misses the tolerance after it is `stopped` (Pipeline::run).
    // At sensors the two answers' own difference can cancel what both share (office-x1 at 0.01:
    // 0.013 %, for an error of 0.06 %), so the estimate also takes their difference with one
    // sign on every leaf (0.065 % there), which is a worst case over the leaves' signs already.
    // The surfaces' RMS difference that stood for it was up to 6 times the error (two rooms at
    // 0.03: 0.66 % for 0.136 %; tests/bench/results/hierarchical-estimate.md).
    if (patchwise) {
        const double difference = relative_rms_difference(result, *patchwise);
        error_estimate = std::max(
            {error_estimate, kCompletionMargin * difference, sensor_rms_of(result, one_signed)});
    }
    double unlinked = 0;
    if (cut_short) {
        // Each leaf's missing factor is light it did not get: filled at twice the mean
        // radiosity, raised by the interreflections it would have fed (1 / (1 − ρ̄)), the answer
        // moves by what the estimate must cover.
        const HierarchicalSystem::LeafLight filled = with_missing_factors_filled(
            tree, system, front_share, light,
            kCompletionMargin * criteria.mean_radiosity / (1 - rho_mean));
        Result with_missing;
        if (result.sensors.empty()) {
            with_missing.surfaces =
                summarise_surfaces(scene, solved_leaves(filled), channels).surfaces;
        } else {
            // Gathered as finely as the filled light needs (without links, the solution's is
            // none at all: every node would be opened), and coarser than the answer: its error
            // is a share of the tolerance, the missing light's tens of per cent.
            system.show_radiosity(filled);
            with_missing.sensors = gather_sensors(
                kUnlinkedGatherCoarsening, true,
                mean_leaf_irradiance([&](std::size_t e) { return filled.irradiance[e]; }));
            system.show_radiosity(light);
        }
        // Measured against either answer: a dark one (a black receiver whose only link was
        // never made) measures nothing against itself.
        unlinked = std::max(relative_rms_difference(result, with_missing),
                            relative_rms_difference(with_missing, result));
    }
    if (options_.want_mesh) result.mesh = *mesh;
    end_stage("gather", gather);
    finish_stats(result, "hierarchical", roots.size(), outcome.iterations,
                 std::max(error_estimate, unlinked), 0, channels, stopped);
    // What the links lost or carried unevenly, apart from the iteration's residual, and the
    // light of the links never made.
    result.stats.error_parts.residual = outcome.error_estimate;
    if (error_estimate > outcome.error_estimate)
        result.stats.error_parts.completion = error_estimate;
    result.stats.error_parts.discretisation = unlinked;
    final_mesh_ = mesh;
    final_mesh_version_ = kLeafMeshVersion;
    return result;
}

}  // namespace radiant
