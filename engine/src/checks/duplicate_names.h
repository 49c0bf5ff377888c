// Two surfaces, luminaires or sensor sets with one name: their results cannot be told apart.
#pragma once

#include <vector>

#include "radiant/warnings.h"

namespace radiant {

/// duplicate_name at every later use of a name already used in the same list. Surfaces of one
/// imported model (one document surface) share its name by design and are not reported.
void check_duplicate_names(const Scene& scene, std::vector<Warning>& out);

}  // namespace radiant
