// The engine's pipeline behind solve(): prepare the scene, build visibility, then either the
// dense path (patch mesh, full form-factor matrix, one of the matrix solvers) or the
// hierarchical one (element tree, links, sweeps), then sensors and summaries.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "meshing/patch_mesh.h"
#include "radiant/solve.h"
#include "scene/prepared_scene.h"
#include "solver/memory_budget.h"
#include "solver/snapshot_publisher.h"
#include "solver/solver.h"
#include "visibility/visibility.h"

namespace radiant {

/// Everything both paths share once the scene is prepared.
struct PreparedSolve {
    PreparedScene scene;
    std::vector<int> triangle_piece;  ///< piece of each visibility triangle
    std::unique_ptr<Visibility> visibility;
    double mean_free_path_m = 0;
};

/// Size limits of the dense path and of refinement; tests lower them to reach the matrix-free path
/// on small scenes, or to compare solutions on one mesh.
struct PipelineLimits {
    /// Above this many convex polygons the dense solvers refuse the scene: n² factors would not
    /// fit (one patch per polygon at least).
    std::size_t max_dense_polygons = 6000;
    /// Above this many convex polygons `shooting` runs without a form-factor matrix: the mesh
    /// cannot fit the dense path's patch budget (3000), and shooting needs no matrix.
    std::size_t max_dense_shooting_polygons = 3000;
    /// A result whose estimate exceeds the tolerance is solved again finer, down to the
    /// tolerance over this (see refine_to_tolerance); 1: never.
    double max_refinement = 32;
};

class Pipeline {
public:
    using Clock = std::chrono::steady_clock;

    Pipeline(const Scene& scene, const SolveOptions& options, SolveObserver* observer,
             const CancellationToken* cancel, PipelineLimits limits = {});

    Result run();

private:
    /// A solve of the same scene at other `options` within `parent` (its discretisation check, a
    /// refinement, the cross-check): it shares the parent's memory budget, cancel and limits,
    /// and reports no stages of its own — it is part of the parent's stage that runs it.
    Pipeline(const Pipeline& parent, const SolveOptions& options);

    /// Patch mesh and one of the matrix solvers, or (`matrix_free`) shooting with each shooter's
    /// factors computed when it shoots.
    Result run_dense(const PreparedSolve& prepared, const std::string& method, bool matrix_free);
    Result run_hierarchical(const PreparedSolve& prepared);
    /// Photons for the reflected light, a final gather at the sensors, rounds of more samples
    /// until the estimate from their spread meets the tolerance (monte_carlo_pipeline.cpp).
    Result run_monte_carlo(const PreparedSolve& prepared);

    /// `estimate`: of the answer the solve would return now (Progress::error_estimate), if any.
    void report(const std::string& stage, double fraction, std::size_t iterations = 0,
                std::optional<double> estimate = std::nullopt, double unshot = 0) const;
    bool should_stop() const {
        return (cancel_ && cancel_->cancelled()) || (deadline_ && Clock::now() >= *deadline_);
    }
    double elapsed() const { return seconds_since(start_); }
    static double seconds_since(Clock::time_point t) {
        return std::chrono::duration<double>(Clock::now() - t).count();
    }
    /// Where a stage began: the time, the rays cast and the memory held then.
    struct StageStart {
        Clock::time_point time;
        std::uint64_t rays = 0;
        std::size_t held_bytes = 0;
    };
    StageStart begin_stage();
    /// Adds the stage begun at `start` and ending now to the result's stage statistics: its
    /// seconds, rays, and the most memory its data held (the budget's peak above what was held
    /// when it began).
    void end_stage(const std::string& name, const StageStart& start);
    /// Adds the discretisation error to a converged result's estimate: Richardson's estimate
    /// from the same method at a coarser tolerance (see pipeline.cpp). The status stays: it says
    /// whether the solver met its tolerance on its mesh; a check that could not finish (time
    /// limit, cancelled) makes the result `stopped`. A mesh that does not coarsen counts
    /// twice the tolerance, so that refinement measures it; `matrix_free` shooting, which is
    /// not refined, then keeps its linear system's bound alone.
    void check_discretisation(const PreparedSolve& prepared, const std::string& method,
                              Result& result, bool matrix_free = false);
    /// In a cluttered room (more than kMaxAutoHierarchicalPolygons convex polygons) solves the
    /// scene by Monte Carlo too and bounds the result's error by their distance plus Monte
    /// Carlo's estimate (stats.error_parts.cross_check): the estimate for `hierarchical`, which
    /// can miss its error there, the smaller of it and the method's own for the others. The
    /// status then says whether that estimate meets the tolerance (cross_check.cpp).
    void cross_check(const PreparedSolve& prepared, Result& result);
    /// While a converged result's estimate exceeds the tolerance, solves again at a smaller
    /// tolerance (errors shrink about in proportion) and estimates the finer result's error
    /// from the two solutions. The time limit or a cancel makes it `stopped`; where no finer
    /// mesh can be tried (limits_.max_refinement, the dense patch budget, the memory budget) the
    /// finest result is kept with its estimate above the tolerance; run() makes it `stopped`.
    void refine_to_tolerance(const PreparedSolve& prepared, std::string method, Result& result);
    /// The hierarchical path, or the dense one (with its matrix unless `matrix_free`): what the
    /// check and refinement solve again.
    Result run_method(const PreparedSolve& prepared, const std::string& method,
                      bool matrix_free = false);
    /// This solve's options at another tolerance, with what is left of its time limit.
    SolveOptions options_within_deadline(double tolerance) const;
    struct DenseMeshSize {
        std::size_t patches = 0;
        bool fits = true;  ///< false: the patch size had to grow to fit the patch budget
    };
    /// The dense path's mesh at `tolerance` (one whose plan would not fit what the memory budget
    /// has left does not fit).
    DenseMeshSize dense_mesh_size(const PreparedSolve& prepared, double tolerance) const;
    /// `meshing` held to what the memory budget has left, and cut short by the time limit or a
    /// cancel.
    MeshingOptions within_limits(MeshingOptions meshing) const;
    /// The plan of `what` ("the patches") within the limits, or nothing when it would not fit
    /// the memory budget: `result` then fails saying so.
    std::optional<PatchPlan> plan_within_limits(const PreparedScene& scene,
                                                const MeshingOptions& meshing,
                                                const std::string& what, Result& result);
    /// Whether `auto` solves a scene of few polygons hierarchically after all: its dense mesh
    /// would be `size`, too large, and the asked tolerance is one the hierarchy can meet.
    bool prefers_hierarchy(const DenseMeshSize& size) const;
    /// The radiosity methods' part of what a lighting designer reads (pipeline_lighting.cpp):
    /// the one maintenance factor applied to every value, the initial values beside them,
    /// requirements checked.
    void finish_lighting(const PreparedSolve& prepared, Result& result);
    /// Raises the result's estimate, and each sensor set's, to the least it may claim.
    void floor_estimate(Result& solved) const;
    /// The steps every finished result takes once its estimate is floored (floor_estimate):
    /// `stopped` for a result that misses its tolerance, the stage statistics, the final
    /// snapshot and progress.
    void finish(Result& solved);
    /// Publishes the final mesh (`final_mesh_`) and the result's sensors as the final snapshot,
    /// with the result's error estimate.
    void publish_final(const Result& result);
    /// Control for the solving stage: `tolerance`, the deadline, cancellation, progress reports
    /// and the snapshot interval of the options.
    SolverControl solving_control(double tolerance) const;
    /// How long past the time limit a solve may run to measure its answer (kGraceShare of the
    /// limit, at least kMinGraceSeconds); none without a limit, after a cancel or inside another
    /// solve.
    std::optional<Clock::duration> grace() const;
    /// Gives `control` the grace, from now, once the time limit is reached (a hierarchical
    /// solve's sweeps, after links made up to the limit).
    void grant_sweep_grace(SolverControl& control) const;
    /// The time limit with the grace added, if there is a grace; else the time limit.
    std::optional<Clock::time_point> graced_deadline() const;
    /// should_stop(), with the grace added to the time limit.
    bool should_stop_after_grace() const;
    /// Fills the statistics every method reports alike.
    void finish_stats(Result& result, const std::string& method, std::size_t patches,
                      std::size_t iterations, double error_estimate, double unshot_fraction,
                      int channels, bool stopped) const;

    /// Stops refinement for want of memory: the result becomes `stopped`, saying why.
    void stop_for_memory(const std::string& refusal);
    /// A first step that does not fit: `result` fails, saying why, and so does the solve.
    void fail_for_memory(Result& result, const std::string& refusal);

    const Scene& scene_;
    const SolveOptions& options_;
    SolveObserver* observer_;
    const CancellationToken* cancel_;
    PipelineLimits limits_;
    Clock::time_point start_;
    std::optional<Clock::time_point> deadline_;
    std::uint64_t rays_ = 0;
    std::vector<StageStats> stages_;
    /// A check or refinement inside another solve (see the nested constructor).
    bool nested_ = false;
    mutable Progress last_progress_;
    /// Mutable like last_progress_: report() is const and hands it every progress.
    mutable SnapshotPublisher snapshots_;
    std::size_t elements_ = 0, links_ = 0;
    /// Scales the tolerance of the linear system (the discretisation check's coarse solve).
    double system_tolerance_scale_ = 1;
    /// The solved mesh of the result, as each path leaves it for publish_final.
    std::shared_ptr<const SolvedMesh> final_mesh_;
    std::uint64_t final_mesh_version_ = 0;
    /// The solve's memory ledger; pipelines that check or refine a result share their parent's.
    std::shared_ptr<MemoryBudget> memory_;
    /// Why a `stopped` result stopped, when it was for memory (see stop_for_memory).
    std::string memory_stop_;
};

}  // namespace radiant
