// Building the JSON pointers that problems carry (RFC 6901).
#pragma once

#include <cstddef>
#include <string>

namespace radiant {

/// RFC 6901 escaping of one reference token (material and group names are user text).
inline std::string escape_token(const std::string& token) {
    std::string out;
    for (const char c : token) {
        if (c == '~') {
            out += "~0";
        } else if (c == '/') {
            out += "~1";
        } else {
            out += c;
        }
    }
    return out;
}

/// `base` followed by an array index.
inline std::string at(const std::string& base, std::size_t index) {
    return base + "/" + std::to_string(index);
}

}  // namespace radiant
