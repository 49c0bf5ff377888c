// EULUMDAT (.ldt) photometric files.
#pragma once

#include <string>
#include <string_view>
#include <variant>

#include "radiant/photometry.h"

namespace radiant::proto {

/// The intensity table of a EULUMDAT file in absolute candela (cd/klm × the first lamp set's
/// total flux / 1000 × the conversion factor), with the C-planes its symmetry indicator (Isym
/// 0–4) says it holds. Or a message naming the line: "ldt: line 3: ...".
std::variant<PhotometricTable, std::string> read_ldt(std::string_view text);

}  // namespace radiant::proto
