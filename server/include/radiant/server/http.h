// HTTP message types shared by the router, handlers and sessions, and the JSON error shape.
#pragma once

#include <cstddef>
#include <optional>
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

/// "application/json", with parameters ("; charset=utf-8") and in any case: what a POST body
/// must be sent as (a web page may send text/plain across origins without asking first).
bool is_json_media_type(std::string_view value);

/// The refusal of a JSON body (`what`: "a scene") too large for `max_body_bytes` (413) or not
/// sent as application/json (415); none when it may be read.
std::optional<Response> refuse_json_body(const Request& request, std::size_t max_body_bytes,
                                         const std::string& what);

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
