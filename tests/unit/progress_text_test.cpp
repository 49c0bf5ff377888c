// The CLI's progress lines: a service job's error estimate is null until the solve has one, and
// the line shows "-" then instead of failing on the null.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "progress_text.h"

namespace radiant::cli {
namespace {

TEST(ProgressText, EstimateIsADashUntilThereIsOne) {
    EXPECT_EQ(estimate_text(std::nullopt), "    -    ");
    EXPECT_EQ(estimate_text(0.0123), "1.23e-02");
    EXPECT_EQ(estimate_text(std::nullopt).size(), estimate_text(0.0123).size() + 1);
}

TEST(ProgressText, ServiceLineWithANullEstimate) {
    const auto progress = nlohmann::json::parse(
        R"({"status":"running","stage":"solving","fraction":0.5,"iterations":12,)"
        R"("error_estimate":null,"elapsed_seconds":1.25})");
    const std::string line = service_progress_line(progress);
    EXPECT_NE(line.find("[###############---------------]  50.0%"), std::string::npos) << line;
    EXPECT_NE(line.find("solving"), std::string::npos) << line;
    EXPECT_NE(line.find("it 12 "), std::string::npos) << line;
    EXPECT_NE(line.find("err     -    "), std::string::npos) << line;
    EXPECT_NE(line.find("1.2s"), std::string::npos) << line;
}

TEST(ProgressText, ServiceLineWithAnEstimateAndMissingMembers) {
    const std::string line =
        service_progress_line(nlohmann::json::parse(R"({"error_estimate":0.004})"));
    EXPECT_NE(line.find("err 4.00e-03"), std::string::npos) << line;
    EXPECT_NE(line.find("  0.0%"), std::string::npos) << line;
}

}  // namespace
}  // namespace radiant::cli
