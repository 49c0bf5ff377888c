#include "checks/units_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "checks/modelling_checks.h"
#include "checks/warning_text.h"

namespace radiant {
namespace {

// What interiors measure, generously: a model from a 10 cm light box to a 1 km campus;
// luminaires from 5 cm (a strip of spots) to 100 m apart (a stadium); the light spread evenly
// over every surface from 0.01 lx to 10⁶ lx (ten times sunlight). A typical model is 10 m across.
struct Plausible {
    double low, high;
    bool holds(double x) const { return x >= low && x <= high; }
};
constexpr Plausible kExtentM{0.1, 1000};
constexpr Plausible kSpacingM{0.05, 100};
constexpr Plausible kMeanLux{kLeastPlausibleMeanLux, 1e6};
constexpr double kTypicalExtentM = 10;
// Nearest neighbours are looked up for at most this many luminaires.
constexpr std::size_t kSpacingSamples = 256;

struct UnitName {
    LengthUnit unit;
    const char* name;
};
constexpr UnitName kUnits[] = {{LengthUnit::m, "m"},
                               {LengthUnit::cm, "cm"},
                               {LengthUnit::mm, "mm"},
                               {LengthUnit::ft, "ft"},
                               {LengthUnit::in, "in"}};

const char* name_of(LengthUnit unit) {
    for (const UnitName& u : kUnits) {
        if (u.unit == unit) return u.name;
    }
    return "m";
}

/// The unit under which a length of `meters`, measured under `given`, comes nearest `typical`.
LengthUnit likely_unit(LengthUnit given, double meters, double typical) {
    LengthUnit best = given;
    double best_miss = std::numeric_limits<double>::infinity();
    for (const UnitName& u : kUnits) {
        const double scale = meters_per_unit(u.unit) / meters_per_unit(given);
        const double miss = std::abs(std::log(meters * scale / typical));
        if (miss < best_miss) {
            best_miss = miss;
            best = u.unit;
        }
    }
    return best;
}

/// Median distance from a luminaire to its nearest neighbour (metres); 0 with fewer than two.
double median_spacing_m(const PreparedScene& prepared) {
    const auto& l = prepared.luminaires;
    if (l.size() < 2) return 0;
    const std::size_t step = std::max<std::size_t>(1, l.size() / kSpacingSamples);
    std::vector<double> nearest;
    for (std::size_t i = 0; i < l.size(); i += step) {
        double d = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < l.size(); ++j) {
            if (j != i) d = std::min(d, length(l[j].position - l[i].position));
        }
        nearest.push_back(d);
    }
    std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
    return nearest[nearest.size() / 2];
}

std::string lux_text(double lux) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2g lx", lux);
    return text;
}

}  // namespace

void check_units(const Scene& scene, const PreparedScene& prepared, std::vector<Warning>& out) {
    const EmittedLight emitted = emitted_light(prepared);
    const double emitted_lm = emitted.total_lm();
    const double spacing_m = median_spacing_m(prepared);
    const double mean_lux = mean_surface_lux(prepared, emitted);
    std::string what;
    if (!kExtentM.holds(prepared.diagonal_m)) {
        what = "the model is " + length_text(prepared.diagonal_m) + " across";
    } else if (spacing_m > 0 && !kSpacingM.holds(spacing_m)) {
        what = "its luminaires are " + length_text(spacing_m) + " apart";
    } else if (emitted_lm > 0 && !kMeanLux.holds(mean_lux)) {
        what = "its light would average " + lux_text(mean_lux) + " over its surfaces";
    } else {
        return;
    }
    // The unit is guessed from the model's size, which does not depend on the flux.
    const LengthUnit likely = likely_unit(scene.units, prepared.diagonal_m, kTypicalExtentM);
    std::string message = "\"units\" is \"" + std::string(name_of(scene.units)) + "\", and " + what;
    message += likely == scene.units ? ": check the units and the luminaires' flux"
                                     : ": are its lengths in " + std::string(name_of(likely)) + "?";
    out.push_back({"units_suspect", std::move(message), "/units"});
}

}  // namespace radiant
