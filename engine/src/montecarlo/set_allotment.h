// How many ray sets each sensor point gets: where a few points are far noisier than the rest
// (under a lamp's shade, beside a bright window), sets spread evenly spend most rays where the
// answer is already good.
#pragma once

#include <cstddef>
#include <vector>

namespace radiant {

/// Ray sets per point such that each sensor set (`set_sizes` split the points) holds `sets[s]`
/// per point on average, or a little more: in proportion to each point's spread per set
/// (`spread`, a standard deviation; empty: the same for all), which gives the least sum of the
/// points' variances for those sets (n ∝ σ), and never fewer than a point `has`. A point's
/// spread counts as at least kMinSpreadShare of its set's RMS spread, so that one whose first
/// sets happened to agree still gets a share; a set without spread gets `sets[s]` for every
/// point.
std::vector<int> allot_sets(const std::vector<int>& sets, const std::vector<int>& has,
                            const std::vector<double>& spread,
                            const std::vector<std::size_t>& set_sizes);

/// The floor on a point's spread, as a share of its set's RMS spread.
inline constexpr double kMinSpreadShare = 0.25;

}  // namespace radiant
