#include "hierarchy/hierarchical_solver.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace radiant {

HierarchicalSystem::HierarchicalSystem(ElementTree& tree, const std::vector<Link>& links,
                                       const std::vector<char>& enclosed_patch, int channels)
    : tree_(tree),
      links_(links),
      enclosed_patch_(enclosed_patch),
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
    // ‖operator‖∞: a leaf's new radiosity is ρ times a weighted sum of radiosities with weights
    // summing to S (its own and its ancestors' link factors), or to 1 where S is completed.
    for (std::size_t e = 0; e < tree.size(); ++e) {
        const Element& x = tree[e];
        if (x.cluster || !x.leaf()) continue;
        double s = 0;
        for (int a = static_cast<int>(e); a >= 0; a = tree[static_cast<std::size_t>(a)].parent) {
            s += tree[static_cast<std::size_t>(a)].link_factor_sum;
        }
        if (enclosed_patch_[static_cast<std::size_t>(x.patch)] && s > 0) s = 1;
        double rho = 0;
        for (int c = 0; c < channels; ++c)
            rho = std::max(rho, x.reflectance[static_cast<std::size_t>(c)]);
        q_inf_ = std::max(q_inf_, rho * s);
    }
}

void HierarchicalSystem::gather() {
    tbb::parallel_for(std::size_t{0}, tree_.size(), [&](std::size_t e) {
        Rgb g{0, 0, 0};
        for (std::size_t k = first_link_[e]; k < first_link_[e + 1]; ++k) {
            const Link& l = links_[k];
            const Rgb& b = tree_[static_cast<std::size_t>(l.source)].radiosity;
            for (int c = 0; c < channels_; ++c) g[c] += l.factor * b[c];
        }
        tree_[e].gathered = g;
    });
}

void HierarchicalSystem::push(int index, const Rgb& down, double factor_sum, Residual& residual) {
    Element& e = tree_[static_cast<std::size_t>(index)];
    Rgb h = down;
    for (int c = 0; c < 3; ++c) h[c] += e.gathered[c];
    const double s = factor_sum + e.link_factor_sum;
    if (!e.leaf()) {
        Rgb sum{0, 0, 0};
        double area = 0;
        for (const int child : e.children) {
            push(child, h, s, residual);
            const Element& c = tree_[static_cast<std::size_t>(child)];
            for (int k = 0; k < 3; ++k) sum[k] += c.area_m2 * c.radiosity[k];
            area += c.area_m2;
        }
        Element& self = tree_[static_cast<std::size_t>(index)];
        for (int k = 0; k < 3; ++k) self.radiosity[k] = area > 0 ? sum[k] / area : 0;
        return;
    }
    const bool enclosed = enclosed_patch_[static_cast<std::size_t>(e.patch)] != 0;
    const double scale = enclosed && s > 0 ? 1 / s : 1;
    Rgb& irradiance = irradiance_[static_cast<std::size_t>(index)];
    for (int c = 0; c < channels_; ++c) {
        irradiance[c] = h[c] * scale + e.luminaire_irradiance[c];
        const double b = e.exitance[c] + e.reflectance[c] * irradiance[c];
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
// sealed dark room) gets nothing. The bound stays sound: it is taken from the residual of the
// next sweep, whatever the iterate it starts from.
void HierarchicalSystem::extrapolate(const Residual& now, const Residual& before) {
    std::array<double, 3> gain{0, 0, 0};
    bool any = false;
    for (int c = 0; c < channels_; ++c) {
        const auto ci = static_cast<std::size_t>(c);
        if (!(before.area_signed[ci] > 0) || !(now.area_signed[ci] > 0)) continue;
        const double q = now.area_signed[ci] / before.area_signed[ci];
        if (!(q > 0.5 && q < 0.9999)) continue;
        gain[ci] = q / (1 - q);
        any = true;
    }
    if (!any) return;
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        Element& x = tree_[e];
        if (x.cluster || !x.leaf()) continue;
        for (int c = 0; c < channels_; ++c) x.radiosity[c] += gain[c] * change_[e][c];
    }
    tree_.pull_up(channels_);
}

HierarchicalOutcome HierarchicalSystem::solve(const SolverControl& control,
                                              const std::function<void()>& publish) {
    HierarchicalOutcome out;
    if (tree_.top() < 0) {
        out.converged = true;
        return out;
    }
    double total_area = 0;
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        if (!tree_[e].cluster && tree_[e].leaf()) total_area += tree_[e].area_m2;
    }
    // Start from the source term (emission and reflected luminaire light): the first sweep then
    // gathers real light even where the operator is zero (black receivers).
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        Element& x = tree_[e];
        for (int c = 0; c < 3; ++c)
            x.radiosity[c] = x.exitance[c] + x.reflectance[c] * x.luminaire_irradiance[c];
    }
    tree_.pull_up(channels_);
    const ContractionNorms q{q_inf_, 2.0};  // only the max-norm bound is known here
    auto last_report = std::chrono::steady_clock::now();
    auto last_snapshot = last_report;
    constexpr std::size_t kMaxSweeps = 1000000;
    Residual previous;
    while (out.iterations < kMaxSweeps) {
        gather();
        Residual r;
        push(tree_.top(), Rgb{0, 0, 0}, 0, r);
        ++out.iterations;
        double worst = 0;
        for (int c = 0; c < channels_; ++c) {
            double sum_ab = 0;
            for (std::size_t e = 0; e < tree_.size(); ++e) {
                const Element& x = tree_[e];
                if (!x.cluster && x.leaf())
                    sum_ab += x.area_m2 * x.radiosity[static_cast<std::size_t>(c)];
            }
            const auto ci = static_cast<std::size_t>(c);
            worst = std::max(worst, relative_error_bound(q, q.q_inf * r.inf[ci], r.area_l1[ci],
                                                         sum_ab, total_area));
        }
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
        extrapolate(r, previous);
        previous = r;
    }
    tree_.pull_up(channels_);
    return out;
}

}  // namespace radiant
