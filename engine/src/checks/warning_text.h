// How warnings name things: a surface, luminaire or sensor set by its name and JSON pointer, a
// share as a percentage.
#pragma once

#include <cstddef>
#include <string>

#include "radiant/scene.h"

namespace radiant {

/// The document pointer of engine surface `index` (Surface::pointer, else /surfaces/<index>).
std::string surface_pointer(const Scene& scene, std::size_t index);

/// `surface "ceiling" (/surfaces/1)`.
std::string surface_label(const Scene& scene, std::size_t index);

/// `"name"`: a name in double quotes.
std::string quoted(const std::string& name);

/// A share in [0, 1] as a whole percentage ("27 %"); under 1 % as "under 1 %".
std::string percent(double share);

/// A length in metres with two significant figures and a sensible unit ("5.7 km", "4 mm").
std::string length_text(double meters);

/// A point or direction as given: "(1.5, 2, 0.8)".
std::string point_text(const Vec3& p);

}  // namespace radiant
