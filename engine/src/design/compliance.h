// A requirement checked against a solve's numbers: Ēm and U₀ of the sensor set (maintained
// values), the largest UGR of the observers that check it, the smallest Ra of the lit sources.
#pragma once

#include <optional>
#include <vector>

#include "radiant/result.h"

namespace radiant {

/// `observers`: those that check this set's glare (none: the UGR criterion is `unknown`).
/// `ra`: the smallest Ra of the sources that light the scene, none when one of them lacks it.
Compliance check_requirement(const AppliedRequirement& requirement, const SensorResult& set,
                             const std::vector<const ObserverResult*>& observers,
                             std::optional<double> ra);

}  // namespace radiant
