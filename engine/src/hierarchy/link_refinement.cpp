#include "hierarchy/link_refinement.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

#include "formfactor/area_average.h"
#include "formfactor/point_polygon.h"
#include "formfactor/quadrature.h"
#include "formfactor/shadow_rays.h"
#include "geometry/random.h"
#include "parallel/fork_join.h"
#include "parallel/per_thread.h"
#include "radiant/box.h"
#include "solution/surface_summary.h"

namespace radiant {
namespace {

using Pair = ElementPair;

// A source nearer to a receiver than this fraction of the receiver's diameter is
// near-singular for the receiver's quadrature points (see Oracle::surface_factor).
constexpr double kNearSingular = 0.25;

// A link's children's shares catch the covariance of the kernel and the radiosity between the
// children, not within them: for a kernel and a radiosity that vary linearly over the source,
// 3/4 of it (the variance of a square's quarters' means is 3/4 of the square's). Extrapolating
// the shares' departure from the area shares by 4/3 catches it all. Measured (box rooms at
// tolerance 0.005, the panel's irradiance): −1.14 % with the area mean, −0.43 % with the shares,
// −0.20 % extrapolated.
constexpr double kShareExtrapolation = 4.0 / 3.0;
// Pairs farther apart than this many times the larger one's diameter take the children's shares
// from the kernel between centroids (its error is second order in size / distance, the shares'
// departure from the area shares first order); nearer ones from Lambert's factor at the
// receiver's points.
constexpr double kShareFarRatio = 1;

enum class Decision { drop, link, split_receiver, split_source };

// Where a link's light comes from: the source itself, or for a cluster, the root patches its
// sample points lie on — so that a cluster never passes on light from a part of it that the
// receiver cannot see (a lit room behind a wall).
struct SourcePart {
    int element;
    double factor;
};

struct Verdict {
    Decision decision = Decision::drop;
    std::vector<SourcePart> parts;
};

// A round's pairs are judged and applied this many at a time, so that the verdicts held at once
// (each with its list of source parts) stay a few MB however many pairs a round has.
constexpr std::size_t kPairsPerSlice = std::size_t{1} << 16;
// Links at the end of linking: the new ones sorted, merged into a copy and then into the earlier
// ones (std::inplace_merge takes a buffer as large): each link is held up to this many times.
constexpr std::size_t kLinkCopiesAtMerge = 4;

// Kernel values at the receiver's points: unoccluded, or with sampled visibility.
struct KernelSamples {
    double factor = 0;                  ///< weighted mean: the link's K
    double spread = 0;                  ///< max − min over the points
    bool partial = false;               ///< some but not all shadow rays of some point were blocked
    std::vector<double> sample_factor;  ///< cluster sources: K carried by each sample point
};

class Oracle {
public:
    Oracle(const ElementTree& tree, const Visibility& visibility, const RefinementCriteria& c)
        : tree_(tree), visibility_(visibility), criteria_(c), eps_(visibility.epsilon()) {}

    /// `may_split` false: only elements that already have children may be split.
    Verdict judge(const Pair& p, bool may_split, std::uint64_t& rays) const {
        const Element& r = tree_[static_cast<std::size_t>(p.receiver)];
        const Element& s = tree_[static_cast<std::size_t>(p.source)];
        if (!may_exchange(r, s)) return {};
        // Clusters only send (see choose_split). A cluster linked as a receiver would hand the
        // irradiance of its few sample points to every part of it alike: the floor under an
        // emitter would get what its sample points on the rest of the floor see, and a
        // surface facing away what its neighbour facing the source gets.
        if (r.cluster) return {Decision::split_receiver, {}};
        // A closed receiver's irradiance is its gathered light divided by its factor sum (see
        // HierarchicalSystem), so an error δ in a factor moves it by δ·(source − the receiver's
        // mean incoming radiosity), not δ·source: a dim source beside a lit receiver still
        // counts, with the scene's mean radiosity standing in for that mean.
        const double power_per_factor =
            r.area_m2 *
            (closed(r) ? std::max(s.radiosity_max, criteria_.mean_radiosity) : s.radiosity_max);
        const double limit = criteria_.power_epsilon_lm / receiver_weight(r);
        const bool split_r = tree_.can_subdivide(p.receiver) && (may_split || !r.leaf());
        const bool split_s = tree_.can_subdivide(p.source) && (may_split || !s.leaf());
        const Decision split = choose_split(r, s, split_r, split_s);

        // A cluster stands in for its parts only from afar: near it, the point-to-disk kernels of
        // its samples misjudge the factor — even a black cluster's, whose factor still counts
        // when a receiver's factor sum is completed to 1 — unless the light that completion
        // would spread over its factor's error is within the link's limit.
        const bool clusters = s.cluster;
        if (clusters && split != Decision::link && box_distance(r, s) < s.diameter_m &&
            r.area_m2 * factor_bound(r, s) * criteria_.mean_radiosity > limit) {
            return {split, {}};
        }
        // A cluster's sample points stand for its mean radiosity; a bright part of it (an
        // emitter among dark surfaces) may lie where no sample point does. Its light above the
        // mean is bounded by the factor of the whole cluster seen from the nearest point.
        if (clusters && split != Decision::link) {
            const double above_mean =
                s.radiosity_max - photometric(s.radiosity, criteria_.channels);
            if (r.area_m2 * above_mean * factor_bound(r, s) > limit) return {split, {}};
        }

        // Decide from the unoccluded kernel first: most splits need no shadow ray at all.
        const KernelSamples open = kernel(r, s, p, false, rays);
        if (open.factor <= 0) return unseen_split(r, s, split_r, split_s);
        const double open_error = power_per_factor * (clusters ? open.factor : open.spread);
        if (open_error > limit && split != Decision::link) return {split, {}};
        // The receiver-side spread cannot see a source whose light varies over it: split that.
        if (!clusters && split_s && source_error(r, s) > limit) return {Decision::split_source, {}};

        const KernelSamples seen = criteria_.unoccluded ? open : kernel(r, s, p, true, rays);
        if (seen.factor <= 0) return {};
        double error = power_per_factor * (clusters ? seen.factor : seen.spread);
        if (seen.partial) error = std::max(error, power_per_factor * seen.factor);
        if (error > limit && split != Decision::link) return {split, {}};
        Verdict v{Decision::link, {}};
        if (!s.cluster) {
            v.parts.push_back({p.source, surface_factor(r, s, open, seen, limit)});
        } else {
            for (std::size_t m = 0; m < s.samples.size(); ++m) {
                if (seen.sample_factor[m] > 0)
                    v.parts.push_back({s.samples[m].root, seen.sample_factor[m]});
            }
        }
        return v;
    }

private:
    // A pair none of whose receiver points has the source in front: dropped, unless one of them
    // straddles the other's plane, where a part its points missed may still see the other (a
    // desk's side, all of whose points lie behind the side of a chair that starts 0.1 m from the
    // desk's end, sees that side from the end). The straddling one is split to find that part.
    static Verdict unseen_split(const Element& r, const Element& s, bool split_r, bool split_s) {
        if (r.cluster || s.cluster) return {};
        auto straddles = [](const Element& a, const Element& b) {
            return has_corner_on(a, b, 1) && has_corner_on(a, b, -1);
        };
        if (split_r && straddles(r, s)) return {Decision::split_receiver, {}};
        if (split_s && straddles(s, r)) return {Decision::split_source, {}};
        return {};
    }

    // Whether a corner of surface `a` lies in front of (`side` 1) or behind (−1) surface `b`'s
    // plane, beyond rounding.
    static bool has_corner_on(const Element& a, const Element& b, double side) {
        const double eps = 1e-9 * (a.diameter_m + b.diameter_m);
        return std::any_of(a.polygon.begin(), a.polygon.end(), [&](const Vec3& v) {
            return side * dot(v - b.polygon[0], b.normal) > eps;
        });
    }

    // The link hands the receiver the source's mean radiosity; where the source's radiosity and
    // the factor from its points to the receiver both vary over it (the floor under a panel, seen
    // from the panel), their covariance is light the link misplaces: bounded by the source's area
    // × its radiosity range × the factor's spread over its points (unoccluded).
    double source_error(const Element& r, const Element& s) const {
        const double range = s.radiosity_max - s.radiosity_min;
        if (!(range > 0)) return 0;
        double lo = 1e300, hi = 0;
        auto at = [&](const Vec3& y) {
            const double g =
                std::max(0.0, front_point_to_polygon_factor(y, s.normal, r.polygon, r.normal));
            lo = std::min(lo, g);
            hi = std::max(hi, g);
        };
        for (const SamplePoint& y : s.samples) at(y.position);
        at(polygon_centroid(s.polygon));
        return s.area_m2 * range * (hi - lo);
    }

    // The link's factor between two surface elements: the mean of the kernel over the
    // receiver's points, with their visibility. Where the source is near-singular for the
    // receiver — nearer than its points are to each other, but not touching (adjacent
    // elements refine along their common edge instead) — those points miss the strip along the
    // source's edges in which the factor falls from about 1 to about 0, so the unoccluded mean
    // comes from adaptive cubature, scaled by the visible fraction the points saw — except for
    // closed receivers, whose factor sums the solver completes (see closed()). The cubature stops
    // when its error would move no more light than the link may carry uncertain (`limit`), so dim
    // pairs cost little.
    double surface_factor(const Element& r, const Element& s, const KernelSamples& open,
                          const KernelSamples& seen, double limit) const {
        const double gap = box_distance(r, s);
        if (!(gap > 1e-9 * (r.diameter_m + s.diameter_m)) || gap >= kNearSingular * r.diameter_m ||
            !(s.radiosity_max > 0) || closed(r)) {
            return seen.factor;
        }
        const double mean = area_averaged_factor(r.polygon, r.normal, s.polygon, s.normal, 1e-3,
                                                 limit / s.radiosity_max);
        return open.factor > 0 ? mean * std::min(seen.factor / open.factor, 1.0) : mean;
    }

    // A receiver whose factor sum the solver completes (to 1 in a closed enclosure), which is
    // exact only while all its links average the kernel over the same points.
    bool closed(const Element& r) const {
        const auto patch = static_cast<std::size_t>(r.patch);
        return patch < criteria_.completed_patch.size() && criteria_.completed_patch[patch] != 0;
    }

    double receiver_weight(const Element& r) const {
        const auto patch = static_cast<std::size_t>(r.patch);
        return patch < criteria_.receiver_weight.size() ? criteria_.receiver_weight[patch] : 1.0;
    }

    static double box_distance(const Element& r, const Element& s) {
        return distance(Box{r.lo, r.hi}, Box{s.lo, s.hi});
    }

    // Upper bound of the factor from any point of r to all of s: A_s / (π d²), d the distance
    // between their boxes (cosines ≤ 1), and never above 1.
    static double factor_bound(const Element& r, const Element& s) {
        const double d = box_distance(r, s), d2 = d * d;
        const double area_over = s.area_m2 / std::numbers::pi;
        return area_over < d2 ? area_over / d2 : 1.0;
    }

    // Light passes only between elements that lie (partly) in front of each other.
    bool may_exchange(const Element& r, const Element& s) const {
        if (!r.cluster && !s.cluster) return has_corner_on(s, r, 1) && has_corner_on(r, s, 1);
        const Element* surface = r.cluster ? (s.cluster ? nullptr : &s) : &r;
        const Element* other = surface == &r ? &s : &r;
        if (!surface) return true;
        // Some corner of the other's box must lie in front of the surface.
        return !behind(Box{other->lo, other->hi}, surface->polygon[0], surface->normal);
    }

    // HSA91: split the element that looks bigger from the other; a cluster source opens first.
    // Receivers are surfaces here: judge() opens receiving clusters before it gets this far.
    static Decision choose_split(const Element& r, const Element& s, bool split_r, bool split_s) {
        if (split_r && split_s) {
            if (s.cluster) return Decision::split_source;
            return r.diameter_m >= s.diameter_m ? Decision::split_receiver : Decision::split_source;
        }
        if (split_r) return Decision::split_receiver;
        if (split_s) return Decision::split_source;
        return Decision::link;
    }

    KernelSamples kernel(const Element& r, const Element& s, const Pair& p, bool visibility,
                         std::uint64_t& rays) const {
        KernelSamples out;
        out.sample_factor.assign(s.cluster ? s.samples.size() : 0, 0.0);
        double lo = 1e300, hi = 0, weighted = 0, weights = 0;
        for (std::size_t k = 0; k < r.samples.size(); ++k) {
            const SamplePoint& x = r.samples[k];
            const std::uint64_t key = (static_cast<std::uint64_t>(p.receiver) << 32) ^
                                      static_cast<std::uint64_t>(p.source) ^ (k << 58);
            const double g = s.cluster ? from_cluster(x, s, visibility, out, rays)
                                       : from_surface(x, s, key, visibility, out.partial, rays);
            lo = std::min(lo, g);
            hi = std::max(hi, g);
            weighted += x.weight * g;
            weights += x.weight;
        }
        // Quadrature points lie symmetrically about the centre: under a coaxial source they all
        // see the same kernel, and their spread alone would call a strongly varying one flat.
        if (!visibility && !s.cluster && !r.cluster) {
            const double g =
                std::max(0.0, front_point_to_polygon_factor(polygon_centroid(r.polygon), r.normal,
                                                            s.polygon, s.normal));
            lo = std::min(lo, g);
            hi = std::max(hi, g);
        }
        out.factor = weights > 0 ? weighted / weights : 0;
        out.spread = hi - lo;
        for (double& f : out.sample_factor) f = weights > 0 ? f / weights : 0;
        return out;
    }

    // Lambert's exact factor to the source polygon, times the fraction of stratified shadow
    // rays that reach it (targets inset by 2ε so that a wall standing on the source blocks).
    double from_surface(const SamplePoint& x, const Element& s, std::uint64_t key, bool visibility,
                        bool& partial, std::uint64_t& rays) const {
        const double f = front_point_to_polygon_factor(x.position, x.normal, s.polygon, s.normal);
        if (f <= 0 || !visibility) return std::max(f, 0.0);
        const int m = criteria_.rays_per_point;
        SampleStream rng(criteria_.seed, key, 0x73757266ull);
        const double v = visible_fraction(visibility_, x.position, x.normal, s.polygon,
                                          polygon_centroid(s.polygon), s.normal, m, rng, rays);
        partial = partial || (v > 0 && v < 1);
        return f * v;
    }

    // A cluster as the sum of its sample points, each carrying a share of its area: the
    // classic point-to-disk kernel A cosθ cosθ' / (πr² + A), bounded as r → 0.
    double from_cluster(const SamplePoint& x, const Element& s, bool visibility, KernelSamples& out,
                        std::uint64_t& rays) const {
        double g = 0;
        int seen = 0, tried = 0;
        for (std::size_t m = 0; m < s.samples.size(); ++m) {
            const SamplePoint& y = s.samples[m];
            const double k = sample_kernel(x.position, x.normal, y);
            if (k <= 0) continue;
            if (visibility) {
                ++tried;
                ++rays;
                if (!visibility_.visible(x.position + x.normal * eps_,
                                         y.position + y.normal * eps_)) {
                    continue;
                }
                ++seen;
            }
            g += k;
            out.sample_factor[m] += x.weight * k;
        }
        out.partial = out.partial || (seen > 0 && seen < tried);
        return g;
    }

    const ElementTree& tree_;
    const Visibility& visibility_;
    const RefinementCriteria& criteria_;
    double eps_;
};

// Which sources may be linked now (RefinementCriteria::ready_source): a surface element with its
// patch, a cluster once any patch in it is.
class SourceReadiness {
public:
    SourceReadiness(const ElementTree& tree, std::span<const char> ready_patch)
        : tree_(tree), ready_patch_(ready_patch) {
        if (ready_patch_.empty() || tree.top() < 0) return;
        cluster_.assign(tree.size(), 0);
        classify(tree.top());
    }

    bool ready(int e) const {
        if (ready_patch_.empty()) return true;
        const Element& x = tree_[static_cast<std::size_t>(e)];
        return x.cluster ? cluster_[static_cast<std::size_t>(e)] != 0
                         : ready_patch_[static_cast<std::size_t>(x.patch)] != 0;
    }

private:
    bool classify(int e) {
        const Element& x = tree_[static_cast<std::size_t>(e)];
        if (!x.cluster) return ready(e);
        bool any = false;
        for (const int c : x.children) any = classify(c) || any;
        cluster_[static_cast<std::size_t>(e)] = any;
        return any;
    }

    const ElementTree& tree_;
    std::span<const char> ready_patch_;
    std::vector<char> cluster_;  // clusters are made with the tree: none is added later
};

// Each child's share of a link's factor, from the unoccluded kernel at the receiver's points and
// extrapolated (kShareExtrapolation), kept where it differs from the child's share of the area by
// more than the rounding of 255ths.
void share_sources(std::vector<Link>& links, const ElementTree& tree) {
    parallel_for(0, links.size(), [&](std::size_t i) {
        Link& l = links[i];
        const Element& s = tree[static_cast<std::size_t>(l.source)];
        if (s.cluster || s.leaf() || s.children.size() > l.child_share.size()) return;
        const Element& r = tree[static_cast<std::size_t>(l.receiver)];
        // Far from both (most links), the kernel between centroids tells the children apart.
        const bool far = distance(Box{r.lo, r.hi}, Box{s.lo, s.hi}) >=
                         kShareFarRatio * std::max(r.diameter_m, s.diameter_m);
        const Vec3 centre = polygon_centroid(r.polygon);
        std::array<double, 4> factor{0, 0, 0, 0};
        double total = 0;
        for (std::size_t c = 0; c < s.children.size(); ++c) {
            const Element& child = tree[static_cast<std::size_t>(s.children[c])];
            if (far) {
                factor[c] =
                    sample_kernel(centre, r.normal,
                                  {polygon_centroid(child.polygon), child.normal, child.area_m2});
            } else {
                for (const SamplePoint& x : r.samples) {
                    factor[c] += x.weight * std::max(0.0, front_point_to_polygon_factor(
                                                              x.position, x.normal, child.polygon,
                                                              child.normal));
                }
            }
            total += factor[c];
        }
        if (!(total > 0) || !(s.area_m2 > 0)) return;
        std::array<std::uint8_t, 4> share{};
        bool even = true;
        for (std::size_t c = 0; c < s.children.size(); ++c) {
            const double by_area =
                255 * tree[static_cast<std::size_t>(s.children[c])].area_m2 / s.area_m2;
            const double by_factor = 255 * factor[c] / total;
            const double extrapolated = by_area + kShareExtrapolation * (by_factor - by_area);
            share[c] = static_cast<std::uint8_t>(std::lround(std::clamp(extrapolated, 0.0, 255.0)));
            even = even && std::abs(by_factor - by_area) <= 1;
        }
        if (!even) l.child_share = share;
    });
}

}  // namespace

RefinementOutcome refine_links(ElementTree& tree, const Visibility& visibility,
                               const RefinementCriteria& criteria) {
    RefinementOutcome out;
    if (tree.top() >= 0) out.deferred.push_back({tree.top(), tree.top()});
    resume_links(out, tree, visibility, criteria);
    return out;
}

void resume_links(RefinementOutcome& out, ElementTree& tree, const Visibility& visibility,
                  const RefinementCriteria& criteria) {
    const Oracle oracle(tree, visibility, criteria);
    const SourceReadiness ready(tree, criteria.ready_source);
    std::vector<Pair> pending = std::move(out.deferred);
    out.deferred.clear();
    std::vector<Link> made;
    auto add_links = [&made](const Pair& p, const Verdict& v) {
        for (const SourcePart& part : v.parts) {
            made.push_back({p.receiver, part.element, static_cast<float>(part.factor)});
        }
    };
    for (; !pending.empty(); ++out.rounds) {
        if (criteria.on_round)
            criteria.on_round(out.rounds, out.rays, out.links.size() + made.size());
        if (criteria.should_stop && criteria.should_stop()) {
            out.stopped = true;
            break;
        }
        // Pairs whose sources hold a ready patch are judged (a cluster's link carries the light of
        // all its parts: it is made when the first of them is ready); the rest wait.
        std::vector<Pair> pairs;
        auto admit = [&](const Pair& p) {
            (ready.ready(p.source) ? pairs : out.deferred).push_back(p);
        };
        // An element's link to itself: a cluster's parts light each other; a plane never does.
        for (const Pair& p : pending) {
            if (p.receiver != p.source) {
                admit(p);
                continue;
            }
            const Element& e = tree[static_cast<std::size_t>(p.receiver)];
            if (!e.cluster) continue;
            if (!ready.ready(p.source)) {
                out.deferred.push_back(p);
                continue;
            }
            for (const int a : e.children) {
                for (const int b : e.children) {
                    if (a == b) {
                        pairs.push_back({a, b});  // opened next round
                    } else {
                        admit({a, b});
                    }
                }
            }
        }
        std::vector<Verdict> verdicts(std::min(pairs.size(), kPairsPerSlice));
        PerThread<std::uint64_t> rays([] { return std::uint64_t{0}; });
        auto count_rays = [&] {
            out.rays += rays.combine([](std::uint64_t a, std::uint64_t b) { return a + b; });
            rays.clear();
        };
        pending.clear();
        std::vector<std::size_t> rejudge;  // splits the budget refused: judged again unsplit
        const std::size_t first_new = tree.size();
        auto over_budget = [&] {
            const std::size_t held =
                tree.bytes() + tree.size() * criteria.later_bytes_per_element +
                (out.links.capacity() + made.capacity()) * sizeof(Link) * kLinkCopiesAtMerge +
                (pairs.capacity() + pending.capacity() + out.deferred.capacity()) * sizeof(Pair) +
                verdicts.size() * sizeof(Verdict);
            if (criteria.max_bytes > 0 && held > criteria.max_bytes) out.budget_reached = true;
            return out.budget_reached;
        };
        // The slice's verdicts, [begin, begin + verdicts.size()) of the round's pairs.
        std::size_t begin = 0;
        auto verdict = [&](std::size_t i) -> Verdict& { return verdicts[i - begin]; };
        auto apply = [&](std::size_t i) {
            const Pair& p = pairs[i];
            const Verdict& v = verdict(i);
            switch (v.decision) {
                case Decision::drop:
                    break;
                case Decision::link:
                    add_links(p, v);
                    break;
                case Decision::split_receiver:
                case Decision::split_source: {
                    const bool receiver = v.decision == Decision::split_receiver;
                    const int e = receiver ? p.receiver : p.source;
                    if (tree[static_cast<std::size_t>(e)].leaf() && over_budget()) {
                        rejudge.push_back(i);
                        break;
                    }
                    tree.subdivide(e);
                    for (const int c : tree[static_cast<std::size_t>(e)].children) {
                        pending.push_back(receiver ? Pair{c, p.source} : Pair{p.receiver, c});
                    }
                    break;
                }
            }
        };
        bool interrupted_round = false;
        for (; begin < pairs.size() && !interrupted_round; begin += verdicts.size()) {
            const std::size_t end = std::min(pairs.size(), begin + verdicts.size());
            for (Verdict& v : verdicts) v = Verdict{};
            // A round of a large model takes seconds; a stop request ends it within a pair or
            // so, and the pairs not judged by then are dropped, like those still pending between
            // rounds.
            std::atomic<bool> interrupted{false};
            parallel_for(begin, end, [&](std::size_t i) {
                if (pairs[i].receiver == pairs[i].source) return;  // opened next round
                if (interrupted.load(std::memory_order_relaxed)) return;
                if (criteria.should_stop && criteria.should_stop()) {
                    interrupted = true;
                    return;
                }
                verdict(i) = oracle.judge(pairs[i], !out.budget_reached, rays.local());
            });
            count_rays();
            if (interrupted) {
                // Keep what was judged to link; splitting would only queue pairs nobody judges.
                for (std::size_t i = begin; i < end; ++i) {
                    if (verdict(i).decision == Decision::link) add_links(pairs[i], verdict(i));
                }
                interrupted_round = true;
                break;
            }
            for (std::size_t i = begin; i < end; ++i) {
                if (pairs[i].receiver == pairs[i].source) {
                    pending.push_back(pairs[i]);
                } else {
                    apply(i);
                }
            }
            if (!rejudge.empty()) {
                parallel_for(0, rejudge.size(), [&](std::size_t k) {
                    verdict(rejudge[k]) = oracle.judge(pairs[rejudge[k]], false, rays.local());
                });
                const std::vector<std::size_t> unsplit = std::move(rejudge);
                rejudge.clear();
                for (const std::size_t i : unsplit) apply(i);
                count_rays();
            }
        }
        if (interrupted_round) {
            out.stopped = true;
            break;
        }
        if (tree.size() > first_new) {
            out.rays += tree.light_from(first_new);
            tree.estimate_from(first_new, criteria.ambient_irradiance, criteria.channels);
        }
    }
    // Samples of one cluster on the same patch make one link.
    auto by_pair = [](const Link& a, const Link& b) {
        return a.receiver != b.receiver ? a.receiver < b.receiver : a.source < b.source;
    };
    std::sort(made.begin(), made.end(), by_pair);
    std::vector<Link> merged;
    merged.reserve(made.size());
    for (const Link& l : made) {
        if (!merged.empty() && merged.back().receiver == l.receiver &&
            merged.back().source == l.source) {
            merged.back().factor += l.factor;
        } else {
            merged.push_back(l);
        }
    }
    // Earlier stages linked other sources: no pair is linked twice.
    const auto earlier = static_cast<std::ptrdiff_t>(out.links.size());
    out.links.insert(out.links.end(), merged.begin(), merged.end());
    std::inplace_merge(out.links.begin(), out.links.begin() + earlier, out.links.end(), by_pair);
    // Sources split since their links were made hand on by their children's shares too.
    share_sources(out.links, tree);
}

}  // namespace radiant
