#include "photometry/intensity_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

namespace radiant {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
constexpr double kAngleTolerance = 1e-9;

enum class Symmetry { rotational, quadrant, plane_c0, plane_c90, none };

Symmetry symmetry_of(const std::vector<double>& c) {
    const double first = c.front(), last = c.back();
    if (c.size() == 1) return Symmetry::rotational;
    if (first == 90 && last == 270) return Symmetry::plane_c90;
    if (last == 90) return Symmetry::quadrant;
    if (last == 180) return Symmetry::plane_c0;
    return Symmetry::none;
}

/// The angle in [0, 360) of the table's own range that shows the same intensity as `c`.
double fold(Symmetry s, double c) {
    c = std::fmod(c, 360.0);
    if (c < 0) c += 360;
    switch (s) {
        case Symmetry::quadrant:
            if (c > 180) c = 360 - c;
            return c > 90 ? 180 - c : c;
        case Symmetry::plane_c0:
            return c > 180 ? 360 - c : c;
        case Symmetry::plane_c90:
            if (c < 90) return 180 - c;
            return c > 270 ? 540 - c : c;
        default:
            return c;
    }
}

/// Fritsch–Butland slope at the middle of two secants: zero at an extremum, so that each piece
/// stays monotone. Slopes and secants per unit of x.
double monotone_slope(double h0, double h1, double d0, double d1) {
    if (d0 * d1 <= 0) return 0;
    const double w0 = 2 * h1 + h0, w1 = h1 + 2 * h0;
    return (w0 + w1) / (w0 / d0 + w1 / d1);
}

/// One curve sample: where (x) and what (y); absent beyond a table's open end.
struct Knot {
    double x = 0, y = 0;
};

/// Monotone cubic Hermite value at x in [k1.x, k2.x]; k0/k3 may be missing at an open end,
/// where the slope is the end piece's secant.
double monotone_cubic(double x, std::optional<Knot> k0, Knot k1, Knot k2, std::optional<Knot> k3) {
    const double h = k2.x - k1.x;
    if (!(h > 0)) return k1.y;
    const double d = (k2.y - k1.y) / h;
    const double m1 = k0 ? monotone_slope(k1.x - k0->x, h, (k1.y - k0->y) / (k1.x - k0->x), d) : d;
    const double m2 = k3 ? monotone_slope(h, k3->x - k2.x, d, (k3->y - k2.y) / (k3->x - k2.x)) : d;
    const double t = (x - k1.x) / h, t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * k1.y + (t3 - 2 * t2 + t) * h * m1 + (3 * t2 - 2 * t3) * k2.y +
           (t3 - t2) * h * m2;
}

constexpr std::array<double, 4> kGaussNodes{-0.8611363115940526, -0.3399810435848563,
                                            0.3399810435848563, 0.8611363115940526};
constexpr std::array<double, 4> kGaussWeights{0.3478548451374538, 0.6521451548625461,
                                              0.6521451548625461, 0.3478548451374538};

/// ∫ f over [a, b] with 4-point Gauss–Legendre on pieces no longer than `step`.
template <class F>
double gauss(double a, double b, double step, const F& f) {
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a) / step)));
    const double h = (b - a) / pieces;
    double sum = 0;
    for (int p = 0; p < pieces; ++p) {
        const double mid = a + (p + 0.5) * h;
        for (std::size_t k = 0; k < 4; ++k) {
            sum += kGaussWeights[k] * 0.5 * h * f(mid + 0.5 * h * kGaussNodes[k]);
        }
    }
    return sum;
}

/// What makes a table's angles or values unusable (empty when nothing does).
std::string layout_problem(const PhotometricTable& t) {
    const auto ascending = [](const std::vector<double>& a) {
        return std::adjacent_find(a.begin(), a.end(), std::greater_equal<>()) == a.end();
    };
    const auto finite = [](const std::vector<double>& a) {
        return std::all_of(a.begin(), a.end(), [](double x) { return std::isfinite(x); });
    };
    if (t.gamma_deg.size() < 2) return "a photometric table needs at least 2 vertical angles";
    if (t.c_deg.empty()) return "a photometric table needs at least 1 horizontal angle";
    if (!finite(t.gamma_deg) || !ascending(t.gamma_deg) || t.gamma_deg.front() < 0 ||
        t.gamma_deg.back() > 180) {
        return "vertical angles must increase within [0, 180] degrees";
    }
    if (!finite(t.c_deg) || !ascending(t.c_deg) || t.c_deg.front() < 0 || t.c_deg.back() > 360) {
        return "horizontal angles must increase within [0, 360] degrees";
    }
    const double first = t.c_deg.front(), last = t.c_deg.back();
    const bool known =
        (first == 0 && (t.c_deg.size() == 1 || last == 90 || last == 180 || last > 180)) ||
        (first == 90 && last == 270) || (t.c_deg.size() == 1);
    if (!known) {
        return "horizontal angles must run 0, 0–90, 0–180, 90–270 or 0–360 degrees (found " +
               std::to_string(first) + "–" + std::to_string(last) + ")";
    }
    if (t.candela.size() != t.c_deg.size() * t.gamma_deg.size()) {
        return "the table needs " + std::to_string(t.c_deg.size() * t.gamma_deg.size()) +
               " intensities, found " + std::to_string(t.candela.size());
    }
    if (!std::all_of(t.candela.begin(), t.candela.end(),
                     [](double x) { return std::isfinite(x) && x >= 0; })) {
        return "intensities must be finite and >= 0";
    }
    return {};
}

}  // namespace

std::variant<IntensityTable, std::string> read_intensity_table(const PhotometricTable& t) {
    if (std::string problem = layout_problem(t); !problem.empty()) return problem;
    IntensityTable table(t);
    if (!(table.flux_lm() > 0)) return std::string("the photometric table emits no light");
    return table;
}

std::string photometric_table_problem(const PhotometricTable& t) {
    const auto table = read_intensity_table(t);
    const auto* problem = std::get_if<std::string>(&table);
    return problem ? *problem : std::string();
}

IntensityTable::IntensityTable(const PhotometricTable& t) : gamma_(t.gamma_deg) {
    const Symmetry s = symmetry_of(t.c_deg);
    // A full turn of C-planes: every image of a table plane under the symmetry.
    for (const double c : t.c_deg) {
        for (const double image : {c, 180 - c, 180 + c, 360 - c}) {
            if (s == Symmetry::rotational && image != c) continue;
            const double a = std::fmod(image + 360.0, 360.0);
            if (std::abs(fold(s, a) - c) < kAngleTolerance) c_.push_back(a);
        }
    }
    std::sort(c_.begin(), c_.end());
    c_.erase(std::unique(c_.begin(), c_.end(),
                         [](double a, double b) { return b - a < kAngleTolerance; }),
             c_.end());
    const std::size_t m = gamma_.size();
    for (const double c : c_) {
        const double folded = s == Symmetry::rotational ? t.c_deg.front() : fold(s, c);
        const auto it = std::lower_bound(t.c_deg.begin(), t.c_deg.end(), folded - kAngleTolerance);
        const auto plane = static_cast<std::size_t>(it - t.c_deg.begin());
        for (std::size_t g = 0; g < m; ++g) cd_.push_back(t.at(plane, g));
    }
    flux_lm_ = integrate();
}

bool IntensityTable::alike_all_round() const {
    const std::size_t m = gamma_.size();
    for (std::size_t k = m; k < cd_.size(); ++k) {
        if (cd_[k] != cd_[k % m]) return false;
    }
    return true;
}

double IntensityTable::row(std::size_t g, double c_deg) const {
    const std::size_t n = c_.size(), m = gamma_.size();
    if (n == 1) return cd_[g];
    double c = std::fmod(c_deg, 360.0);
    if (c < 0) c += 360;
    // k: the last plane at or before c, counting the turn before 0 as plane n−1 − 360°.
    const auto after = std::upper_bound(c_.begin(), c_.end(), c);
    const long k = static_cast<long>(after - c_.begin()) - 1;
    const auto knot = [&](long i) {
        const long wraps =
            i >= 0 ? i / static_cast<long>(n) : -((-i - 1) / static_cast<long>(n)) - 1;
        const auto index = static_cast<std::size_t>(i - wraps * static_cast<long>(n));
        return Knot{c_[index] + 360.0 * static_cast<double>(wraps), cd_[index * m + g]};
    };
    return monotone_cubic(c, knot(k - 1), knot(k), knot(k + 1), knot(k + 2));
}

template <class RowAt>
double IntensityTable::along_gamma(double g, const RowAt& row_at) const {
    const std::size_t m = gamma_.size();
    if (!(g >= gamma_.front() - kAngleTolerance && g <= gamma_.back() + kAngleTolerance)) return 0;
    const auto after = std::upper_bound(gamma_.begin(), gamma_.end(), g);
    const std::size_t i =
        std::min(static_cast<std::size_t>(std::max<long>(0, after - gamma_.begin() - 1)), m - 2);
    // Beyond a pole the curve runs on in the opposite plane (γ → −γ, C → C + 180°).
    const auto knot = [&](long j) -> std::optional<Knot> {
        if (j >= 0 && j < static_cast<long>(m)) {
            const auto u = static_cast<std::size_t>(j);
            return Knot{gamma_[u], row_at(u, false)};
        }
        if (j < 0 && gamma_.front() == 0) return Knot{-gamma_[1], row_at(1, true)};
        if (j >= static_cast<long>(m) && gamma_.back() == 180) {
            return Knot{360 - gamma_[m - 2], row_at(m - 2, true)};
        }
        return std::nullopt;
    };
    const auto l = static_cast<long>(i);
    const double value = monotone_cubic(std::clamp(g, gamma_[i], gamma_[i + 1]), knot(l - 1),
                                        *knot(l), *knot(l + 1), knot(l + 2));
    return std::max(0.0, value);
}

double IntensityTable::candela(double gamma_rad, double c_rad) const {
    const double c = c_rad / kDegree;
    return along_gamma(gamma_rad / kDegree, [&](std::size_t u, bool opposite) {
        return row(u, opposite ? c + 180 : c);
    });
}

double IntensityTable::peak_candela() const { return *std::max_element(cd_.begin(), cd_.end()); }

double IntensityTable::widest_lit_gamma_rad() const {
    const std::size_t m = gamma_.size();
    std::size_t last = 0;
    for (std::size_t k = 0; k < cd_.size(); ++k)
        if (cd_[k] > 0) last = std::max(last, k % m);
    return gamma_[std::min(last + 1, m - 1)] * kDegree;
}

double IntensityTable::integrate() const {
    constexpr double kGammaStep = 2.5 * kDegree, kCStep = 5 * kDegree;
    const std::size_t m = gamma_.size();
    // Along one C direction every γ node reads the same rows: interpolate each across C once.
    std::vector<double> rows(m);
    const auto over_gamma = [&](double c_rad) {
        const double c = c_rad / kDegree;
        for (std::size_t u = 0; u < m; ++u) rows[u] = row(u, c);
        // Beyond the poles the curve reads the opposite plane at rows 1 and m − 2 only.
        const double before_pole = row(1, c + 180), after_pole = row(m - 2, c + 180);
        const auto row_at = [&](std::size_t u, bool opposite) {
            return opposite ? (u == 1 ? before_pole : after_pole) : rows[u];
        };
        double sum = 0;
        for (std::size_t i = 0; i + 1 < m; ++i) {
            sum += gauss(gamma_[i] * kDegree, gamma_[i + 1] * kDegree, kGammaStep,
                         [&](double g) { return along_gamma(g / kDegree, row_at) * std::sin(g); });
        }
        return sum;
    };
    if (c_.size() == 1) return 2 * std::numbers::pi * over_gamma(0);
    double sum = 0;
    for (std::size_t k = 0; k < c_.size(); ++k) {
        const double next = k + 1 < c_.size() ? c_[k + 1] : c_.front() + 360;
        sum += gauss(c_[k] * kDegree, next * kDegree, kCStep, over_gamma);
    }
    return sum;
}

}  // namespace radiant
