// Light through a reflectance: the product of two per-channel values, channel by channel.
#pragma once

#include "radiant/scene.h"

namespace radiant {

inline Rgb times(const Rgb& a, const Rgb& b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }

}  // namespace radiant
