#include "solver/pipeline.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>

#include <OpenMesh/Core/System/omstream.hh>

#include "checks/modelling_checks.h"
#include "design/light_components.h"
#include "formfactor/enclosure.h"
#include "formfactor/transport.h"
#include "meshing/patch_mesh.h"
#include "parallel/fork_join.h"
#include "parallel/per_thread.h"
#include "solution/gouraud.h"
#include "solution/result_difference.h"
#include "solution/sensors.h"
#include "solution/surface_summary.h"
#include "solver/memory_estimates.h"
#include "solver/shooting_solver.h"
#include "solver/solver.h"
#include "visibility/occluder_triangles.h"

namespace radiant {
namespace {

// Above this many patches the dense solvers' n² memory and time stop paying; the patch size
// grows instead (the hierarchical solver is the answer for larger models).
constexpr std::size_t kMaxDensePatches = 3000;
// Matrix-free shooting keeps O(patches) memory, but every shot costs O(patches) factors: the
// patch size stays at its target (no growth to fit a budget) unless the mesh would exceed this.
constexpr std::size_t kMaxMatrixFreePatches = 1'000'000;
// `auto` solves scenes with at most this many convex polygons densely: a handful of walls,
// where the full matrix costs less than building a hierarchy —
constexpr std::size_t kMaxAutoDensePolygons = 12;
// — unless its mesh would exceed this many patches, where the n² factors cost more than the
// hierarchy (2 cores, tolerance 0.01: the cube's 600 patches 0.65 s dense against 0.9 s; the
// furnace around a slab, 2984 patches, 29 s against 1.6 s) and the hierarchical estimate can
// meet the tolerance: a closed room's completion term keeps it at 0.2–0.4 %, so finer
// tolerances stay dense.
constexpr std::size_t kMaxAutoDensePatches = 1000;
constexpr double kMinAutoHierarchicalTolerance = 0.005;
// LU (O(n³)) beats iteration up to about here on two cores, at any reflectance.
constexpr std::size_t kMaxAutoDirectPatches = 1500;
// Without sensors `auto` solves scenes of more than this many convex polygons (furnished rooms)
// by Monte Carlo, which measures the noise of the surfaces' means and bounds their error there;
// among close objects the hierarchy's estimate was under its error (at 0.01, open plan of 377
// polygons: 2.8 % for an estimate of 0.90 %, in 8 s; meeting room: 1.1 % for 0.72 %; furnished
// office: stopped at 58 s), Monte Carlo's not (0.26–0.50 % for 0.80–0.99 %, 0.35–1.9 s). A room
// with less in it (two rooms joined by a door: 0.23 % for 0.57 %) is left to the hierarchy,
// which draws smooth surfaces where the photons' elements are speckled.
constexpr std::size_t kMaxAutoHierarchicalPolygons = 100;
// The discretisation check solves again at this many times the tolerance (patches twice as
// large), at most at kMaxCheckTolerance, and not at all if that is less than kMinCheckRatio
// times the tolerance (see check_discretisation and richardson_estimate). The cap is high
// because the estimate divides the difference by the ratio less one: checked at 0.5, the
// sphere's at 0.3 was 4.5 times its error; at 0.9, 3.8.
constexpr double kCheckCoarsening = 4;
constexpr double kMaxCheckTolerance = 0.9;
constexpr double kMinCheckRatio = 1.5;
// The order in patches at which the dense path's estimate takes its error to fall (see
// richardson_estimate).
constexpr double kDenseErrorOrder = 0.75;
// The hierarchical solver's difference counts this many times: its error does not follow its
// tolerance as closely as a dense mesh's follows its patch count.
constexpr double kHierarchicalCheckMargin = 3;
// A converged result whose estimate exceeds the tolerance is solved again finer (see
// refine_to_tolerance): each time the tolerance shrinks by the estimate over this share of the
// tolerance, by at least kMinRefineRatio (a smaller step would amplify the two solutions' noise)
// and at most kMaxRefineRatio, down to the asked tolerance over PipelineLimits::max_refinement.
constexpr double kRefineTarget = 0.7;
constexpr double kMinRefineRatio = 2;
constexpr double kMaxRefineRatio = 8;
// The estimate never claims less than this share of the tolerance: two solutions whose factors
// are each held far under it differ by their quadratures' noise as much as by their
// convergence, so the mesh check cannot resolve errors below it (parallel squares 0.5 m apart
// at 0.01: a hierarchical error of 2.1 % of the tolerance where the check's two solutions
// differed by 1 % of it). At 0.1 it still lets an error of 0.1 % be estimated within 4 times
// (issue 27). The dense path's factors are far closer (errors of 4e-6 at tolerance 0.1 where the
// two solutions agreed to 2e-8): its share is smaller, so that a loose tolerance's floor does
// not swamp an error of 0.1 % up to tolerance 0.4.
constexpr double kUnresolvedShare = 0.04;
constexpr double kDenseUnresolvedShare = 0.01;
// The dense matrix solvers solve the linear system to this share of the tolerance: their bound
// on the algebraic error (‖r‖ / (1 − q), area-weighted) is 2–8 times the error it bounds, and
// a few more sweeps of a matrix already built cost little next to its factors. It is half the
// estimate's floor, which then also holds what the mesh check cannot resolve: in a furnace of
// ρ 0.999 the bound is tight (the error is the slowest mode, uniform) and the factors' closure,
// amplified a thousandfold, put Jacobi's error 1 % above a system solved to the floor itself.
// Matrix-free shooting, whose every shot casts rays, stops at kMatrixFreeSystemShare.
constexpr double kDenseSystemShare = kDenseUnresolvedShare / 2;
constexpr double kMatrixFreeSystemShare = 0.25;
// Memory per patch of the dense path and of matrix-free shooting, besides the form-factor
// matrix: the patch mesh (PatchGeometry and OpenMesh faces), the linear system's arrays, the
// solved patches and the display meshes of two snapshots.
constexpr std::size_t kDensePatchBytes = 3072;
// What a discretisation check that could not coarsen the mesh (the tolerance already gives the
// scene's coarsest) claims, in tolerances: more than one, so that a finer solve measures it.
constexpr double kUncheckedShare = 2;
// What a solve stopped at its time limit would otherwise answer without a measure of its error
// may run this share of the limit past it: a hierarchical solve's sweeps of the links it made
// (unswept they answer with the emitters' first shot only: the furnished office, stopped as its
// linking ended, 18 % off), Monte Carlo's first round (the samples any estimate is made of),
// the dense form factor rows and their solve (else the first bounce: room-s2, 24 % off).
constexpr double kGraceShare = 0.1;
constexpr double kMinGraceSeconds = 0.5;
// Mesh versions of refined solutions: above those of either path (dense 1, hierarchical 1–3),
// so a viewer sees the triangles change.
constexpr std::uint64_t kFirstRefinedMeshVersion = 4;

// The error of the finer of two solutions whose discretisations differ by `ratio` (see
// mesh_ratio), from their difference: errors fall as ratio^-order, so it is about difference /
// (ratio^order − 1). A dense mesh's error falls as 1 / patches (O(h²)) where light is smooth —
// the cube's floor and walls: their error times the patch count stays within 3 % from 96 to 600
// patches — but slower along edges where surfaces meet: the cube's emitting ceiling, which sees
// mostly the walls' edges, received 5.1 % too little at 24 patches and 1.64 % at 96, and the
// box rooms' RMS errors at 0.01 are up to 1.25 times the order-1 estimate; kDenseErrorOrder
// covers them. The difference is measured as the estimate is stated (relative_rms_difference);
// the hierarchical solver's at order 1 in the tolerance, kHierarchicalCheckMargin times over.
// A dense mesh's difference counts on the surfaces too where there are sensors: two meshes'
// errors can cancel at a work plane (room-s2, 85 and 247 patches: errors of 0.58 % and 0.31 %
// whose work planes differed by 0.31 %, an estimate of 0.26 %; their surfaces by 0.82 %). The
// hierarchical solver's surfaces differ far more than its error between tolerances (office-x4
// at 0.1: 27 times), so its check keeps to the sensors.
double richardson_estimate(const std::string& method, const Result& fine, const Result& coarse,
                           double ratio) {
    const double difference = relative_rms_difference(fine, coarse);
    if (method == "hierarchical") return kHierarchicalCheckMargin * difference / (ratio - 1);
    return std::max(difference, surface_rms_difference(fine, coarse)) /
           (std::pow(ratio, kDenseErrorOrder) - 1);
}

// Without a matrix the patches keep their target size, and only gaps narrower than an eighth of
// it cut them (the hierarchical roots' gap at this tolerance): every patch costs a factor in
// every shot, and the dense mesh's half-patch gap splits the floor along every piece of
// furniture (office-x64: 100 000 patches).
MeshingOptions dense_meshing(double patch_edge, std::size_t max_patches, bool matrix_free) {
    return matrix_free ? MeshingOptions{patch_edge, max_patches, 0.125 * patch_edge}
                       : MeshingOptions{patch_edge, max_patches};
}

// How much finer `fine`'s discretisation is than `coarse`'s, in the units its error goes with:
// the tolerance for the hierarchical solver, patches for a dense mesh (error ∝ h² ∝ 1/patches),
// which stops growing with the tolerance at the scene's coarsest mesh.
double mesh_ratio(const std::string& method, double tolerance_ratio, const Result& fine,
                  const Result& coarse) {
    if (method == "hierarchical") return tolerance_ratio;
    return static_cast<double>(fine.stats.patches) /
           static_cast<double>(std::max<std::size_t>(coarse.stats.patches, 1));
}

}  // namespace

Pipeline::Pipeline(const Scene& scene, const SolveOptions& options, SolveObserver* observer,
                   const CancellationToken* cancel, PipelineLimits limits)
    : scene_(scene),
      options_(options),
      observer_(observer),
      cancel_(cancel),
      limits_(limits),
      start_(Clock::now()),
      snapshots_(observer, options.snapshot_interval_seconds, start_),
      memory_(std::make_shared<MemoryBudget>(
          options.max_memory_bytes > 0 ? options.max_memory_bytes : physical_memory_bytes() / 2)) {
    if (options.max_seconds) {
        deadline_ = start_ + std::chrono::duration_cast<Clock::duration>(
                                 std::chrono::duration<double>(*options.max_seconds));
    }
}

Pipeline::Pipeline(const Pipeline& parent, const SolveOptions& options)
    : Pipeline(parent.scene_, options, nullptr, parent.cancel_, parent.limits_) {
    memory_ = parent.memory_;
    nested_ = true;
}

Pipeline::StageStart Pipeline::begin_stage() {
    // A nested solve leaves the peak to its parent's stage.
    return {Clock::now(), rays_, nested_ ? 0 : memory_->restart_peak()};
}

void Pipeline::end_stage(const std::string& name, const StageStart& start) {
    if (nested_) return;
    const std::size_t peak = memory_->peak_bytes();
    stages_.push_back({name, seconds_since(start.time), rays_ - start.rays,
                       peak > start.held_bytes ? peak - start.held_bytes : 0});
}

void Pipeline::report(const std::string& stage, double fraction, std::size_t iterations,
                      std::optional<double> estimate, double unshot) const {
    if (!observer_) return;
    Progress p;
    p.stage = stage;
    p.fraction = fraction;
    p.iterations = iterations;
    p.error_estimate = estimate;
    p.unshot_fraction = unshot;
    p.elapsed_seconds = elapsed();
    p.rays = rays_;
    p.elements = elements_;
    p.links = links_;
    last_progress_ = p;
    snapshots_.note_progress(p);
    observer_->on_progress(p);
}

void Pipeline::publish_final(const Result& result) {
    if (!observer_ || !final_mesh_) return;
    Progress progress = last_progress_;
    progress.error_estimate = result.stats.error_estimate;
    snapshots_.finish(final_mesh_, final_mesh_version_,
                      std::make_shared<const std::vector<SensorResult>>(result.sensors), progress);
}

void Pipeline::check_discretisation(const PreparedSolve& prepared, const std::string& method,
                                    Result& result, bool matrix_free) {
    const double coarse_tolerance =
        std::min(kCheckCoarsening * options_.tolerance, kMaxCheckTolerance);
    const double ratio = coarse_tolerance / options_.tolerance;
    // Matrix-free shooting is never refined: where no coarser mesh measures its mesh's error, it
    // reports the bound of its linear system alone.
    const double unchecked = matrix_free ? 0.0 : kUncheckedShare * options_.tolerance;
    // No coarser solve to measure by — tolerances above kMaxCheckTolerance / kMinCheckRatio, or
    // a dense mesh made of the model's own polygons, split where other surfaces touch them,
    // which may not coarsen (known before solving it again: dense shooting on office-x4 at 0.3
    // spent 145 s on a coarse mesh of 6 707 patches, against its own 6 521): as for a mesh that
    // does not coarsen, a finer solve measures the error instead.
    bool coarsens = ratio >= kMinCheckRatio;
    if (coarsens && method != "hierarchical") {
        const double edge = target_patch_edge(prepared.mean_free_path_m, coarse_tolerance);
        // A plan that does not fit counts fewer: the check's own solve then refuses it.
        const std::size_t coarse_patches =
            PatchPlan(
                prepared.scene,
                within_limits(dense_meshing(
                    edge, matrix_free ? kMaxMatrixFreePatches : kMaxDensePatches, matrix_free)))
                .count();
        coarsens = static_cast<double>(result.stats.patches) >=
                   kMinCheckRatio * static_cast<double>(coarse_patches);
    }
    if (!coarsens) {
        result.stats.error_parts.discretisation = unchecked;
        result.stats.error_estimate = std::max(result.stats.error_estimate, unchecked);
        return;
    }
    // Not yet the answer's estimate: the mesh's part comes from this check.
    report("checking", 0.95, result.stats.iterations, std::nullopt, result.stats.unshot_fraction);
    SolveOptions coarse = options_within_deadline(coarse_tolerance);
    coarse.want_mesh = false;
    bool finished = !should_stop();
    double estimate = result.stats.error_estimate;
    if (finished) {
        Pipeline check(*this, coarse);
        // Its linear system is solved as far as this one's, so that the difference is the
        // mesh's, not the iteration's.
        check.system_tolerance_scale_ = options_.tolerance / coarse_tolerance;
        const Result c = check.run_method(prepared, method, matrix_free);
        rays_ += check.rays_;
        if (!check.memory_stop_.empty()) stop_for_memory(check.memory_stop_);
        finished = c.status == SolveStatus::converged;
        if (finished) {
            const double measured = mesh_ratio(method, ratio, result, c);
            // The same mesh twice shows no error at all, whatever this mesh's is.
            const double discretisation = measured >= kMinCheckRatio
                                              ? richardson_estimate(method, result, c, measured)
                                              : unchecked;
            result.stats.error_parts.discretisation = discretisation;
            estimate = std::max(estimate, discretisation);
        }
    }
    // Cut short (the time limit, a cancel, the check's own solve stopped), the mesh's error is
    // unmeasured: it claims what a mesh that does not coarsen claims, not the linear system's
    // bound alone (room-s2, `direct` stopped as the check began: 0.01 % for an error of 0.14 %).
    if (!finished) {
        result.stats.error_parts.discretisation = unchecked;
        estimate = std::max(estimate, unchecked);
    }
    result.stats.error_estimate = estimate;
    result.stats.rays = rays_;
    result.stats.seconds = elapsed();
    if (!finished) result.status = SolveStatus::stopped;
}

void Pipeline::refine_to_tolerance(const PreparedSolve& prepared, std::string method,
                                   Result& result) {
    double solved_tolerance = options_.tolerance;
    const double finest = options_.tolerance / limits_.max_refinement;
    for (std::uint64_t round = 0; result.status == SolveStatus::converged &&
                                  !(result.stats.error_estimate <= options_.tolerance);
         ++round) {
        // In steps of √2, so that a rounding difference in the estimate (the same room in
        // millimetres) does not change the mesh.
        const double wanted = result.stats.error_estimate / (kRefineTarget * options_.tolerance);
        const double ratio = std::min(std::clamp(std::exp2(0.5 * std::ceil(2 * std::log2(wanted))),
                                                 kMinRefineRatio, kMaxRefineRatio),
                                      solved_tolerance / finest);
        if (should_stop()) {
            result.status = SolveStatus::stopped;
            break;
        }
        if (!(ratio >= kMinRefineRatio)) break;  // also a NaN estimate: nothing to refine by
        const SolveOptions finer = options_within_deadline(solved_tolerance / ratio);
        // The dense path's mesh cannot outgrow its patch budget: `auto` goes on with the
        // hierarchical solver, the others with the finest mesh that fits, once.
        bool switched = false;
        if (method != "hierarchical") {
            const DenseMeshSize size = dense_mesh_size(prepared, finer.tolerance);
            if (!size.fits && options_.method == "auto") {
                method = "hierarchical";
                switched = true;
            } else if (!(static_cast<double>(size.patches) >=
                         kMinCheckRatio * static_cast<double>(result.stats.patches))) {
                // The finest mesh that fits, or one the model's polygons hold at this size, is
                // not finer enough to measure by (errors go as h², i.e. as 1 / patches).
                break;
            }
        }
        report("refining", 0.95, result.stats.iterations, result.stats.error_estimate,
               result.stats.unshot_fraction);
        Pipeline refined(*this, finer);
        Result f = refined.run_method(prepared, method);
        if (!refined.memory_stop_.empty()) stop_for_memory(refined.memory_stop_);
        // A finer solve's own estimate need only meet the asked tolerance, not its own; it is
        // judged against that below.
        bool finished = f.status == SolveStatus::converged ||
                        (f.status == SolveStatus::stopped && !should_stop() &&
                         f.stats.error_estimate <= options_.tolerance);
        if (finished) f.status = SolveStatus::converged;
        // Richardson's estimate from the two solutions, as check_discretisation's; a solution
        // of the other method gets its own check instead.
        if (finished && switched) {
            refined.check_discretisation(prepared, method, f);
            finished = f.status == SolveStatus::converged;
        } else if (finished) {
            const double measured = mesh_ratio(method, ratio, f, result);
            finished = measured >= kMinCheckRatio;
            if (finished) {
                f.stats.error_parts.discretisation =
                    richardson_estimate(method, f, result, measured);
                f.stats.error_estimate =
                    std::max(f.stats.error_estimate, f.stats.error_parts.discretisation);
            }
        }
        rays_ += refined.rays_;
        if (!finished) {
            if (should_stop()) result.status = SolveStatus::stopped;
            break;
        }
        result = std::move(f);
        solved_tolerance = finer.tolerance;
        final_mesh_ = refined.final_mesh_;
        final_mesh_version_ = kFirstRefinedMeshVersion + round;
    }
    result.stats.rays = rays_;
    result.stats.seconds = elapsed();
}

Result Pipeline::run_method(const PreparedSolve& prepared, const std::string& method,
                            bool matrix_free) {
    return method == "hierarchical" ? run_hierarchical(prepared)
                                    : run_dense(prepared, method, matrix_free);
}

SolveOptions Pipeline::options_within_deadline(double tolerance) const {
    SolveOptions options = options_;
    options.tolerance = tolerance;
    if (deadline_)
        options.max_seconds = std::chrono::duration<double>(*deadline_ - Clock::now()).count();
    return options;
}

bool Pipeline::prefers_hierarchy(const DenseMeshSize& size) const {
    return size.patches > kMaxAutoDensePatches &&
           options_.tolerance >= kMinAutoHierarchicalTolerance;
}

Pipeline::DenseMeshSize Pipeline::dense_mesh_size(const PreparedSolve& prepared,
                                                  double tolerance) const {
    const double edge = target_patch_edge(prepared.mean_free_path_m, tolerance);
    const PatchPlan plan(prepared.scene, within_limits({edge, kMaxDensePatches}));
    return {plan.count(), !plan.exceeded() && plan.target_edge_m() <= edge};
}

MeshingOptions Pipeline::within_limits(MeshingOptions meshing) const {
    meshing.max_plan_bytes = memory_->available_bytes();
    meshing.should_stop = [this] { return should_stop(); };
    return meshing;
}

std::optional<PatchPlan> Pipeline::plan_within_limits(const PreparedScene& scene,
                                                      const MeshingOptions& meshing,
                                                      const std::string& what, Result& result) {
    PatchPlan plan(scene, within_limits(meshing));
    if (plan.exceeded()) {
        fail_for_memory(result,
                        memory_->refusal("planning " + what + " (the pieces' contacts cut them)",
                                         plan.least_bytes()));
        return std::nullopt;
    }
    return plan;
}

SolverControl Pipeline::solving_control(double tolerance) const {
    tolerance *= system_tolerance_scale_;
    SolverControl control;
    control.tolerance = tolerance;
    control.deadline = deadline_;
    control.cancel = cancel_;
    control.progress = [this, tolerance](std::size_t it, double err, double unshot) {
        report(
            "solving",
            0.6 + 0.3 * std::clamp(std::log(std::max(err, 1e-300)) / std::log(tolerance), 0.0, 1.0),
            it, std::nullopt, unshot);
    };
    control.snapshot_interval = std::chrono::duration<double>(options_.snapshot_interval_seconds);
    return control;
}

std::optional<Pipeline::Clock::duration> Pipeline::grace() const {
    if (nested_ || !deadline_ || (cancel_ && cancel_->cancelled())) return std::nullopt;
    return std::max<Clock::duration>(
        std::chrono::duration_cast<Clock::duration>(kGraceShare * (*deadline_ - start_)),
        std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(kMinGraceSeconds)));
}

void Pipeline::grant_sweep_grace(SolverControl& control) const {
    const Clock::time_point now = Clock::now();
    const std::optional<Clock::duration> extra = grace();
    if (extra && now >= *deadline_) control.deadline = now + *extra;
}

std::optional<Pipeline::Clock::time_point> Pipeline::graced_deadline() const {
    const std::optional<Clock::duration> extra = grace();
    return extra ? std::optional<Clock::time_point>(*deadline_ + *extra) : deadline_;
}

bool Pipeline::should_stop_after_grace() const {
    const std::optional<Clock::time_point> until = graced_deadline();
    return (cancel_ && cancel_->cancelled()) || (until && Clock::now() >= *until);
}

void Pipeline::finish_stats(Result& result, const std::string& method, std::size_t patches,
                            std::size_t iterations, double error_estimate, double unshot_fraction,
                            int channels, bool stopped) const {
    SolveStats& st = result.stats;
    st.method = method;
    st.patches = patches;
    st.elements = elements_;
    st.links = links_;
    st.iterations = iterations;
    st.rays = rays_;
    st.unshot_fraction = unshot_fraction;
    st.error_estimate = error_estimate;
    st.error_parts.residual = error_estimate;  // the linear system's; checks add their parts
    st.channels = channels;
    st.threads = arena_threads();
    st.seconds = elapsed();
    result.status = stopped ? SolveStatus::stopped : SolveStatus::converged;
}

Result Pipeline::run() {
    Result result;
    result.scene = scene_.name;

    report("meshing", 0.0);
    const StageStart prepare_start = begin_stage();
    // The scene counts in the budget (the caller holds it while it is solved), and so does its
    // preparation; a budget they do not fit fails the solve before anything is allocated.
    const std::size_t input_bytes = scene_bytes(scene_);
    const std::size_t preparation_bytes = preparation_peak_bytes(scene_);
    if (!memory_->fits(input_bytes + preparation_bytes)) {
        result.error = "memory budget: " + memory_->refusal("the scene and its preparation",
                                                            input_bytes + preparation_bytes);
        return result;
    }
    const MemoryHold input_hold(*memory_, input_bytes);
    MemoryHold preparation_hold(*memory_, preparation_bytes);
    PreparedSolve prepared;
    prepared.scene = prepare_scene(scene_);
    if (prepared.scene.pieces.empty()) {
        result.error = "the scene has no surface with a non-zero area";
        return result;
    }
    const std::size_t polygons = prepared.scene.pieces.size();
    std::string method = options_.method;
    // Groups, several maintenance factors and non-planar sensor kinds need the Monte Carlo
    // method (docs/lighting-design.md).
    const std::string monte_carlo_only = monte_carlo_only_reason(scene_);
    if (!monte_carlo_only.empty() && method != "auto" && method != "monte-carlo") {
        result.error = monte_carlo_only + ", not \"" + method + "\"";
        return result;
    }
    if (method == "auto" && !monte_carlo_only.empty()) method = "monte-carlo";
    // Rooms with furniture and sensors: photons and a final gather cost little per polygon and
    // measure their own error where it is asked for (the sensors); without sensors, on the
    // surfaces' means (kMaxAutoHierarchicalPolygons). A handful of walls stays dense: its
    // surfaces are exact there.
    const bool has_sensors =
        std::any_of(prepared.scene.sensors.begin(), prepared.scene.sensors.end(),
                    [](const PreparedSensorSet& s) { return !s.points.empty(); });
    if (method == "auto" && polygons > kMaxAutoDensePolygons) {
        method =
            has_sensors || polygons > kMaxAutoHierarchicalPolygons ? "monte-carlo" : "hierarchical";
    }
    // Beyond the dense limit only shooting can do without the matrix, and it does so as soon as
    // the mesh cannot fit the matrix's patch budget.
    const bool matrix_free = method == "shooting" && polygons > limits_.max_dense_shooting_polygons;
    const bool dense = method != "hierarchical" && method != "monte-carlo" && method != "shooting";
    if (dense && polygons > limits_.max_dense_polygons) {
        result.error = "the scene has " + std::to_string(polygons) +
                       " convex polygons; the dense solvers handle at most " +
                       std::to_string(limits_.max_dense_polygons) +
                       " (use method \"hierarchical\" or \"shooting\")";
        return result;
    }
    omerr().disable();  // T-junction fallbacks are expected, not errors to print
    auto [triangles, triangle_piece] = occluder_triangles(prepared.scene);
    prepared.triangle_piece = std::move(triangle_piece);
    prepared.visibility = make_embree_visibility(triangles);
    prepared.mean_free_path_m = mean_free_path(prepared.scene, *prepared.visibility,
                                               prepared.triangle_piece, options_.seed, rays_);
    if (method == "auto" && prefers_hierarchy(dense_mesh_size(prepared, options_.tolerance)))
        method = "hierarchical";
    end_stage("prepare", prepare_start);
    // Stage: checks — what looks like a modelling mistake, on the ray tracer just built and
    // before any solving work, so that a strict solve refuses at once.
    const StageStart checks_start = begin_stage();
    std::uint64_t check_rays = 0;
    std::vector<Warning> warnings =
        modelling_warnings({scene_, prepared.scene, *prepared.visibility, triangles,
                            prepared.triangle_piece, options_.seed},
                           check_rays);
    // Embree holds its own copy; the checks were the last to read this one (emitting surfaces'
    // light paths start on its triangles). Until it goes, the preparation's peak stays held.
    std::vector<Triangle>().swap(triangles);
    preparation_hold.resize(preparation_held_bytes(scene_));
    rays_ += check_rays;
    end_stage("checks", checks_start);
    if (observer_ && !warnings.empty()) observer_->on_warnings(warnings);
    if (options_.strict && !warnings.empty()) {
        result.error = "strict: the scene has warnings: " + describe_warnings(warnings);
        result.warnings = std::move(warnings);
        return result;
    }
    if (method == "monte-carlo") {
        Result solved = run_monte_carlo(prepared);
        if (solved.status != SolveStatus::failed) {
            floor_estimate(solved);
            finish(solved);
        }
        solved.warnings = std::move(warnings);
        return solved;
    }
    Result solved = method == "hierarchical" ? run_hierarchical(prepared)
                                             : run_dense(prepared, method, matrix_free);
    // In a cluttered room the cross-check below replaces the hierarchical solver's estimate, so
    // its mesh check and refinement would be spent for nothing (the furnished office at 0.1:
    // 26 s of 53).
    const bool cluttered = polygons > kMaxAutoHierarchicalPolygons;
    // Matrix-free shooting is for models too large to solve at a finer tolerance; the coarser
    // mesh of the check costs it about a sixteenth of its own.
    if (solved.status == SolveStatus::converged && !(cluttered && method == "hierarchical")) {
        const StageStart check_start = begin_stage();
        check_discretisation(prepared, method, solved, matrix_free);
        if (!matrix_free) refine_to_tolerance(prepared, method, solved);
        end_stage("checking", check_start);
    }
    // Stage: cross-check — among clutter a radiosity method's own estimate cannot be taken on
    // trust (docs/accuracy.md, "Bookshelves").
    if (cluttered && solved.status != SolveStatus::failed) {
        if (!should_stop() && memory_stop_.empty()) {
            const StageStart cross_start = begin_stage();
            cross_check(prepared, solved);
            end_stage("cross-check", cross_start);
        } else if (method == "hierarchical") {
            // Past the time limit, cancelled or out of memory: nothing vouches for its estimate.
            solved.status = SolveStatus::stopped;
        }
    }
    // The sensor sets' and light scenes' estimates derive from the floored one.
    floor_estimate(solved);
    if (solved.status != SolveStatus::failed) finish_lighting(prepared, solved);
    finish(solved);
    solved.warnings = std::move(warnings);
    return solved;
}

void Pipeline::stop_for_memory(const std::string& refusal) {
    if (memory_stop_.empty()) memory_stop_ = refusal;
}

void Pipeline::fail_for_memory(Result& result, const std::string& refusal) {
    stop_for_memory(refusal);
    result.error = "memory budget: " + refusal;
}

void Pipeline::floor_estimate(Result& solved) const {
    const bool dense =
        solved.stats.method != "hierarchical" && solved.stats.method != "monte-carlo";
    const double least = (dense ? kDenseUnresolvedShare : kUnresolvedShare) * options_.tolerance;
    solved.stats.error_estimate = std::max(solved.stats.error_estimate, least);
    for (SensorResult& set : solved.sensors) {
        if (set.error_estimate > 0) set.error_estimate = std::max(set.error_estimate, least);
    }
}

void Pipeline::finish(Result& solved) {
    // `converged` promises an estimate within the tolerance (contract §3). A result whose finest
    // mesh still misses it is the best one within the limits, as at the time limit.
    if (solved.status == SolveStatus::converged &&
        !(solved.stats.error_estimate <= options_.tolerance)) {
        solved.status = SolveStatus::stopped;
    }
    // Nor does a mesh the memory budget kept coarser than the tolerance asked for: its estimate
    // (Richardson's, from two meshes the budget may have made alike) cannot vouch for it.
    if (solved.status == SolveStatus::converged && !memory_stop_.empty()) {
        solved.status = SolveStatus::stopped;
    }
    if (solved.status == SolveStatus::stopped && solved.stop_reason.empty()) {
        if (cancel_ && cancel_->cancelled()) {
            solved.stop_reason = "cancelled";
        } else if (!memory_stop_.empty()) {
            solved.stop_reason = "memory budget: " + memory_stop_;
        } else if (deadline_ && Clock::now() >= *deadline_) {
            char limit[64];
            std::snprintf(limit, sizeof limit, "the time limit of %g s", *options_.max_seconds);
            solved.stop_reason = limit;
        } else {
            solved.stop_reason = "the estimate exceeds the tolerance on the finest mesh tried";
        }
    }
    solved.stats.stages = stages_;
    publish_final(solved);
    report("done", 1.0, solved.stats.iterations, solved.stats.error_estimate,
           solved.stats.unshot_fraction);
}

Result Pipeline::run_dense(const PreparedSolve& solve_input, const std::string& requested,
                           bool matrix_free) {
    // Stage: meshing — the patches.
    const StageStart meshing_start = begin_stage();
    Result result;
    result.scene = scene_.name;
    const PreparedScene& prepared = solve_input.scene;
    const Visibility& visibility = *solve_input.visibility;
    const double patch_edge = target_patch_edge(solve_input.mean_free_path_m, options_.tolerance);
    // Memory: the patches and the matrix with the solver's own copy of it must fit; the patch
    // budget shrinks (patches grow) until they do.
    auto dense_bytes = [&](std::size_t patch_count) {
        const std::string& m = requested != "auto"                    ? requested
                               : patch_count <= kMaxAutoDirectPatches ? "direct"
                                                                      : "gauss-seidel";
        const std::size_t per_factor = matrix_free
                                           ? 0
                                           : sizeof(float) + (m == "direct"     ? 2 * sizeof(double)
                                                              : m == "shooting" ? sizeof(float)
                                                                                : 0);
        return patch_count * kDensePatchBytes + patch_count * patch_count * per_factor;
    };
    std::size_t max_patches = matrix_free ? kMaxMatrixFreePatches : kMaxDensePatches;
    const std::size_t wanted_bytes = dense_bytes(max_patches);
    bool patches_cut = false;
    while (max_patches > 1 && !memory_->fits(dense_bytes(max_patches))) {
        max_patches -= std::max<std::size_t>(1, max_patches / 16);
        patches_cut = true;
    }
    // Counted before it is built: a piece is one patch at least, and the lines where other
    // surfaces touch it split it further, so the mesh can exceed max_patches.
    std::optional<PatchPlan> plan = plan_within_limits(
        prepared, dense_meshing(patch_edge, max_patches, matrix_free), "the patches", result);
    if (!plan) return result;
    const std::size_t n = plan->count();
    if (!memory_->fits(dense_bytes(n))) {
        fail_for_memory(result,
                        memory_->refusal(std::to_string(n) + " patches and their form factors",
                                         dense_bytes(n)));
        return result;
    }
    PatchMesh patches(prepared, std::move(*plan));
    if (patches_cut && patches.target_edge_m() > patch_edge) {
        stop_for_memory(memory_->refusal("the patches the tolerance asks for", wanted_bytes));
    }
    end_stage("meshing", meshing_start);
    // Stage: form factors — the matrix (without one, the luminaires' light only).
    const StageStart factors_start = begin_stage();
    const MemoryHold dense_hold(*memory_, dense_bytes(n));
    const int channels = prepared.channels;

    const OcclusionCulling culling(prepared);
    TransportOptions transport_options;
    transport_options.seed = options_.seed;
    const Transport transport(
        prepared, patches, visibility, culling, transport_options,
        enclosed_patches(prepared, patches, visibility, solve_input.triangle_piece, options_.seed,
                         rays_, [this] { return should_stop(); }));

    auto display_mesh = [&](const std::array<std::vector<double>, 3>& v) {
        std::vector<double> display(n);
        for (std::size_t i = 0; i < n; ++i) {
            display[i] = photometric(
                Rgb{v[0][i], channels > 1 ? v[1][i] : 0, channels > 1 ? v[2][i] : 0}, channels);
        }
        return std::make_shared<const SolvedMesh>(
            gouraud_mesh(patches, display, prepared.world_origin));
    };
    // Before any light is transported the solution is the emission; a viewer sees it while the
    // form factors are computed.
    if (observer_) {
        std::array<std::vector<double>, 3> emitted;
        for (int c = 0; c < channels; ++c) {
            const auto ci = static_cast<std::size_t>(c);
            emitted[ci].assign(n, 0.0);
            for (std::size_t i = 0; i < n; ++i) {
                const PatchGeometry& p = patches.patch(i);
                const PreparedMaterial& m =
                    prepared.materials[static_cast<std::size_t>(p.material)];
                if (!p.back_side && !p.hidden) emitted[ci][i] = m.exitance_lm_m2[ci];
            }
        }
        snapshots_.offer(display_mesh(emitted), 1);
    }

    // Form factors, one receiver row per task; rays counted per thread. Without a matrix only
    // the luminaires' light is computed here; the factors come row by row while shooting.
    report("form factors", 0.05);
    std::vector<float> form_factors(matrix_free ? 0 : n * n, 0.0f);
    std::vector<Rgb> luminaire_irradiance(n, Rgb{0, 0, 0});
    PerThread<std::uint64_t> ray_count([] { return std::uint64_t{0}; });
    std::atomic<bool> interrupted{false};
    parallel_for(0, n, [&](std::size_t i) {
        if (interrupted.load(std::memory_order_relaxed)) return;
        if (should_stop_after_grace()) {
            interrupted = true;
            return;
        }
        std::uint64_t& local = ray_count.local();
        if (!matrix_free) transport.form_factor_row(i, &form_factors[i * n], local);
        luminaire_irradiance[i] = transport.luminaire_irradiance_on_patch(i, local);
    });
    rays_ += ray_count.combine([](std::uint64_t a, std::uint64_t b) { return a + b; });
    elements_ = n;
    links_ = static_cast<std::size_t>(
        std::count_if(form_factors.begin(), form_factors.end(), [](float f) { return f > 0; }));
    end_stage("form factors", factors_start);
    // Stage: solving — the linear system (matrix-free shooting computes its factors here).
    const StageStart solving = begin_stage();

    LinearSystem system;
    system.n = n;
    system.channels = channels;
    system.form_factors = matrix_free ? nullptr : &form_factors;
    system.area_m2.resize(n);
    for (int c = 0; c < channels; ++c) {
        system.reflectance[static_cast<std::size_t>(c)].resize(n);
        system.source[static_cast<std::size_t>(c)].resize(n);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const PatchGeometry& p = patches.patch(i);
        const PreparedMaterial& m = prepared.materials[static_cast<std::size_t>(p.material)];
        system.area_m2[i] = p.area_m2;
        for (int c = 0; c < channels; ++c) {
            const auto ci = static_cast<std::size_t>(c);
            const double emitted = p.back_side || p.hidden ? 0.0 : m.exitance_lm_m2[ci];
            system.reflectance[ci][i] = m.reflectance[ci];
            system.source[ci][i] = emitted + m.reflectance[ci] * luminaire_irradiance[i][ci];
        }
    }

    // Solve.
    const std::string method =
        requested != "auto" ? requested : (n <= kMaxAutoDirectPatches ? "direct" : "gauss-seidel");
    const auto solver = make_solver(method);
    SolverOutcome outcome;
    // Matrix-free shooting: F·(shot radiosity), the reflected light each patch received.
    std::array<std::vector<double>, 3> gathered;
    bool stopped = interrupted.load();
    if (!stopped) {
        report("solving", 0.6);
        // Leave most of the budget to meshing error.
        SolverControl control = solving_control(
            (matrix_free ? kMatrixFreeSystemShare : kDenseSystemShare) * options_.tolerance);
        // The rows and their solve share one grace.
        control.deadline = graced_deadline();
        if (observer_) {
            control.snapshot = [&](const std::array<std::vector<double>, 3>& radiosity) {
                snapshots_.offer(display_mesh(radiosity), 1);
            };
        }
        if (matrix_free) {
            std::uint64_t factors = 0;
            outcome = shoot_matrix_free(system, transport, control, rays_, factors, gathered);
            links_ = static_cast<std::size_t>(factors);
        } else {
            outcome = solver->solve(system, control);
        }
        stopped = !outcome.converged;
    } else {
        // Interrupted before the matrix was complete: the best answer is the first bounce.
        for (int c = 0; c < channels; ++c) {
            outcome.radiosity[static_cast<std::size_t>(c)] =
                system.source[static_cast<std::size_t>(c)];
        }
        outcome.error_estimate = 1.0;
        outcome.unshot_fraction = 1.0;
    }

    // Irradiance per patch: H = F·B + direct light from luminaires (without a matrix, F·B over
    // the radiosity shot so far; what is still unshot is within the error estimate).
    std::vector<SolvedElement> solved(n);
    for (std::size_t i = 0; i < n; ++i) {
        const PatchGeometry& p = patches.patch(i);
        solved[i] = {p.surface, p.material, p.area_m2, p.back_side, p.hidden, {0, 0, 0}, {0, 0, 0}};
    }
    for (int c = 0; c < channels; ++c) {
        const auto ci = static_cast<std::size_t>(c);
        const std::vector<double>& b = outcome.radiosity[ci];
        parallel_for(0, n, [&](std::size_t i) {
            double g = 0;
            if (matrix_free) {
                g = gathered[ci].empty() ? 0.0 : gathered[ci][i];
            } else {
                for (std::size_t j = 0; j < n; ++j) g += form_factors[i * n + j] * b[j];
            }
            solved[i].irradiance[ci] = g + luminaire_irradiance[i][ci];
            solved[i].radiosity[ci] = b[i];
        });
    }

    const auto mesh = display_mesh(outcome.radiosity);
    end_stage("solving", solving);
    // Stage: gather — the sensors' light from the solved patches.
    const StageStart gather = begin_stage();
    // The radiosity is final from here on; the heartbeat shows it while the sensors gather.
    snapshots_.offer(mesh, 1);
    report("sensors", 0.9, outcome.iterations, std::nullopt, outcome.unshot_fraction);
    result.sensors = gather_sensors(prepared, transport, outcome.radiosity, channels,
                                    kSensorNoiseShare * options_.tolerance, rays_);
    SurfaceSummary summary = summarise_surfaces(prepared, solved, channels);
    result.surfaces = std::move(summary.surfaces);
    result.stats.emitted_flux_lm = summary.emitted_flux_lm;
    result.stats.absorbed_flux_lm = summary.absorbed_flux_lm;
    if (options_.want_mesh) result.mesh = *mesh;
    end_stage("gather", gather);
    finish_stats(result, std::string(solver ? solver->name() : method), n, outcome.iterations,
                 outcome.error_estimate, outcome.unshot_fraction, channels, stopped);
    // Matrix-free shooting's bound is attained where its error is uniform (a closed room of one
    // reflectance, see gather_sweep.h): what no bound measures, the floor's share of the
    // tolerance, comes on top of it rather than under it.
    if (matrix_free) result.stats.error_estimate += kDenseUnresolvedShare * options_.tolerance;
    final_mesh_ = mesh;
    final_mesh_version_ = 1;
    return result;
}

}  // namespace radiant
