// Runs one piece of benchmark work in a forked child, so that its peak memory (the child's
// ru_maxrss) is its own and a crash or a runaway case cannot take the whole benchmark down.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace radiant::bench {

struct IsolatedOutcome {
    std::optional<nlohmann::json> value;  ///< what `work` returned; empty when the child failed
    double peak_mib = 0;  ///< the child's peak resident memory (ru_maxrss or VmHWM, the larger)
    std::string failure;  ///< why there is no value (signal, exception, …)
};

/// Forks, runs `work` in the child and returns its JSON. The child is killed (SIGALRM) after
/// `watchdog_seconds`. The caller must not have started any threads (fork keeps only one).
IsolatedOutcome run_isolated(const std::function<nlohmann::json()>& work,
                             unsigned watchdog_seconds);

}  // namespace radiant::bench
