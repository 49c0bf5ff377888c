// FarPieceDraw: a far point draws a bulb's facets with the probabilities it reports, every facet
// with power can be drawn, and the facets facing the point are drawn far more often.
#include "montecarlo/far_piece_draw.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/random.h"

namespace radiant {
namespace {

// A ball of radius 0.03 m about `centre` in facets: centroids and outward normals on a grid of
// latitudes and longitudes, each with power ∝ its band's circumference, and a few without power.
struct Facets {
    std::vector<Vec3> centroids, normals;
    std::vector<double> powers;
};
Facets bulb(const Vec3& centre) {
    Facets f;
    constexpr int kBands = 10, kAround = 16;
    for (int i = 0; i < kBands; ++i) {
        const double theta = (i + 0.5) * std::numbers::pi / kBands;
        for (int j = 0; j < kAround; ++j) {
            const double phi = j * 2 * std::numbers::pi / kAround;
            const Vec3 n{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                         std::cos(theta)};
            f.normals.push_back(n);
            f.centroids.push_back(centre + n * 0.03);
            f.powers.push_back((i * kAround + j) % 17 == 0 ? 0.0 : std::sin(theta));
        }
    }
    return f;
}

TEST(FarPieceDraw, DrawsEachFacetWithTheProbabilityItReports) {
    const Vec3 centre{1, 2, 1.5};
    const Facets f = bulb(centre);
    const double share = 0.1;
    const FarPieceDraw draw(f.centroids, f.normals, f.powers, share);
    const Vec3 near = centre + Vec3{0.1, 0, 0}, x = centre + Vec3{2.0, -1.0, -1.2};
    EXPECT_FALSE(draw.far(near));
    ASSERT_TRUE(draw.far(x));

    const int draws = 400000;
    std::vector<int> count(f.powers.size(), 0);
    std::vector<double> reported(f.powers.size(), -1);
    for (int k = 0; k < draws; ++k) {
        SampleStream rng(3, 9, static_cast<std::uint64_t>(k));
        double p = 0;
        const std::size_t s = draw.draw(x, rng.next(), p);
        ASSERT_LT(s, f.powers.size());
        ASSERT_GT(p, 0) << "facet " << s;
        if (reported[s] >= 0) {
            EXPECT_DOUBLE_EQ(p, reported[s]);
        }
        reported[s] = p;
        ++count[s];
    }
    double total = 0, facing = 0, away = 0;
    const Vec3 toward = normalized(x - centre);
    for (std::size_t s = 0; s < f.powers.size(); ++s) {
        if (!(f.powers[s] > 0)) {
            EXPECT_EQ(count[s], 0) << "facet " << s << " has no power";
            continue;
        }
        ASSERT_GE(reported[s], 0) << "facet " << s << " with power never drawn";
        const double p = reported[s];
        total += p;
        const double sigma = std::sqrt(p * (1 - p) / draws);
        EXPECT_NEAR(static_cast<double>(count[s]) / draws, p, 5 * sigma) << "facet " << s;
        (dot(f.normals[s], toward) > 0 ? facing : away) += count[s];
    }
    EXPECT_NEAR(total, 1, 1e-9);
    // Draws go mostly to what faces x; those facing away get only the share by power.
    EXPECT_GT(facing, 10 * away);
}

}  // namespace
}  // namespace radiant
