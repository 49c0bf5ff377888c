#include "radiant/server/config.h"

#include <charconv>
#include <fstream>
#include <stdexcept>

namespace radiant::server {

std::filesystem::path default_web_root(const std::filesystem::path& executable) {
    return (executable.parent_path() / ".." / "share" / "radiant" / "web").lexically_normal();
}

std::optional<ListenAddress> parse_listen(const std::string& text) {
    const std::size_t colon = text.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == text.size()) return std::nullopt;
    ListenAddress out;
    out.host = text.substr(0, colon);
    if (out.host.size() >= 2 && out.host.front() == '[' && out.host.back() == ']') {
        out.host = out.host.substr(1, out.host.size() - 2);
    }
    const char* first = text.data() + colon + 1;
    const char* last = text.data() + text.size();
    unsigned port = 0;
    const auto [end, ec] = std::from_chars(first, last, port);
    if (ec != std::errc{} || end != last || port > 65535) return std::nullopt;
    out.port = static_cast<std::uint16_t>(port);
    return out;
}

std::string read_token_file(const std::string& path) {
    std::ifstream in(path);
    std::string token;
    if (!in || !std::getline(in, token))
        throw std::runtime_error("cannot read the token file " + path);
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (!token.empty() && space(token.back())) token.pop_back();
    while (!token.empty() && space(token.front())) token.erase(token.begin());
    if (token.empty()) throw std::runtime_error("the token file " + path + " holds no token");
    return token;
}

}  // namespace radiant::server
