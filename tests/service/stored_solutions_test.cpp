// The light scenes' cache of parsed solutions: bounded by the values it holds, least recently
// used dropped first, an oversized solution not kept at all.
#include "radiant/server/stored_solutions.h"

#include <gtest/gtest.h>

namespace {

using radiant::Result;
using radiant::server::StoredSolutions;

/// A solution holding `points` sensor values.
std::shared_ptr<const Result> solution(std::size_t points) {
    auto r = std::make_shared<Result>();
    r->sensors.emplace_back();
    r->sensors[0].illuminance.assign(points, 1.0);
    return r;
}

TEST(StoredSolutions, DropsTheLeastRecentlyUsedWhenTheValuesRunOver) {
    StoredSolutions kept(100);
    kept.keep("a", solution(40));
    kept.keep("b", solution(40));
    EXPECT_NE(kept.find("a"), nullptr);  // now "b" is the least recently used
    kept.keep("c", solution(40));
    EXPECT_NE(kept.find("a"), nullptr);
    EXPECT_EQ(kept.find("b"), nullptr);
    EXPECT_NE(kept.find("c"), nullptr);
    kept.keep("huge", solution(101));
    EXPECT_EQ(kept.find("huge"), nullptr);
    EXPECT_NE(kept.find("a"), nullptr);  // nothing was dropped for it
}

}  // namespace
