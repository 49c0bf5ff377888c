// solve(): the engine's pipeline — prepare, mesh, visibility, form factors, solve, gather.
#include "radiant/solve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include <OpenMesh/Core/System/omstream.hh>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "formfactor/enclosure.h"
#include "formfactor/transport.h"
#include "meshing/patch_mesh.h"
#include "scene/prepared_scene.h"
#include "solution/gouraud.h"
#include "solution/sensors.h"
#include "solver/solver.h"

namespace radiant {
namespace {

using Clock = std::chrono::steady_clock;

// Above this many patches the dense solvers' n² memory and time stop paying; the patch size
// grows instead (the hierarchical solver is the answer for larger models).
constexpr std::size_t kMaxDensePatches = 3000;
// A model with more polygons than this cannot be meshed within the dense solvers' budget
// (one patch per polygon at least); it needs the hierarchical solver, so it is refused clearly.
constexpr std::size_t kMaxDensePolygons = 6000;
// LU (O(n³)) beats iteration up to about here on two cores, at any reflectance.
constexpr std::size_t kMaxAutoDirectPatches = 1500;

class Pipeline {
public:
    Pipeline(const Scene& scene, const SolveOptions& options, SolveObserver* observer,
             const CancellationToken* cancel)
        : scene_(scene), options_(options), observer_(observer), cancel_(cancel),
          start_(Clock::now()) {
        if (options.max_seconds) {
            deadline_ = start_ + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>(*options.max_seconds));
        }
    }

    Result run();

private:
    void report(const std::string& stage, double fraction, std::size_t iterations = 0,
                double error = 0, double unshot = 0) const;
    bool should_stop() const {
        return (cancel_ && cancel_->cancelled()) || (deadline_ && Clock::now() >= *deadline_);
    }
    double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

    const Scene& scene_;
    const SolveOptions& options_;
    SolveObserver* observer_;
    const CancellationToken* cancel_;
    Clock::time_point start_;
    std::optional<Clock::time_point> deadline_;
    std::uint64_t rays_ = 0;
};

void Pipeline::report(const std::string& stage, double fraction, std::size_t iterations,
                      double error, double unshot) const {
    if (!observer_) return;
    Progress p;
    p.stage = stage;
    p.fraction = fraction;
    p.iterations = iterations;
    p.error_estimate = error;
    p.unshot_fraction = unshot;
    p.elapsed_seconds = elapsed();
    p.rays = rays_;
    observer_->on_progress(p);
}

// All pieces as triangle fans, and the piece of each triangle.
std::pair<std::vector<Triangle>, std::vector<int>> occluder_triangles(const PreparedScene& scene) {
    std::vector<Triangle> tris;
    std::vector<int> piece;
    for (std::size_t i = 0; i < scene.pieces.size(); ++i) {
        const auto& v = scene.pieces[i].vertices;
        for (std::size_t k = 1; k + 1 < v.size(); ++k) {
            tris.push_back({v[0], v[k], v[k + 1]});
            piece.push_back(static_cast<int>(i));
        }
    }
    return {tris, piece};
}

std::string choose_method(const std::string& requested, std::size_t patches) {
    if (requested != "auto") return requested;
    return patches <= kMaxAutoDirectPatches ? "direct" : "gauss-seidel";
}

Result Pipeline::run() {
    Result result;
    result.scene = scene_.name;

    report("meshing", 0.0);
    const PreparedScene prepared = prepare_scene(scene_);
    if (prepared.pieces.empty()) {
        result.error = "the scene has no surface with a non-zero area";
        return result;
    }
    if (prepared.pieces.size() > kMaxDensePolygons) {
        result.error = "the scene has " + std::to_string(prepared.pieces.size()) +
                       " convex polygons; the dense solvers handle at most " +
                       std::to_string(kMaxDensePolygons);
        return result;
    }
    omerr().disable();  // T-junction fallbacks are expected, not errors to print
    const auto [triangles, triangle_piece] = occluder_triangles(prepared);
    const auto visibility = make_embree_visibility(triangles);
    const double free_path = mean_free_path(prepared, *visibility, options_.seed);
    PatchMesh patches(prepared, {target_patch_edge(free_path, options_.tolerance), kMaxDensePatches});
    const std::size_t n = patches.size();
    const int channels = prepared.channels;

    const OcclusionCulling culling(prepared);
    TransportOptions transport_options;
    transport_options.seed = options_.seed;
    const Transport transport(
        prepared, patches, *visibility, culling, transport_options,
        enclosed_patches(prepared, patches, *visibility, triangle_piece, options_.seed));

    // Form factors, one receiver row per task; rays counted per thread.
    report("form factors", 0.05);
    std::vector<float> form_factors(n * n, 0.0f);
    std::vector<Rgb> luminaire_irradiance(n, Rgb{0, 0, 0});
    tbb::combinable<std::uint64_t> ray_count([] { return std::uint64_t{0}; });
    std::atomic<bool> interrupted{false};
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        if (interrupted.load(std::memory_order_relaxed)) return;
        if (should_stop()) {
            interrupted = true;
            return;
        }
        std::uint64_t& local = ray_count.local();
        transport.form_factor_row(i, &form_factors[i * n], local);
        luminaire_irradiance[i] = transport.luminaire_irradiance_on_patch(i, local);
    });
    rays_ += ray_count.combine([](std::uint64_t a, std::uint64_t b) { return a + b; });

    LinearSystem system;
    system.n = n;
    system.channels = channels;
    system.form_factors = &form_factors;
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
    const std::string method = choose_method(options_.method, n);
    const auto solver = make_solver(method);
    SolverOutcome outcome;
    bool stopped = interrupted.load();
    if (!stopped) {
        report("solving", 0.6);
        SolverControl control;
        control.tolerance = options_.tolerance / 4;  // leave most of the budget to meshing error
        control.deadline = deadline_;
        control.cancel = cancel_;
        control.progress = [&](std::size_t it, double err, double unshot) {
            report("solving", 0.6 + 0.3 * std::clamp(std::log(std::max(err, 1e-300)) /
                                                         std::log(control.tolerance), 0.0, 1.0),
                   it, err, unshot);
        };
        outcome = solver->solve(system, control);
        stopped = !outcome.converged;
    } else {
        // Interrupted before the matrix was complete: the best answer is the first bounce.
        for (int c = 0; c < channels; ++c) outcome.radiosity[static_cast<std::size_t>(c)] = system.source[static_cast<std::size_t>(c)];
        outcome.error_estimate = 1.0;
        outcome.unshot_fraction = 1.0;
    }

    // Irradiance per patch: H = F·B + direct light from luminaires.
    for (int c = 0; c < channels; ++c) {
        const auto ci = static_cast<std::size_t>(c);
        auto& b = patches.radiosity(c);
        auto& h = patches.irradiance(c);
        b = outcome.radiosity[ci];
        patches.unshot(c) = outcome.unshot[ci].empty() ? std::vector<double>(n, 0.0) : outcome.unshot[ci];
        h.assign(n, 0.0);
        tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
            double g = 0;
            for (std::size_t j = 0; j < n; ++j) g += form_factors[i * n + j] * b[j];
            h[i] = g + luminaire_irradiance[i][ci];
        });
    }

    report("sensors", 0.9, outcome.iterations, outcome.error_estimate, outcome.unshot_fraction);
    result.sensors = gather_sensors(prepared, transport, outcome.radiosity, channels, rays_);

    // Per-surface averages over front sides, and the energy balance.
    auto photometric = [&](const std::array<std::vector<double>, 3>& v, std::size_t i) {
        return channels == 1 ? v[0][i] : luminance(Rgb{v[0][i], v[1][i], v[2][i]});
    };
    std::array<std::vector<double>, 3> irradiance;
    for (int c = 0; c < channels; ++c) irradiance[static_cast<std::size_t>(c)] = patches.irradiance(c);
    std::vector<double> surface_area(prepared.surface_names.size(), 0.0);
    std::vector<double> sum_h(surface_area.size(), 0.0), sum_b(surface_area.size(), 0.0);
    double emitted = 0, absorbed = 0;
    std::vector<double> display(n);
    for (std::size_t i = 0; i < n; ++i) {
        const PatchGeometry& p = patches.patch(i);
        const PreparedMaterial& m = prepared.materials[static_cast<std::size_t>(p.material)];
        display[i] = photometric(outcome.radiosity, i);
        Rgb absorbed_rgb{0, 0, 0}, emitted_rgb{0, 0, 0};
        for (int c = 0; c < channels; ++c) {
            const auto ci = static_cast<std::size_t>(c);
            absorbed_rgb[ci] = p.area_m2 * (1 - m.reflectance[ci]) * irradiance[ci][i];
            emitted_rgb[ci] = p.back_side || p.hidden ? 0 : p.area_m2 * m.exitance_lm_m2[ci];
        }
        absorbed += channels == 1 ? absorbed_rgb[0] : luminance(absorbed_rgb);
        emitted += channels == 1 ? emitted_rgb[0] : luminance(emitted_rgb);
        if (p.back_side) continue;
        const auto s = static_cast<std::size_t>(p.surface);
        surface_area[s] += p.area_m2;
        sum_h[s] += p.area_m2 * photometric(irradiance, i);
        sum_b[s] += p.area_m2 * display[i];
    }
    for (const PreparedLuminaire& l : prepared.luminaires) {
        emitted += channels == 1 ? l.flux_lm[0] : luminance(l.flux_lm);
    }
    for (std::size_t s = 0; s < surface_area.size(); ++s) {
        SurfaceResult r;
        r.name = prepared.surface_names[s];
        r.area_m2 = prepared.surface_area_m2[s];
        r.average_irradiance = surface_area[s] > 0 ? sum_h[s] / surface_area[s] : 0;
        r.average_radiosity = surface_area[s] > 0 ? sum_b[s] / surface_area[s] : 0;
        result.surfaces.push_back(std::move(r));
    }
    if (options_.want_mesh) result.mesh = gouraud_mesh(patches, display, prepared.world_origin);

    std::size_t links = 0;
    for (const float f : form_factors) links += f > 0 ? 1 : 0;
    SolveStats& st = result.stats;
    st.method = solver ? std::string(solver->name()) : method;
    st.patches = n;
    st.elements = n;
    st.links = links;
    st.iterations = outcome.iterations;
    st.rays = rays_;
    st.unshot_fraction = outcome.unshot_fraction;
    st.error_estimate = outcome.error_estimate;
    st.emitted_flux_lm = emitted;
    st.absorbed_flux_lm = absorbed;
    st.channels = channels;
    st.threads = tbb::this_task_arena::max_concurrency();
    st.seconds = elapsed();
    result.status = stopped ? SolveStatus::stopped : SolveStatus::converged;
    report("done", 1.0, outcome.iterations, outcome.error_estimate, outcome.unshot_fraction);
    return result;
}

std::string describe(const std::vector<Problem>& problems) {
    std::ostringstream out;
    for (std::size_t i = 0; i < problems.size(); ++i) {
        if (i) out << "; ";
        out << problems[i].pointer << ": " << problems[i].message;
    }
    return out.str();
}

bool known_method(const std::string& method) {
    const auto& names = solver_names();
    return std::find(names.begin(), names.end(), method) != names.end();
}

}  // namespace

Result solve(const Scene& scene, const SolveOptions& options, SolveObserver* observer,
             const CancellationToken* cancel) {
    Result result;
    result.scene = scene.name;
    try {
        if (auto problems = check_scene(scene); !problems.empty()) {
            result.error = "invalid scene: " + describe(problems);
            return result;
        }
        if (!(options.tolerance > 0 && options.tolerance < 1)) {
            result.error = "tolerance must be in (0, 1)";
            return result;
        }
        if (!known_method(options.method)) {
            result.error = "unknown method \"" + options.method + "\"";
            return result;
        }
        tbb::task_arena arena(options.threads > 0 ? options.threads
                                                  : tbb::task_arena::automatic);
        arena.execute([&] { result = Pipeline(scene, options, observer, cancel).run(); });
    } catch (const std::exception& e) {
        result = Result{};
        result.scene = scene.name;
        result.error = std::string("internal error: ") + e.what();
    }
    return result;
}

SolveOptions options_from(const Settings& settings) {
    SolveOptions o;
    o.tolerance = settings.tolerance;
    o.max_seconds = settings.max_seconds;
    o.method = settings.method;
    return o;
}

const std::vector<std::string>& solver_names() {
    static const std::vector<std::string> names{"auto", "direct", "jacobi", "gauss-seidel",
                                                "shooting"};
    return names;
}

const char* to_string(SolveStatus status) {
    switch (status) {
        case SolveStatus::converged: return "converged";
        case SolveStatus::stopped: return "stopped";
        case SolveStatus::failed: return "failed";
    }
    return "failed";
}

}  // namespace radiant
