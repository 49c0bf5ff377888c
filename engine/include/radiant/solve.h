// The engine's one entry point: solve a scene, with progress and cancellation.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "radiant/result.h"
#include "radiant/scene.h"

namespace radiant {

struct SolveOptions {
    double tolerance = 0.01;            ///< relative error target; also sets the patch size
    std::optional<double> max_seconds;  ///< wall-clock budget; the best result so far is returned
    std::string method = "auto";        ///< auto, direct, jacobi, gauss-seidel, shooting
    int threads = 0;                    ///< 0: all cores
    std::uint64_t seed = 1;             ///< sampling seed; results do not depend on `threads`
    bool want_mesh = false;             ///< fill Result::mesh
    /// Least time between two snapshots handed to SolveObserver::on_snapshot while solving.
    double snapshot_interval_seconds = 0.5;
    /// Memory budget of the solve: the scene it is given and everything the solver allocates.
    /// Each step estimates its memory before it allocates it; refinement stops at a step that
    /// would not fit (the result is then `stopped`, with `stop_reason`), and a solve whose first
    /// steps do not fit fails at once. 0: half the machine's physical memory.
    std::size_t max_memory_bytes = 0;
    /// Warnings are errors: a scene with modelling warnings is refused before it is solved, and
    /// a solve that ends with a warning (the time limit) fails; either result is `failed`, with
    /// the warnings in Result::warnings.
    bool strict = false;
};

/// The machine's physical memory in bytes (0 if unknown).
std::size_t physical_memory_bytes();

/// Options from a scene's own `settings`; command-line flags override fields afterwards.
SolveOptions options_from(const Settings& settings);

/// The solver names `method` accepts.
std::vector<std::string> solver_names();

/// Cooperative cancellation; `cancel()` may be called from any thread.
class CancellationToken {
public:
    void cancel() noexcept { cancelled_.store(true, std::memory_order_relaxed); }
    bool cancelled() const noexcept { return cancelled_.load(std::memory_order_relaxed); }

private:
    std::atomic<bool> cancelled_{false};
};

struct Progress {
    std::string stage;    ///< "meshing", "form factors", "solving", "sensors"
    double fraction = 0;  ///< rough completion of the whole solve in [0, 1]
    std::size_t iterations = 0;
    double unshot_fraction = 0;
    /// The estimated relative error of the answer so far, as SolveStats::error_estimate: empty
    /// until the solve has one. A linear solve's residual is no such estimate (the mesh's error
    /// comes on top), so it only shows in `fraction`; Monte Carlo rounds estimate their answer,
    /// the radiosity methods once their mesh is checked.
    std::optional<double> error_estimate;
    double elapsed_seconds = 0;
    std::uint64_t rays = 0;
    std::size_t elements = 0;  ///< current number of patches or hierarchy leaves
    std::size_t links = 0;
};

/// A progressive result published while the solve runs: the patch mesh with the current
/// radiosity (triangle and vertex values), so a viewer can redraw as the solution converges.
struct Snapshot {
    std::uint64_t version = 0;               ///< 1, 2, … in publication order
    std::uint64_t mesh_version = 0;          ///< changes only when the geometry (triangles) changes
    std::shared_ptr<const SolvedMesh> mesh;  ///< world coordinates; radiosity of this snapshot
    /// Sensor values of the latest solution that had them (the final snapshot: the result's);
    /// null until the solver has some.
    std::shared_ptr<const std::vector<SensorResult>> sensors;
    Progress progress;
    bool final = false;  ///< the last snapshot: its values are the result's
};

/// Receives progress from the solving thread (or a worker thread). Implementations must be
/// cheap and thread-safe; they must not throw.
class SolveObserver {
public:
    virtual ~SolveObserver() = default;
    virtual void on_progress(const Progress& progress) = 0;
    /// At most once per SolveOptions::snapshot_interval_seconds, and once at the end; from the
    /// first patch mesh on also at least every 1.5 intervals, in every phase (phases without new
    /// values repeat the latest ones). May be called from a thread of the engine's own.
    virtual void on_snapshot(const Snapshot& /*snapshot*/) {}
    /// The modelling checks' warnings, once, before solving starts, when there are any (the
    /// result repeats them, with any the solve adds). From the solving thread.
    virtual void on_warnings(const std::vector<Warning>& /*warnings*/) {}
};

/// Solves `scene`. Never throws for bad input: a scene that fails `check_scene` gives a result
/// with status `failed` and the problems in `error`. Thread-safe for distinct calls.
Result solve(const Scene& scene, const SolveOptions& options, SolveObserver* observer = nullptr,
             const CancellationToken* cancel = nullptr);

}  // namespace radiant
