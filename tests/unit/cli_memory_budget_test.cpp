// `radiant solve --max-memory-mb M` holds the process's peak resident memory within M + 10 % on
// the furnished office (a benchmark scene): it converges, stops refining, or refuses, as M
// shrinks, and the kernel's count of its peak says the budget held.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "cli_run.h"

namespace {

using radiant::test::CliRun;
using radiant::test::run_cli;

const std::string kOffice = std::string(RADIANT_SOURCE_DIR) +
                            "/proto/examples/furnished-office-clutter/furnished-office.json";

struct Case {
    double budget_mib;
    const char* tolerance;
    const char* want;  ///< status, or "refused" (failed for memory, exit 1)
};

TEST(CliMemoryBudget, PeakResidentMemoryStaysWithinTheBudget) {
    // Unbounded, this solve peaks near 40 MiB; at 0.003 near 45 MiB.
    for (const Case c : {Case{48, "0.01", "converged"}, Case{40, "0.003", "stopped"},
                         Case{28, "0.01", "refused"}, Case{20, "0.01", "refused"}}) {
        SCOPED_TRACE(std::to_string(c.budget_mib) + " MiB at tolerance " + c.tolerance);
        const CliRun run = run_cli("solve " + kOffice + " --tolerance " + c.tolerance +
                                   " --max-memory-mb " + std::to_string(c.budget_mib));
        EXPECT_GT(run.peak_mib, 5);  // measured: the radiant process, not the shell
        EXPECT_LE(run.peak_mib, 1.1 * c.budget_mib);
        if (std::string(c.want) == "refused") {
            EXPECT_EQ(run.exit_code, 1) << run.err;
            EXPECT_NE(run.err.find("memory budget"), std::string::npos) << run.err;
            continue;
        }
        ASSERT_EQ(run.exit_code, 0) << run.err;
        const auto result = nlohmann::json::parse(run.out);
        EXPECT_EQ(result["status"], c.want);
        if (std::string(c.want) == "stopped") {
            EXPECT_EQ(result.value("stop_reason", "").rfind("memory budget: ", 0), 0u)
                << result.value("stop_reason", "");
        }
    }
}

TEST(CliMemoryBudget, AFileTooLargeToReadWithinTheBudgetIsNotRead) {
    // Reading the 0.6 MB office takes about 8 MiB besides the process itself.
    const CliRun run = run_cli("solve " + kOffice + " --max-memory-mb 10");
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("more than --max-memory-mb 10"), std::string::npos) << run.err;
    EXPECT_LE(run.peak_mib, 11);
}

}  // namespace
