// solve(): checks the request, then runs the pipeline inside a task arena of the requested size.
#include "radiant/solve.h"

#include <algorithm>
#include <sstream>

#include <unistd.h>

#include "checks/solve_outcome.h"
#include "parallel/fork_join.h"
#include "solver/pipeline.h"

namespace radiant {
namespace {

std::string describe(const std::vector<Problem>& problems) {
    std::ostringstream out;
    for (std::size_t i = 0; i < problems.size(); ++i) {
        if (i) out << "; ";
        out << problems[i].pointer << ": " << problems[i].message;
    }
    return out.str();
}

bool known_method(const std::string& method) {
    const std::vector<std::string> names = solver_names();
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
        run_with_threads(options.threads,
                         [&] { result = Pipeline(scene, options, observer, cancel).run(); });
        check_solve_outcome(result, options, cancel && cancel->cancelled(), result.warnings);
        if (options.strict && !result.warnings.empty() && result.status != SolveStatus::failed) {
            result.status = SolveStatus::failed;
            result.error = "strict: the solve has warnings: " + describe_warnings(result.warnings);
        }
    } catch (const std::exception& e) {
        result = Result{};
        result.scene = scene.name;
        result.error = std::string("internal error: ") + e.what();
    }
    return result;
}

std::size_t physical_memory_bytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(page)
                                 : 0;
}

SolveOptions options_from(const Settings& settings) {
    SolveOptions o;
    o.tolerance = settings.tolerance;
    o.max_seconds = settings.max_seconds;
    o.method = settings.method;
    o.strict = settings.strict;
    return o;
}

std::vector<std::string> solver_names() {
    return {"auto", "monte-carlo", "hierarchical", "direct", "jacobi", "gauss-seidel", "shooting"};
}

const char* to_string(SolveStatus status) {
    switch (status) {
        case SolveStatus::converged:
            return "converged";
        case SolveStatus::stopped:
            return "stopped";
        case SolveStatus::failed:
            return "failed";
    }
    return "failed";
}

}  // namespace radiant
