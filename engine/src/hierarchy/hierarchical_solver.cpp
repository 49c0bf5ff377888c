#include "hierarchy/hierarchical_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "hierarchy/progressive_shooting.h"
#include "parallel/fork_join.h"

namespace radiant {
namespace {

// A part whose openings (see find_parts) add up to at most this share of its area is closed.
constexpr double kClosedEscapeShare = 1e-4;
// The completion alternative (see patchwise_completed) is an error estimate: its response
// needs no more than this relative accuracy.
constexpr double kResponseTolerance = 0.01;

}  // namespace

HierarchicalSystem::HierarchicalSystem(ElementTree& tree, const std::vector<Link>& links,
                                       const std::vector<char>& enclosed_patch,
                                       const std::vector<double>& front_share, int channels)
    : tree_(tree),
      links_(links),
      enclosed_patch_(enclosed_patch),
      front_share_(front_share),
      channels_(channels),
      irradiance_(tree.size(), Rgb{0, 0, 0}),
      change_(tree.size(), Rgb{0, 0, 0}) {
    first_link_.assign(tree.size() + 1, 0);
    for (const Link& l : links) ++first_link_[static_cast<std::size_t>(l.receiver) + 1];
    for (std::size_t e = 0; e < tree.size(); ++e) first_link_[e + 1] += first_link_[e];
    for (std::size_t e = 0; e < tree.size(); ++e) {
        double sum = 0;
        for (std::size_t k = first_link_[e]; k < first_link_[e + 1]; ++k) sum += links[k].factor;
        tree[e].link_factor_sum = sum;
    }
    completion_ = complete_leaves(tree, front_share);
    // ‖operator‖∞: a leaf's new radiosity is ρ times a weighted sum of radiosities with weights
    // summing to S (its own and its ancestors' link factors), or to 1 where S is completed.
    for (std::size_t e = 0; e < tree.size(); ++e) {
        const Element& x = tree[e];
        if (x.cluster || !x.leaf()) continue;
        double rho = 0;
        for (int c = 0; c < channels; ++c)
            rho = std::max(rho, x.reflectance[static_cast<std::size_t>(c)]);
        q_inf_ = std::max(q_inf_, rho * completion_.completed_sum[e]);
        total_area_ += x.area_m2;
        ++leaves_;
    }
    find_parts();
    measure_defects();
}

HierarchicalSystem::LeafLight HierarchicalSystem::light() const {
    LeafLight out{irradiance_, std::vector<Rgb>(tree_.size())};
    for (std::size_t e = 0; e < tree_.size(); ++e) out.radiosity[e] = tree_[e].radiosity;
    return out;
}

void HierarchicalSystem::show_radiosity(const LeafLight& light) {
    for (std::size_t e = 0; e < tree_.size(); ++e) tree_[e].radiosity = light.radiosity[e];
    tree_.pull_up(channels_);
}

// The solution completes each leaf's factor sum S through its inherited links first (see
// leaf_completion.h). Completing per root patch instead — each leaf gets the light through its
// links unscaled plus its missing factor (share − S) times the patch's light per unit factor —
// is another plausible answer: a leaf's sum mixes its ancestors' links, averaged over larger
// areas, with its own, so the sums of one patch's leaves scatter (0.9–1.4 in a unit cube) about
// their mean. This is the change in each leaf's irradiance that makes, before the change is
// reflected on, times its patch's weight: a patch the sensors need less was linked to 1/weight of
// the accuracy. Gathers afresh from the solution's radiosity.
std::vector<Rgb> HierarchicalSystem::patchwise_completion_change(std::span<const double> weight) {
    gather();
    // Light through each element's links and its ancestors' (a parent comes before its children).
    std::vector<Rgb> linked(tree_.size(), Rgb{0, 0, 0});
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        const Element& x = tree_[e];
        if (x.cluster) continue;
        linked[e] = x.gathered;
        if (x.depth == 0) continue;
        const Rgb& above = linked[static_cast<std::size_t>(x.parent)];
        for (int c = 0; c < channels_; ++c) linked[e][c] += above[c];
    }
    const std::size_t patches = front_share_.size();
    std::vector<Rgb> gathered(patches, Rgb{0, 0, 0});  // Σ A·(light through links), per patch
    std::vector<double> factors(patches, 0.0);         // Σ A·S
    auto completed = [this](std::size_t e) {
        const Element& x = tree_[e];
        return !x.cluster && x.leaf() &&
               completes_leaf(front_share_[static_cast<std::size_t>(x.patch)],
                              completion_.factor_sum[e]);
    };
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        if (!completed(e)) continue;
        const Element& x = tree_[e];
        const auto p = static_cast<std::size_t>(x.patch);
        factors[p] += x.area_m2 * completion_.factor_sum[e];
        for (int c = 0; c < channels_; ++c) gathered[p][c] += x.area_m2 * linked[e][c];
    }
    std::vector<Rgb> change(tree_.size(), Rgb{0, 0, 0});
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        if (!completed(e)) continue;
        const auto p = static_cast<std::size_t>(tree_[e].patch);
        const double missing = front_share_[p] - completion_.factor_sum[e];
        const double w = p < weight.size() ? weight[p] : 1.0;
        for (int c = 0; c < channels_; ++c) {
            const double per_factor = factors[p] > 0 ? gathered[p][c] / factors[p] : 0;
            const double solved = irradiance_[e][c] - tree_[e].luminaire_irradiance[c];
            change[e][c] = w * (std::max(0.0, linked[e][c] + missing * per_factor) - solved);
        }
    }
    return change;
}

// The change's response through the linked system, B = ρ(ΔE + K·B), solved like conserve()'s
// z: once for the leaves it brightens and once for those it darkens, since the solver's bound
// is relative to a positive solution.
HierarchicalSystem::LeafLight HierarchicalSystem::patchwise_completed(
    const SolverControl& control, std::span<const double> weight) {
    const std::vector<Rgb> change = patchwise_completion_change(weight);
    const LeafLight solution = light();
    LeafLight out = solution;
    for (const double sign : {1.0, -1.0}) {
        std::vector<Rgb> source(tree_.size(), Rgb{0, 0, 0});
        bool any = false;
        for (std::size_t e = 0; e < tree_.size(); ++e) {
            for (int c = 0; c < channels_; ++c) {
                source[e][c] = std::max(0.0, sign * change[e][c]);
                any = any || source[e][c] > 0;
            }
        }
        if (!any) continue;
        respond(std::move(source), control, kResponseTolerance);
        for (std::size_t e = 0; e < tree_.size(); ++e) {
            for (int c = 0; c < channels_; ++c) {
                out.irradiance[e][c] += sign * irradiance_[e][c];
                out.radiosity[e][c] += sign * tree_[e].radiosity[c];
            }
        }
    }
    irradiance_ = solution.irradiance;
    show_radiosity(solution);
    rebalance(out, solution);
    return out;
}

// The solution keeps its light: a closed part absorbs what it emits (see conserve()), and the
// box rooms balance to 0.02 %. The alternative's per-patch completion loses or makes light,
// which shows as the same difference on every surface (a uniform 0.5–1.6 % in a room lit by one
// small panel) and is not an error the solution has; so each part of the alternative is scaled
// to absorb what the solution's does, and only the light it moves between surfaces counts.
void HierarchicalSystem::rebalance(LeafLight& other, const LeafLight& solution) const {
    std::vector<Rgb> wanted(part_area_.size(), Rgb{0, 0, 0}), got = wanted;
    auto part_of = [this](const Element& x) {
        return x.cluster || !x.leaf() ? -1 : part_[static_cast<std::size_t>(x.patch)];
    };
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        const Element& x = tree_[e];
        const int p = part_of(x);
        for (int c = 0; p >= 0 && c < channels_; ++c) {
            const double absorbing = x.area_m2 * (1 - x.reflectance[c]);
            wanted[static_cast<std::size_t>(p)][c] += absorbing * solution.irradiance[e][c];
            got[static_cast<std::size_t>(p)][c] += absorbing * other.irradiance[e][c];
        }
    }
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        const Element& x = tree_[e];
        const int p = part_of(x);
        for (int c = 0; p >= 0 && c < channels_; ++c) {
            const auto k = static_cast<std::size_t>(p);
            if (got[k][c] > 0) other.irradiance[e][c] *= wanted[k][c] / got[k][c];
            other.radiosity[e][c] = x.exitance[c] + x.reflectance[c] * other.irradiance[e][c];
        }
    }
}

// Root patches that exchange light (through links, either way) form parts: light stays in its
// part, so a sealed room's share of the correction stays in it.
void HierarchicalSystem::find_parts() {
    const std::size_t patches = enclosed_patch_.size();
    std::vector<int> up(patches);
    std::iota(up.begin(), up.end(), 0);
    auto find = [&up](int p) {
        while (up[static_cast<std::size_t>(p)] != p) {
            int& next = up[static_cast<std::size_t>(p)];
            next = up[static_cast<std::size_t>(next)];
            p = next;
        }
        return p;
    };
    for (const Link& l : links_) {
        const int a = find(tree_[static_cast<std::size_t>(l.receiver)].patch);
        const int b = find(tree_[static_cast<std::size_t>(l.source)].patch);
        if (a != b) up[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
    std::vector<int> id(patches, -1);
    part_.assign(patches, -1);
    for (std::size_t p = 0; p < patches; ++p) {
        const auto r = static_cast<std::size_t>(find(static_cast<int>(p)));
        if (id[r] < 0) {
            id[r] = static_cast<int>(part_area_.size());
            part_area_.push_back(0);
        }
        part_[p] = id[r];
    }
    // Light leaves a part where its leaves' factors sum to less than 1 uncompleted: its area
    // seen through openings (by reciprocity about the openings' area). A part is closed when
    // that is a negligible share of its area, as around a one-sided panel's small back.
    std::vector<double> escape(part_area_.size(), 0.0);
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        const Element& x = tree_[e];
        if (x.cluster || !x.leaf()) continue;
        const auto k = static_cast<std::size_t>(part_[static_cast<std::size_t>(x.patch)]);
        part_area_[k] += x.area_m2;
        escape[k] += x.area_m2 * std::max(0.0, 1 - completion_.completed_sum[e]);
    }
    part_closed_.resize(part_area_.size());
    for (std::size_t k = 0; k < part_area_.size(); ++k)
        part_closed_[k] = escape[k] <= kClosedEscapeShare * part_area_[k];
}

// Completion makes each closed leaf's factors sum to 1, so a uniform radiosity is reproduced
// exactly (furnaces stay right at ρ → 1), but it cannot give reciprocity: a source whose
// factors come out low hands on less than all its light, and the room absorbs less than it
// emits. Leaf j hands on, per unit of its radiosity, Σ K·W_r over the links from it and its
// ancestors, each source's share by area (W_r: the light per unit irradiance receiver r passes
// on to its leaves, see LeafCompletion::weight). In a closed part, a leaf of an enclosed patch
// sees only fronts of surfaces, so all its light should land: its defect is its area minus what
// it hands on.
// Elsewhere some of its light may rightly leave (an opening, the back of a one-sided panel):
// no defect is known.
void HierarchicalSystem::measure_defects() {
    const std::size_t n = tree_.size();
    defect_.assign(n, 0.0);
    std::vector<double> handed(n, 0.0);  // per unit area of the source
    for (const Link& l : links_) {
        const double light = l.factor * completion_.weight[static_cast<std::size_t>(l.receiver)];
        const int shares = l.share_total();
        if (shares == 0) {
            handed[static_cast<std::size_t>(l.source)] += light;
            continue;
        }
        // Shared among the children: each hands on its share (see handed_radiosity).
        const std::vector<int>& children = tree_[static_cast<std::size_t>(l.source)].children;
        for (std::size_t c = 0; c < children.size(); ++c)
            handed[static_cast<std::size_t>(children[c])] += light * l.child_share[c] / shares;
    }
    for (std::size_t e = 0; e < n; ++e) {
        const Element& x = tree_[e];
        if (x.cluster) continue;
        handed[e] = (x.area_m2 > 0 ? handed[e] / x.area_m2 : 0) +
                    (x.depth > 0 ? handed[static_cast<std::size_t>(x.parent)] : 0);
        const auto patch = static_cast<std::size_t>(x.patch);
        if (x.leaf() && enclosed_patch_[patch] &&
            part_closed_[static_cast<std::size_t>(part_[patch])])
            defect_[e] = x.area_m2 * (1 - handed[e]);
    }
}

// Solves the linked system lit by `source` alone (irradiance per leaf, no emission) to
// `tolerance`, leaving its answer in the tree and irradiance_; the caller restores the solution.
HierarchicalOutcome HierarchicalSystem::respond(std::vector<Rgb> source,
                                                const SolverControl& control, double tolerance) {
    SolverControl quiet = control;
    quiet.progress = nullptr;
    quiet.tolerance = tolerance;
    spread_ = std::move(source);
    responding_ = true;
    const HierarchicalOutcome out = iterate(quiet, nullptr, true);
    responding_ = false;
    spread_ = {};
    return out;
}

Rgb HierarchicalSystem::outside_exitance(const Element& leaf) const {
    return responding_ ? Rgb{0, 0, 0} : leaf.exitance;
}

Rgb HierarchicalSystem::outside_irradiance(const Element& leaf, std::size_t index) const {
    return responding_ ? spread_[index] : leaf.luminaire_irradiance;
}

void HierarchicalSystem::gather() {
    parallel_for(0, tree_.size(), [&](std::size_t e) {
        Rgb g{0, 0, 0};
        for (std::size_t k = first_link_[e]; k < first_link_[e + 1]; ++k) {
            const Link& l = links_[k];
            const Rgb b = handed_radiosity(l, tree_, [this](int s) -> const Rgb& {
                return tree_[static_cast<std::size_t>(s)].radiosity;
            });
            for (int c = 0; c < channels_; ++c) g[c] += l.factor * b[c];
        }
        tree_[e].gathered = g;
    });
}

void HierarchicalSystem::push(int index, const Rgb& down, Residual& residual) {
    Element& e = tree_[static_cast<std::size_t>(index)];
    if (!e.leaf()) {
        Rgb h = down;
        for (int c = 0; c < 3; ++c) h[c] += e.gathered[c];
        Rgb sum{0, 0, 0};
        double area = 0;
        for (const int child : e.children) {
            push(child, h, residual);
            const Element& c = tree_[static_cast<std::size_t>(child)];
            for (int k = 0; k < 3; ++k) sum[k] += c.area_m2 * c.radiosity[k];
            area += c.area_m2;
        }
        Element& self = tree_[static_cast<std::size_t>(index)];
        for (int k = 0; k < 3; ++k) self.radiosity[k] = area > 0 ? sum[k] / area : 0;
        return;
    }
    const auto i = static_cast<std::size_t>(index);
    const double own = completion_.own_scale[i], inherited = completion_.inherited_scale[i];
    Rgb& irradiance = irradiance_[i];
    const Rgb exitance = outside_exitance(e), outside = outside_irradiance(e, i);
    for (int c = 0; c < channels_; ++c) {
        irradiance[c] = e.gathered[c] * own + down[c] * inherited + outside[c];
        const double b = exitance[c] + e.reflectance[c] * irradiance[c];
        const double change = std::abs(b - e.radiosity[c]);
        residual.inf[c] = std::max(residual.inf[c], change);
        residual.area_l1[c] += e.area_m2 * change;
        residual.area_signed[c] += e.area_m2 * (b - e.radiosity[c]);
        change_[static_cast<std::size_t>(index)][c] = b - e.radiosity[c];
        e.radiosity[c] = b;
    }
}

// Aitken's Δ² on the slowest mode: near ρ → 1 the total change shrinks by a steady factor q per
// sweep, so the sweeps still to come would add about q/(1−q) times each leaf's last change;
// adding that now turns thousands of sweeps into a few, and a leaf that did not change (a
// sealed dark room) gets nothing. Only once q has settled — two successive ratios agree to a
// tenth of 1 − q — is the change that mode alone: after shooting, some patches have sent their
// light and others not, and q/(1−q) (999 at ρ = 0.999) times that mixture would overshoot. The
// bound stays sound: it is taken from the residual of the next sweep, whatever the iterate it
// starts from. Returns whether it extrapolated.
bool HierarchicalSystem::extrapolate(const Residual& now, const Residual& before,
                                     const Residual& older) {
    std::array<double, 3> gain{0, 0, 0};
    bool any = false;
    for (int c = 0; c < channels_; ++c) {
        const auto ci = static_cast<std::size_t>(c);
        if (!(before.area_signed[ci] != 0) || !(older.area_signed[ci] != 0)) continue;
        const double q = now.area_signed[ci] / before.area_signed[ci];
        const double q_before = before.area_signed[ci] / older.area_signed[ci];
        if (!(q > 0.5 && q < 0.9999) || !(std::abs(q - q_before) <= 0.1 * (1 - q))) continue;
        gain[ci] = q / (1 - q);
        any = true;
    }
    if (!any) return false;
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        Element& x = tree_[e];
        if (x.cluster || !x.leaf()) continue;
        for (int c = 0; c < channels_; ++c) x.radiosity[c] += gain[c] * change_[e][c];
    }
    tree_.pull_up(channels_);
    return true;
}

// Shooting first, while light is concentrated (see progressive_shooting.h); then Jacobi sweeps,
// which cost the same per patch once every patch has light to send, run in parallel over
// receivers, and with Aitken's extrapolation converge in a few sweeps even at ρ → 1.
HierarchicalOutcome HierarchicalSystem::solve(const SolverControl& control,
                                              const std::function<void()>& publish) {
    HierarchicalOutcome out;
    if (tree_.top() < 0) {
        out.converged = true;
        return out;
    }
    ProgressiveShooting shooting(tree_, links_, completion_, enclosed_patch_.size(), channels_);
    std::array<double, 3> residual = shooting.run(control, publish, irradiance_);
    for (double& r : residual) r *= q_inf_;
    out.error_estimate = bound(residual);
    if (control.progress) control.progress(1, out.error_estimate, 0);
    if (out.error_estimate <= control.tolerance) {
        out.converged = true;
    } else if (!control.should_stop()) {
        out = iterate(control, publish, false);
    }
    ++out.iterations;  // the shooting pass
    if (out.converged) conserve(control, out);
    return out;
}

// Sound bound on the relative error from the max-norm of the residual, per channel, and never
// below what double arithmetic can resolve: each sweep rounds a sum over every leaf, and
// rounding errors add up like the rest, through 1/(1 − q).
double HierarchicalSystem::bound(const std::array<double, 3>& residual_inf) const {
    const ContractionNorms q{q_inf_, 2.0};  // only the max-norm bound is known here
    double worst = 0;
    for (int c = 0; c < channels_; ++c) {
        const auto ci = static_cast<std::size_t>(c);
        double sum_ab = 0;
        for (std::size_t e = 0; e < tree_.size(); ++e) {
            const Element& x = tree_[e];
            if (!x.cluster && x.leaf()) sum_ab += x.area_m2 * x.radiosity[ci];
        }
        worst = std::max(worst, relative_error_bound(q, residual_inf[ci], 0, sum_ab, total_area_));
    }
    const double rounding = static_cast<double>(leaves_) * std::numeric_limits<double>::epsilon() /
                            (1 - std::min(q_inf_, 1 - 1e-6));
    return worst > 0 ? std::max(worst, rounding) : 0;
}

HierarchicalOutcome HierarchicalSystem::iterate(const SolverControl& control,
                                                const std::function<void()>& publish,
                                                bool from_source) {
    HierarchicalOutcome out;
    // From the source term (emission and reflected luminaire light), the first sweep gathers
    // real light even where the operator is zero (black receivers).
    if (from_source) {
        for (std::size_t e = 0; e < tree_.size(); ++e) {
            Element& x = tree_[e];
            if (x.cluster) continue;
            const Rgb exitance = outside_exitance(x), outside = outside_irradiance(x, e);
            for (int c = 0; c < 3; ++c)
                x.radiosity[c] = exitance[c] + x.reflectance[c] * outside[c];
        }
        tree_.pull_up(channels_);
    }
    auto last_report = std::chrono::steady_clock::now();
    auto last_snapshot = last_report;
    constexpr std::size_t kMaxSweeps = 1000000;
    Residual previous, older;
    while (out.iterations < kMaxSweeps) {
        gather();
        Residual r;
        push(tree_.top(), Rgb{0, 0, 0}, r);
        ++out.iterations;
        std::array<double, 3> residual{0, 0, 0};
        for (std::size_t c = 0; c < 3; ++c) residual[c] = q_inf_ * r.inf[c];
        const double worst = bound(residual);
        out.error_estimate = worst;
        const auto now = std::chrono::steady_clock::now();
        if (control.progress && now - last_report > std::chrono::milliseconds(100)) {
            control.progress(out.iterations, worst, 0);
            last_report = now;
        }
        if (publish && now - last_snapshot >= control.snapshot_interval) {
            tree_.pull_up(channels_);
            publish();
            last_snapshot = now;
        }
        if (worst <= control.tolerance) {
            out.converged = true;
            break;
        }
        if (control.should_stop()) break;
        if (extrapolate(r, previous, older)) {
            previous = older = Residual{};  // the next ratios start afresh
        } else {
            older = previous;
            previous = r;
        }
    }
    tree_.pull_up(channels_);
    return out;
}

// The linked operator K̃ loses (or makes) light d_j·B_j at each closed leaf j. Handing that
// light to the leaves of its part in proportion to the light they already receive gives
// K' = K̃ + u·dᵀ, u = H̃ / Σ A·H̃ over the part: its columns conserve light, and its rows still
// sum to 1 since the defects of a part sum to 0 — a uniform radiosity is still reproduced, so
// ρ → 1 stays stable — and every receiver's irradiance moves by the same share (a uniform
// irradiance would move a dim receiver's by far more). Its solution is B̃ + β·z
// (Sherman–Morrison), z solving the linked system lit by u alone and β = dᵀB̃ / (1 − dᵀz), per
// part and channel: one more solve of the same system.
void HierarchicalSystem::conserve(const SolverControl& control, HierarchicalOutcome& out) {
    const std::size_t parts = part_area_.size();
    if (parts == 0) return;
    auto part_of = [this](const Element& x) {
        return x.cluster || !x.leaf() ? -1 : part_[static_cast<std::size_t>(x.patch)];
    };
    std::vector<Rgb> lost(parts, Rgb{0, 0, 0}), emitted(parts, Rgb{0, 0, 0});
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        const Element& x = tree_[e];
        const int p = part_of(x);
        if (p < 0) continue;
        for (int c = 0; c < channels_; ++c) {
            lost[static_cast<std::size_t>(p)][c] += defect_[e] * x.radiosity[c];
            emitted[static_cast<std::size_t>(p)][c] +=
                x.area_m2 * (x.exitance[c] + x.luminaire_irradiance[c]);
        }
    }
    for (std::size_t p = 0; p < parts; ++p) {
        for (int c = 0; c < channels_; ++c) {
            if (emitted[p][c] > 0)
                out.conservation_defect =
                    std::max(out.conservation_defect, std::abs(lost[p][c]) / emitted[p][c]);
        }
    }
    if (!(out.conservation_defect > 0.01 * control.tolerance)) return;

    std::vector<Rgb> radiosity(tree_.size());
    for (std::size_t e = 0; e < tree_.size(); ++e) radiosity[e] = tree_[e].radiosity;
    const std::vector<Rgb> irradiance = irradiance_;
    std::vector<Rgb> received(parts, Rgb{0, 0, 0});  // Σ A·H̃
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        const int p = part_of(tree_[e]);
        for (int c = 0; p >= 0 && c < channels_; ++c)
            received[static_cast<std::size_t>(p)][c] += tree_[e].area_m2 * irradiance[e][c];
    }
    std::vector<Rgb> u(tree_.size(), Rgb{0, 0, 0});
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        const int p = part_of(tree_[e]);
        for (int c = 0; p >= 0 && c < channels_; ++c) {
            const double sum = received[static_cast<std::size_t>(p)][c];
            u[e][c] = sum > 0 ? irradiance[e][c] / sum : 0;
        }
    }
    // The correction moves the light by about the defect's share, so z needs only a tolerance
    // that much coarser for the same error in the result.
    const HierarchicalOutcome z =
        respond(std::move(u), control, std::min(0.5, control.tolerance / out.conservation_defect));

    std::vector<Rgb> seen(parts, Rgb{0, 0, 0});  // dᵀz
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        const int p = part_of(tree_[e]);
        for (int c = 0; p >= 0 && c < channels_; ++c)
            seen[static_cast<std::size_t>(p)][c] += defect_[e] * tree_[e].radiosity[c];
    }
    double moved = 0, total = 0;  // Σ A·|β z| against Σ A·B̃
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        Element& x = tree_[e];
        const int p = part_of(x);
        for (int c = 0; c < channels_; ++c) {
            double beta = 0;
            if (p >= 0 && z.converged) {
                const auto k = static_cast<std::size_t>(p);
                // dᵀz is about 0 (z is nearly uniform, Σd = 0); far from it, K' is not a
                // small change of K̃ and the correction is not trusted.
                if (std::abs(seen[k][c]) < 0.5) beta = lost[k][c] / (1 - seen[k][c]);
            }
            const double z_b = x.radiosity[c], z_h = irradiance_[e][c];
            x.radiosity[c] = radiosity[e][c] + beta * z_b;
            irradiance_[e][c] = irradiance[e][c] + beta * z_h;
            if (p >= 0) {
                moved += x.area_m2 * std::abs(beta * z_b);
                total += x.area_m2 * radiosity[e][c];
            }
        }
    }
    tree_.pull_up(channels_);
    if (!z.converged) {
        out.converged = false;
        return;
    }
    const double change = total > 0 ? moved / total : 0;
    out.error_estimate = out.error_estimate * (1 + change) + z.error_estimate * change;
}

}  // namespace radiant
