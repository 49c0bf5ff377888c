// Solving the linked hierarchy: a pass of progressive shooting (see progressive_shooting.h),
// then Jacobi sweeps of gather (every element sums K·B over its own links) and push-pull
// (irradiance pushed down to the leaves, radiosity pulled up as area averages), until a sound
// bound on the error of the linked system meets the tolerance. In a closed enclosure the linked
// operator is then made to conserve energy (see conserve()).
#pragma once

#include <functional>
#include <span>
#include <vector>

#include "hierarchy/element_tree.h"
#include "hierarchy/leaf_completion.h"
#include "hierarchy/link_refinement.h"
#include "solver/solver.h"

namespace radiant {

struct HierarchicalOutcome {
    std::size_t iterations = 0;
    double error_estimate = 0;  ///< bound on the relative error of the linked system
    bool converged = false;
    /// Light the links lost (or made) in closed enclosures before conserve() restored it, as a
    /// share of the light emitted there: an error of the links the system bound cannot see.
    double conservation_defect = 0;
};

class HierarchicalSystem {
public:
    /// `enclosed_patch[p]` marks root patches in a closed enclosure: their leaves' gathered
    /// factors are completed to exactly 1 (as the dense transport does point by point), since
    /// an error δ in that sum costs ρδ/(1−ρ) and ρ may be 0.999. `front_share[p]`: the share of
    /// each root patch's hemisphere that ends on surface fronts (1 where enclosed), what the
    /// others' are completed to (see complete_leaves).
    HierarchicalSystem(ElementTree& tree, const std::vector<Link>& links,
                       const std::vector<char>& enclosed_patch,
                       const std::vector<double>& front_share, int channels);

    /// Shoots, then sweeps until the bound meets `control.tolerance`, the deadline passes or it
    /// is cancelled; `publish` is called at the snapshot rate.
    HierarchicalOutcome solve(const SolverControl& control, const std::function<void()>& publish);

    /// Irradiance (lux, per channel) on the front of leaf `e`, links and luminaires together.
    const Rgb& leaf_irradiance(int e) const { return irradiance_[static_cast<std::size_t>(e)]; }
    /// The sum of leaf `e`'s and its ancestors' link factors, before any completion.
    double factor_sum(std::size_t e) const { return completion_.factor_sum[e]; }

    /// Irradiance and radiosity per element (per channel; the leaves' are the answer).
    struct LeafLight {
        std::vector<Rgb> irradiance, radiosity;
    };
    LeafLight light() const;
    /// Puts `light`'s radiosity on the tree, with each element's range, where a sensor gather
    /// reads it (gather_sensors_from_tree); the irradiance stays the solution's.
    void show_radiosity(const LeafLight& light);

    /// The solution had the completed leaves been completed per root patch instead (see
    /// patchwise_completion_change): a second, as plausible answer of the same links, whose
    /// difference from this one the error estimate must cover. Each patch's change counts
    /// `weight[patch]` times (its importance to the sensors, see RefinementCriteria; empty: 1),
    /// and each part is scaled to absorb what the solution's does (see rebalance). Two more
    /// solves of the linked system; the solution itself is left as it was.
    LeafLight patchwise_completed(const SolverControl& control, std::span<const double> weight);

private:
    struct Residual {
        std::array<double, 3> inf{0, 0, 0}, area_l1{0, 0, 0}, area_signed{0, 0, 0};
    };
    HierarchicalOutcome iterate(const SolverControl& control, const std::function<void()>& publish,
                                bool from_source);
    double bound(const std::array<double, 3>& residual_inf) const;
    bool extrapolate(const Residual& now, const Residual& before, const Residual& older);
    void gather();
    void push(int e, const Rgb& down, Residual& residual);
    void find_parts();
    void measure_defects();
    void conserve(const SolverControl& control, HierarchicalOutcome& out);
    std::vector<Rgb> patchwise_completion_change(std::span<const double> weight);
    void rebalance(LeafLight& other, const LeafLight& solution) const;
    HierarchicalOutcome respond(std::vector<Rgb> source, const SolverControl& control,
                                double tolerance);
    /// Light a leaf gets from outside the links: emission and luminaires, or during a response
    /// solve (conserve(), patchwise_completed()) that solve's source, spread_.
    Rgb outside_exitance(const Element& leaf) const;
    Rgb outside_irradiance(const Element& leaf, std::size_t index) const;

    ElementTree& tree_;
    const std::vector<Link>& links_;
    std::vector<std::size_t> first_link_;  // links of element e: [first_link_[e], first_link_[e+1])
    const std::vector<char>& enclosed_patch_;
    const std::vector<double>& front_share_;
    int channels_;
    std::vector<Rgb> irradiance_;
    std::vector<Rgb> change_;  // each leaf's change in the last sweep
    LeafCompletion completion_;
    double q_inf_ = 0;
    double total_area_ = 0;  // of the leaves
    std::size_t leaves_ = 0;
    // Parts: sets of root patches that exchange light only among themselves. part_[p] is patch
    // p's part, part_area_ the area of each part's leaves.
    std::vector<int> part_;
    std::vector<double> part_area_;
    std::vector<char> part_closed_;
    std::vector<double> defect_;  // per leaf of an enclosed patch: light its links fail to hand on
    bool responding_ = false;     // a response solve is running
    std::vector<Rgb> spread_;     // its source irradiance (see respond())
};

}  // namespace radiant
