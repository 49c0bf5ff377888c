// IES LM-63 photometric files (LM-63-1991, -1995, -2002; also the header-less 1986 layout).
#pragma once

#include <string>
#include <string_view>
#include <variant>

#include "radiant/photometry.h"

namespace radiant::proto {

/// The intensity table of an LM-63 file of photometric type C with TILT=NONE, in absolute
/// candela (values × candela multiplier × ballast factor). Or a message naming the line:
/// "ies: line 12: expected 37 vertical angles, found 30".
std::variant<PhotometricTable, std::string> read_ies(std::string_view text);

}  // namespace radiant::proto
