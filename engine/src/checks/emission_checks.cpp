#include "checks/emission_checks.h"

#include "checks/warning_text.h"
#include "scene/json_pointer.h"

namespace radiant {

void check_emission(const Scene& scene, const PreparedScene& prepared, std::vector<Warning>& out) {
    if (!(emitted_light(prepared).total_lm() > 0)) {
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
}

}  // namespace radiant
