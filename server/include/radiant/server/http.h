// HTTP message types shared by the router, handlers and sessions, and the JSON error shape.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <boost/beast/http.hpp>
#include <nlohmann/json.hpp>

#include "radiant/scene.h"

namespace radiant::server {

namespace http = boost::beast::http;
using Request = http::request<http::string_body>;
using Response = http::response<http::string_body>;

/// Beast 1.74 uses boost::string_view; the rest of Radiant uses std::string_view.
inline std::string_view to_std(boost::beast::string_view text) {
    return {text.data(), text.size()};
}

/// `%XX` escapes decoded (malformed ones kept as they are); `+` is a space only in a query.
std::string percent_decode(std::string_view text, bool plus_is_space);

/// `body` as application/json with the request's HTTP version and keep-alive.
Response json_response(const Request& request, http::status status, const nlohmann::json& body);
Response text_response(const Request& request, http::status status, std::string body,
                       const char* content_type);

/// {"error": {"code", "message", "pointer"}}; `problems`, when given, are all listed in
/// "problems" and the first one fills message and pointer (as `radiant validate` prints them).
Response error_response(const Request& request, http::status status, const std::string& code,
                        const std::string& message, const std::string& pointer = "",
                        const std::vector<Problem>& problems = {});

}  // namespace radiant::server
