#include "radiant/server/http.h"

#include <utility>

namespace radiant::server {
namespace {

int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

std::string percent_decode(std::string_view text, bool plus_is_space) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '+' && plus_is_space) {
            out += ' ';
        } else if (text[i] == '%' && i + 2 < text.size() && hex_value(text[i + 1]) >= 0 &&
                   hex_value(text[i + 2]) >= 0) {
            out += static_cast<char>(hex_value(text[i + 1]) * 16 + hex_value(text[i + 2]));
            i += 2;
        } else {
            out += text[i];
        }
    }
    return out;
}

Response text_response(const Request& request, http::status status, std::string body,
                       const char* content_type) {
    Response response{status, request.version()};
    response.set(http::field::server, "radiantd");
    response.set(http::field::content_type, content_type);
    response.keep_alive(request.keep_alive());
    response.body() = std::move(body);
    response.prepare_payload();
    return response;
}

Response json_response(const Request& request, http::status status, const nlohmann::json& body) {
    // A message may quote request bytes (a path, a job id) that are not UTF-8: replace them
    // rather than throw, so the answer stays the 4xx it should be.
    return text_response(request, status,
                         body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n",
                         "application/json");
}

Response error_response(const Request& request, http::status status, const std::string& code,
                        const std::string& message, const std::string& pointer,
                        const std::vector<Problem>& problems) {
    nlohmann::json error = {{"code", code}, {"message", message}, {"pointer", pointer}};
    if (!problems.empty()) {
        error["message"] = problems.front().message;
        error["pointer"] = problems.front().pointer;
        nlohmann::json list = nlohmann::json::array();
        for (const Problem& p : problems) {
            list.push_back({{"pointer", p.pointer}, {"message", p.message}});
        }
        error["problems"] = std::move(list);
    }
    return json_response(request, status, {{"error", std::move(error)}});
}

}  // namespace radiant::server
