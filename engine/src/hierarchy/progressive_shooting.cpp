#include "hierarchy/progressive_shooting.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <boost/heap/d_ary_heap.hpp>

#include "solution/surface_summary.h"
#include "solver/solver.h"

namespace radiant {
namespace {

struct Candidate {
    double power;
    int patch;
    bool operator<(const Candidate& o) const {
        return power != o.power ? power < o.power : patch > o.patch;
    }
};

}  // namespace

ProgressiveShooting::ProgressiveShooting(ElementTree& tree, const std::vector<Link>& links,
                                         const LeafCompletion& completion, std::size_t n_patches,
                                         int channels)
    : tree_(tree), links_(links), completion_(completion), channels_(channels) {
    root_of_patch_.assign(n_patches, -1);
    for (std::size_t e = 0; e < tree.size(); ++e) {
        const Element& x = tree[e];
        if (!x.cluster && x.depth == 0)
            root_of_patch_[static_cast<std::size_t>(x.patch)] = static_cast<int>(e);
    }
    auto source_patch = [&](const Link& l) {
        return static_cast<std::size_t>(tree[static_cast<std::size_t>(l.source)].patch);
    };
    first_sent_.assign(n_patches + 1, 0);
    for (const Link& l : links) ++first_sent_[source_patch(l) + 1];
    for (std::size_t p = 0; p < n_patches; ++p) first_sent_[p + 1] += first_sent_[p];
    sent_.resize(links.size());
    std::vector<std::size_t> next(first_sent_.begin(), first_sent_.end() - 1);
    for (std::size_t k = 0; k < links.size(); ++k) sent_[next[source_patch(links[k])]++] = k;
    is_touched_.assign(n_patches, 0);
}

std::array<double, 3> ProgressiveShooting::run(const SolverControl& control,
                                               const std::function<void()>& publish,
                                               std::vector<Rgb>& irradiance) {
    const std::size_t n = tree_.size();
    pending_.assign(n, Rgb{0, 0, 0});
    unshot_.assign(n, Rgb{0, 0, 0});
    power_.assign(root_of_patch_.size(), 0.0);
    double area = 0, rho_area = 0;
    for (std::size_t e = 0; e < n; ++e) {
        Element& x = tree_[e];
        if (x.cluster) continue;
        x.radiosity = source_radiosity(x);
        if (!x.leaf()) continue;
        irradiance[e] = x.luminaire_irradiance;
        unshot_[e] = x.radiosity;
        power_[static_cast<std::size_t>(x.patch)] +=
            x.area_m2 * photometric(x.radiosity, channels_);
        area += x.area_m2;
        rho_area +=
            x.area_m2 * *std::max_element(x.reflectance.begin(), x.reflectance.begin() + channels_);
    }
    omega_ = over_relaxation(area > 0 ? rho_area / area : 0);
    // Most unshot power first (ties: the lower patch index, so the order is reproducible); a
    // patch is in the queue at most once, its key raised as light reaches it.
    using Queue =
        boost::heap::d_ary_heap<Candidate, boost::heap::arity<4>, boost::heap::mutable_<true>>;
    Queue queue;
    std::vector<Queue::handle_type> handle(power_.size());
    std::vector<char> queued(power_.size(), 0);
    auto offer = [&](int p) {
        const auto pi = static_cast<std::size_t>(p);
        if (queued[pi]) {
            queue.increase(handle[pi], Candidate{power_[pi], p});
        } else if (power_[pi] > 0) {
            handle[pi] = queue.push(Candidate{power_[pi], p});
            queued[pi] = 1;
        }
    };
    for (std::size_t p = 0; p < power_.size(); ++p) offer(static_cast<int>(p));
    auto last_snapshot = std::chrono::steady_clock::now();
    std::size_t links_sent = 0;
    while (!queue.empty() && links_sent < links_.size()) {
        const int patch = queue.top().patch;
        const auto shooter = static_cast<std::size_t>(patch);
        queue.pop();
        queued[shooter] = 0;
        send(patch, irradiance);
        links_sent += first_sent_[shooter + 1] - first_sent_[shooter];
        offer(patch);  // what it overshot
        for (const int p : touched_) {
            is_touched_[static_cast<std::size_t>(p)] = 0;
            offer(p);
        }
        touched_.clear();
        const auto now = std::chrono::steady_clock::now();
        if (publish && now - last_snapshot >= control.snapshot_interval) {
            settle_all(irradiance);
            publish_with_ambient(publish);
            last_snapshot = now;
        }
        if (control.should_stop()) break;
    }
    settle_all(irradiance);
    tree_.pull_up(channels_);
    std::array<double, 3> largest{0, 0, 0};
    for (std::size_t e = 0; e < n; ++e) {
        if (tree_[e].cluster || !tree_[e].leaf()) continue;
        for (int c = 0; c < channels_; ++c) {
            const auto ci = static_cast<std::size_t>(c);
            largest[ci] = std::max(largest[ci], std::abs(unshot_[e][ci]));
        }
    }
    return largest;
}

void ProgressiveShooting::send(int patch, std::vector<Rgb>& irradiance) {
    const auto p = static_cast<std::size_t>(patch);
    const int root = root_of_patch_[p];
    if (root < 0) return;
    settle(root, Rgb{0, 0, 0}, irradiance);
    pull_unshot(root);
    for (std::size_t k = first_sent_[p]; k < first_sent_[p + 1]; ++k) {
        const Link& l = links_[sent_[k]];
        const Rgb u = handed_radiosity(
            l, tree_, [this](int s) -> const Rgb& { return unshot_[static_cast<std::size_t>(s)]; });
        const auto r = static_cast<std::size_t>(l.receiver);
        const Element& receiver = tree_[r];
        Rgb reflected{0, 0, 0};
        for (int c = 0; c < channels_; ++c) {
            const double received = omega_ * l.factor * u[c];
            pending_[r][c] += received;
            reflected[c] = receiver.reflectance[c] * received;
        }
        const auto q = static_cast<std::size_t>(receiver.patch);
        power_[q] += completion_.weight[r] * std::abs(photometric(reflected, channels_));
        if (!is_touched_[q]) {
            is_touched_[q] = 1;
            touched_.push_back(receiver.patch);
        }
    }
    scale_unshot(root, 1 - omega_);
    power_[p] *= omega_ - 1;
}

// Pushes the pending irradiance of e and its descendants down to the leaves, where it becomes
// irradiance, radiosity and unshot radiosity alike.
void ProgressiveShooting::settle(int index, const Rgb& down, std::vector<Rgb>& irradiance) {
    const auto e = static_cast<std::size_t>(index);
    const Rgb own = pending_[e];
    pending_[e] = Rgb{0, 0, 0};
    Element& x = tree_[e];
    if (!x.leaf()) {
        Rgb h = down;
        for (int c = 0; c < 3; ++c) h[c] += own[c];
        for (const int child : x.children) settle(child, h, irradiance);
        return;
    }
    for (int c = 0; c < channels_; ++c) {
        const double received =
            own[c] * completion_.own_scale[e] + down[c] * completion_.inherited_scale[e];
        const double reflected = x.reflectance[c] * received;
        irradiance[e][c] += received;
        x.radiosity[c] += reflected;
        unshot_[e][c] += reflected;
    }
}

void ProgressiveShooting::settle_all(std::vector<Rgb>& irradiance) {
    for (const int root : root_of_patch_) {
        if (root >= 0) settle(root, Rgb{0, 0, 0}, irradiance);
    }
}

const Rgb& ProgressiveShooting::pull_unshot(int index) {
    const auto e = static_cast<std::size_t>(index);
    const Element& x = tree_[e];
    if (x.leaf()) return unshot_[e];
    Rgb sum{0, 0, 0};
    double area = 0;
    for (const int child : x.children) {
        const Rgb& u = pull_unshot(child);
        const double a = tree_[static_cast<std::size_t>(child)].area_m2;
        for (int c = 0; c < 3; ++c) sum[c] += a * u[c];
        area += a;
    }
    for (int c = 0; c < 3; ++c) unshot_[e][c] = area > 0 ? sum[c] / area : 0;
    return unshot_[e];
}

void ProgressiveShooting::scale_unshot(int index, double factor) {
    const auto e = static_cast<std::size_t>(index);
    for (double& u : unshot_[e]) u *= factor;
    for (const int child : tree_[e].children) scale_unshot(child, factor);
}

// Shows each leaf with ρ·seen·ambient added (see ambient_term), then puts back the radiosity as
// it was, to the bit: when snapshots fall must not change the solution.
void ProgressiveShooting::publish_with_ambient(const std::function<void()>& publish) {
    std::vector<std::size_t> leaves;
    std::vector<double> area, seen;
    for (std::size_t e = 0; e < tree_.size(); ++e) {
        const Element& x = tree_[e];
        if (x.cluster || !x.leaf()) continue;
        leaves.push_back(e);
        area.push_back(x.area_m2);
        seen.push_back(std::min(1.0, completion_.completed_sum[e]));
    }
    Rgb ambient{0, 0, 0};
    std::vector<double> unshot(leaves.size()), rho(leaves.size());
    for (int c = 0; c < channels_; ++c) {
        for (std::size_t k = 0; k < leaves.size(); ++k) {
            unshot[k] = unshot_[leaves[k]][c];
            rho[k] = tree_[leaves[k]].reflectance[c];
        }
        ambient[c] = ambient_term(unshot, rho, area, seen);
    }
    std::vector<Rgb> radiosity(leaves.size());
    for (std::size_t k = 0; k < leaves.size(); ++k) {
        Element& x = tree_[leaves[k]];
        radiosity[k] = x.radiosity;
        for (int c = 0; c < channels_; ++c)
            x.radiosity[c] += x.reflectance[c] * seen[k] * ambient[c];
    }
    tree_.pull_up(channels_);
    publish();
    for (std::size_t k = 0; k < leaves.size(); ++k) tree_[leaves[k]].radiosity = radiosity[k];
    tree_.pull_up(channels_);
}

}  // namespace radiant
