// The ambient term of Cohen et al. 1988, against a hand computation (and against the known bug
// pattern of summing reflectance × area instead of unshot exitance × area).
#include <gtest/gtest.h>

#include "solver/solver.h"

namespace radiant {
namespace {

TEST(AmbientTerm, HandComputation) {
    // Areas 1, 3; reflectances 0.5, 0.7; unshot 2, 0.
    // ρ̄ = (0.5·1 + 0.7·3)/4 = 0.65; Σ ΔB A / Σ A = 2/4 = 0.5; ambient = 0.5 / 0.35.
    const std::vector<double> unshot{2.0, 0.0}, rho{0.5, 0.7}, area{1.0, 3.0};
    EXPECT_NEAR(ambient_term(unshot, rho, area), 0.5 / 0.35, 1e-12);
}

TEST(AmbientTerm, OpenScenesWeighAreasByTheShareTheySee) {
    // As above, the second patch seeing surfaces over half its hemisphere: Σ s A = 2.5;
    // kept = (1·0.5·1 + 0.5²·0.7·3)/2.5 = 0.41; Σ s ΔB A / Σ s A = 2/2.5 = 0.8.
    const std::vector<double> unshot{2.0, 0.0}, rho{0.5, 0.7}, area{1.0, 3.0};
    EXPECT_NEAR(ambient_term(unshot, rho, area, {1.0, 0.5}), 0.8 / 0.59, 1e-12);
    // A patch that sees nothing neither gets nor spreads ambient light.
    EXPECT_NEAR(ambient_term(unshot, rho, area, {1.0, 0.0}), 2.0 / 0.5, 1e-12);
    EXPECT_EQ(ambient_term(unshot, rho, area, {1.0, 1.0}), ambient_term(unshot, rho, area));
}

TEST(AmbientTerm, NothingUnshotNothingAmbient) {
    EXPECT_EQ(ambient_term({0.0, 0.0}, {0.9, 0.9}, {1.0, 1.0}), 0.0);
    EXPECT_EQ(ambient_term({}, {}, {}), 0.0);
}

}  // namespace
}  // namespace radiant
