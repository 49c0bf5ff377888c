// Progressive shooting on the linked hierarchy (Cohen et al. 1988, on links after Hanrahan,
// Salzman & Aupperle 1991): the root patch with the most unshot power sends it, over-relaxed
// (Feda & Purgathofer 1992), through the links that leave its elements. A receiver keeps what it
// gets pending at its own level until its patch shoots (then it is pushed down to its leaves and
// pulled up as their unshot average), so a shot costs the shooter's links and elements alone. While
// light is concentrated — in the emitters, then in what they light — this is where it pays: a scene
// without reflection is solved once every emitter has shot, and a viewer sees the direct light
// after a fraction of a sweep.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "hierarchy/element_tree.h"
#include "hierarchy/leaf_completion.h"
#include "hierarchy/link_refinement.h"
#include "solver/solver.h"

namespace radiant {

class ProgressiveShooting {
public:
    /// Every link's source is a surface element (a cluster's links pass on the light of the
    /// root patches its samples lie on, see link_refinement), so each belongs to one patch.
    /// `completion`: how the leaves' gathered light is scaled (see leaf_completion.h);
    /// `n_patches`: the root patches' count.
    ProgressiveShooting(ElementTree& tree, const std::vector<Link>& links,
                        const LeafCompletion& completion, std::size_t n_patches, int channels);

    /// Lights the leaves with the source term (emission, reflected luminaire light), then shoots
    /// patch after patch, the one with the most unshot power first, until the shots have sent
    /// through as many links as there are (a sweep's work: by then light is spread, and sweeps,
    /// which run in parallel, do better), nothing is left unshot, or `control` says stop;
    /// `publish` is called at its snapshot rate, with the ambient term of what is still unshot
    /// added to the radiosity for the while (Cohen et al. 1988). Leaves every leaf's radiosity and
    /// `irradiance` as shot so far (interior nodes pulled up) and returns the largest unshot
    /// radiosity of any leaf, per channel: the residual of the system is M times it.
    std::array<double, 3> run(const SolverControl& control, const std::function<void()>& publish,
                              std::vector<Rgb>& irradiance);

private:
    void send(int patch, std::vector<Rgb>& irradiance);
    void settle(int e, const Rgb& down, std::vector<Rgb>& irradiance);
    void settle_all(std::vector<Rgb>& irradiance);
    const Rgb& pull_unshot(int e);
    void scale_unshot(int e, double factor);
    void publish_with_ambient(const std::function<void()>& publish);

    ElementTree& tree_;
    const std::vector<Link>& links_;
    const LeafCompletion& completion_;
    int channels_;
    double omega_ = 1;                     // over-relaxation (see over_relaxation)
    std::vector<int> root_of_patch_;       // −1 for patches with no element (hidden)
    std::vector<std::size_t> first_sent_;  // links from patch p: sent_[first_sent_[p] … [p + 1])
    std::vector<std::size_t> sent_;
    std::vector<Rgb> pending_;   // per element: irradiance received, not yet pushed to its leaves
    std::vector<Rgb> unshot_;    // leaves: radiosity not yet sent on; interior: their average
    std::vector<double> power_;  // per patch: unshot power, pending light's share included
    std::vector<int> touched_;   // patches whose power the current shot raised
    std::vector<char> is_touched_;
};

}  // namespace radiant
