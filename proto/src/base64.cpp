#include "radiant/proto/base64.h"

#include <array>

namespace radiant::proto {
namespace {

constexpr std::string_view kAlphabet =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

}  // namespace

std::optional<std::vector<unsigned char>> decode_base64(std::string_view text) {
    static const std::array<int, 256> value = [] {
        std::array<int, 256> v{};
        v.fill(-1);
        for (std::size_t i = 0; i < kAlphabet.size(); ++i)
            v[static_cast<unsigned char>(kAlphabet[i])] = static_cast<int>(i);
        return v;
    }();
    std::vector<unsigned char> out;
    out.reserve(text.size() / 4 * 3);
    unsigned bits = 0;
    int count = 0, padding = 0;
    for (const char c : text) {
        if (c == ' ' || c == '\n' || c == '\r' || c == '\t') continue;
        if (c == '=') {
            ++padding;
            continue;
        }
        const int v = value[static_cast<unsigned char>(c)];
        if (v < 0 || padding > 0) return std::nullopt;  // a bad character, or data after '='
        bits = (bits << 6) | static_cast<unsigned>(v);
        if (++count % 4 == 0) {
            out.push_back(static_cast<unsigned char>(bits >> 16));
            out.push_back(static_cast<unsigned char>(bits >> 8));
            out.push_back(static_cast<unsigned char>(bits));
            bits = 0;
        }
    }
    const int tail = count % 4;
    if (tail == 1 || padding > 2 || (padding > 0 && (tail + padding) % 4 != 0)) return std::nullopt;
    if (tail == 2) out.push_back(static_cast<unsigned char>(bits >> 4));
    if (tail == 3) {
        out.push_back(static_cast<unsigned char>(bits >> 10));
        out.push_back(static_cast<unsigned char>(bits >> 2));
    }
    return out;
}

std::string encode_base64(std::string_view bytes) {
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned bits = (byte(i) << 16) | (byte(i + 1) << 8) | byte(i + 2);
        for (const int shift : {18, 12, 6, 0}) out += kAlphabet[(bits >> shift) & 63];
    }
    if (const std::size_t tail = bytes.size() - i; tail > 0) {
        const unsigned bits = (byte(i) << 16) | (tail == 2 ? byte(i + 1) << 8 : 0u);
        out += kAlphabet[(bits >> 18) & 63];
        out += kAlphabet[(bits >> 12) & 63];
        out += tail == 2 ? kAlphabet[(bits >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

}  // namespace radiant::proto
