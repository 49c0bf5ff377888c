// Two surfaces, luminaires or sensor sets with one name: their results cannot be told apart.
#pragma once

#include <vector>

#include "radiant/warnings.h"

namespace radiant {

/// duplicate_name once per name used more than once in the same list, at its second use.
/// Surfaces of one imported model (one document surface) share its name by design and are not
/// reported.
void check_duplicate_names(const Scene& scene, std::vector<Warning>& out);

}  // namespace radiant
