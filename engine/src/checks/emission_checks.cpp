#include "checks/emission_checks.h"

#include <cstdio>

#include "checks/warning_text.h"
#include "scene/json_pointer.h"

namespace radiant {
namespace {

// Spread evenly over its surfaces, a furnished room's light averages 10-130 lx (a lounge of three
// table lamps 16, an office 73, a cove-lit lobby 130). Under this, a flux in the wrong unit is
// likelier than a room meant to be so dark: the example office's two 3 000 lm panels typed as
// their 30 W read 0.5 lx, as 3 (klm) 0.05 lx. Under kLeastPlausibleMeanLux units_suspect speaks
// instead.
constexpr double kLeastMeanLux = 1;

// flux_suspect when the light given as flux (luminaires, materials' `flux`), the most of what
// the scene emits, averages under kLeastMeanLux over the surfaces: it names the brightest source.
void check_flux_level(const Scene& scene, const PreparedScene& prepared,
                      const EmittedLight& emitted, std::vector<Warning>& out) {
    const double mean_lux = mean_surface_lux(prepared, emitted);
    if (!(mean_lux >= kLeastPlausibleMeanLux && mean_lux < kLeastMeanLux)) return;
    // Emission given as exitance (the exact cases' 1 lm/m²) is a radiometric test, not a lamp.
    std::vector<double> material_lm(prepared.materials.size(), 0.0);
    for (const Piece& p : prepared.pieces) {
        const auto m = static_cast<std::size_t>(p.material);
        material_lm[m] += luminance(prepared.materials[m].exitance_lm_m2) * p.area_m2;
    }
    double given_lm = 0, brightest_lm = 0;
    std::string brightest, pointer;
    for (std::size_t i = 0; i < prepared.luminaires.size() && i < scene.luminaires.size(); ++i) {
        const double lm = luminance(prepared.luminaires[i].flux_lm);
        given_lm += lm;
        if (lm > brightest_lm) {
            brightest_lm = lm;
            brightest = "luminaire " + quoted(scene.luminaires[i].name);
            pointer = "/luminaires/" + std::to_string(i);
        }
    }
    for (std::size_t m = 0; m < scene.materials.size() && m < material_lm.size(); ++m) {
        const std::optional<Emission>& e = scene.materials[m].emission;
        if (!e || e->kind != Emission::Kind::flux) continue;
        given_lm += material_lm[m];
        if (material_lm[m] > brightest_lm) {
            brightest_lm = material_lm[m];
            brightest = "material " + quoted(scene.materials[m].name);
            pointer = "/materials/" + escape_pointer_token(scene.materials[m].name) + "/emission";
        }
    }
    if (!(given_lm >= 0.5 * emitted.total_lm()) || brightest.empty()) return;
    char text[200];
    std::snprintf(text, sizeof text,
                  "the light would average %.2g lx over the model's surfaces, where a furnished "
                  "room's averages 10-130 lx; %s emits the most, %.3g lm: is a flux in W or klm "
                  "rather than lm?",
                  mean_lux, brightest.c_str(), brightest_lm);
    out.push_back({"flux_suspect", text, pointer});
}

}  // namespace

void check_emission(const Scene& scene, const PreparedScene& prepared, std::vector<Warning>& out) {
    const EmittedLight emitted = emitted_light(prepared);
    if (!(emitted.total_lm() > 0)) {
        out.push_back({"no_light",
                       "nothing emits light: every result is 0 lx; add luminaires, or an "
                       "emitting material on a surface",
                       "/luminaires"});
    }
    std::vector<bool> used(prepared.materials.size(), false);
    for (const Piece& p : prepared.pieces) used[static_cast<std::size_t>(p.material)] = true;
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const Material& material = scene.materials[m];
        if (!material.emission || !(material.emission->value > 0) || used[m]) continue;
        out.push_back({"emission_unused",
                       "material " + quoted(material.name) + " emits light, but no surface uses it",
                       "/materials/" + escape_pointer_token(material.name) + "/emission"});
    }
    check_flux_level(scene, prepared, emitted, out);
}

}  // namespace radiant
