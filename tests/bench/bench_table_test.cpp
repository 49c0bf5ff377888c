// How radiant-bench judges each row's error estimate against its measured error.
#include "bench_table.h"

#include <gtest/gtest.h>

#include <sstream>

namespace radiant::bench {
namespace {

BenchRow row(const std::string& scene, double rms, double estimate, double reference_error) {
    BenchRow r;
    r.scene = scene;
    r.method = "hierarchical";
    r.tolerance = 0.01;
    r.status = "converged";
    r.rms_error = rms;
    r.error_estimate = estimate;
    r.reference_error = reference_error;
    return r;
}

// A row measured against a reference that is itself off by 0.14 % cannot be shown to miss by
// 0.02 %; one that misses by more than its reference's error is listed as under.
TEST(BenchTable, ARowMissesOnlyBeyondItsReferencesOwnError) {
    std::ostringstream out;
    print_estimate_misses(out, {row("noisy", 0.0010, 0.0008, 0.0014),
                                row("exact", 0.0010, 0.0008, 0), row("fine", 0.001, 0.002, 0)});
    const std::string text = out.str();
    EXPECT_NE(text.find("2 of 3 converged rows have a larger RMS error"), std::string::npos)
        << text;
    EXPECT_NE(text.find("1 of these misses are within the reference's own"), std::string::npos)
        << text;
    EXPECT_NE(text.find("- under: exact"), std::string::npos) << text;
    EXPECT_NE(text.find("- under (within the reference's error): noisy"), std::string::npos)
        << text;
    EXPECT_EQ(text.find("fine"), std::string::npos) << text;
}

// Loose likewise: 4.5 times a measured 0.2 % whose reference may be 0.1 % off is not shown loose.
TEST(BenchTable, ALooseEstimateIsCertainOnlyBeyondTheReferencesError) {
    std::ostringstream out;
    print_estimate_misses(out, {row("noisy", 0.002, 0.009, 0.001), row("exact", 0.002, 0.009, 0)});
    const std::string text = out.str();
    EXPECT_NE(text.find("- loose: exact"), std::string::npos) << text;
    EXPECT_NE(text.find("- loose (within the reference's error): noisy"), std::string::npos)
        << text;
}

}  // namespace
}  // namespace radiant::bench
