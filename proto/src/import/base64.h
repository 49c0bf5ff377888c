// Strict base64 (RFC 4648, standard alphabet, padding optional, whitespace allowed).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace radiant::proto {

/// The decoded bytes, or nothing when `text` is not base64.
std::optional<std::vector<unsigned char>> decode_base64(std::string_view text);

}  // namespace radiant::proto
