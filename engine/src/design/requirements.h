// EN 12464-1 requirements: the built-in activity table, a task area's requirement as applied,
// and the lower requirement of its immediate surrounding.
#pragma once

#include <string_view>

#include "radiant/lighting.h"
#include "radiant/result.h"

namespace radiant {

/// The table row with this reference number, or null.
const Activity* find_activity(std::string_view reference);

/// The criteria in force: the activity's values, overridden by those the requirement gives.
/// An unknown activity contributes nothing (check_scene refuses it).
AppliedRequirement apply_requirement(const Requirement& requirement);

/// The immediate surrounding's requirement (EN 12464-1:2011 §4.3.2, Table 1): Ēm 500 lx for
/// a task of 750 lx or more, 300 lx for 500 lx, 200 lx for 300 lx, the task's own below that;
/// U₀ ≥ 0.40. Glare and colour rendering are the task area's criteria only.
AppliedRequirement surrounding_requirement(const AppliedRequirement& task);

}  // namespace radiant
