// Base64 (RFC 4648, standard alphabet): strict decoding of embedded model files (padding
// optional, whitespace allowed), and encoding of binary arrays in the service's events.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace radiant::proto {

/// The decoded bytes, or nothing when `text` is not base64.
std::optional<std::vector<unsigned char>> decode_base64(std::string_view text);

/// `bytes` as padded base64 without line breaks.
std::string encode_base64(std::string_view bytes);

}  // namespace radiant::proto
