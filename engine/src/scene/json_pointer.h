// RFC 6901 JSON pointers, as problems and warnings name what in the scene they are about.
#pragma once

#include <string>

namespace radiant {

/// One reference token escaped ("~" → "~0", "/" → "~1"): names are user text.
inline std::string escape_pointer_token(const std::string& token) {
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

}  // namespace radiant
