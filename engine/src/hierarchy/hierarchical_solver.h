// Solving the linked hierarchy: Jacobi sweeps of gather (every element sums K·B over its own
// links) and push-pull (irradiance pushed down to the leaves, radiosity pulled up as area
// averages), until a sound bound on the error of the linked system meets the tolerance.
#pragma once

#include <functional>
#include <vector>

#include "hierarchy/element_tree.h"
#include "hierarchy/link_refinement.h"
#include "solver/solver.h"

namespace radiant {

struct HierarchicalOutcome {
    std::size_t iterations = 0;
    double error_estimate = 0;  ///< bound on the relative error of the linked system
    bool converged = false;
};

class HierarchicalSystem {
public:
    /// `enclosed_patch[p]` marks root patches in a closed enclosure: their leaves' gathered
    /// factors are completed to exactly 1 (as the dense transport does point by point), since
    /// an error δ in that sum costs ρδ/(1−ρ) and ρ may be 0.999.
    HierarchicalSystem(ElementTree& tree, const std::vector<Link>& links,
                       const std::vector<char>& enclosed_patch, int channels);

    /// Sweeps until the bound meets `control.tolerance`, the deadline passes or it is cancelled;
    /// `publish` is called whenever control.snapshot_due says so.
    HierarchicalOutcome solve(const SolverControl& control, const std::function<void()>& publish);

    /// Irradiance (lux, per channel) on the front of leaf `e`, links and luminaires together.
    const Rgb& leaf_irradiance(int e) const { return irradiance_[static_cast<std::size_t>(e)]; }

private:
    struct Residual {
        std::array<double, 3> inf{0, 0, 0}, area_l1{0, 0, 0}, area_signed{0, 0, 0};
    };
    void extrapolate(const Residual& now, const Residual& before);
    void gather();
    void push(int e, const Rgb& down, double factor_sum, Residual& residual);

    ElementTree& tree_;
    const std::vector<Link>& links_;
    std::vector<std::size_t> first_link_;  // links of element e: [first_link_[e], first_link_[e+1])
    const std::vector<char>& enclosed_patch_;
    int channels_;
    std::vector<Rgb> irradiance_;
    std::vector<Rgb> change_;  // each leaf's change in the last sweep
    double q_inf_ = 0;
};

}  // namespace radiant
