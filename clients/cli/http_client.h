// A small synchronous HTTP/1.1 client for radiantd (Beast), used by submit, status, watch and
// result. One connection per request: the CLI makes a handful of calls, so pooling buys nothing.
#pragma once

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace radiant::cli {

struct ServerUrl {
    std::string host;
    std::string port;
    std::string token{};  ///< sent as "Authorization: Bearer" when not empty
};

/// "http://HOST:PORT" with an optional trailing slash (port defaults to 80); nothing otherwise.
std::optional<ServerUrl> parse_server_url(const std::string& url);
/// $RADIANT_SERVER, or http://127.0.0.1:8080.
std::string default_server_url();

struct HttpReply {
    unsigned status = 0;
    std::string body;
};

/// Thrown when the server cannot be reached or the connection breaks.
struct ConnectionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// `method` is "GET", "POST" or "DELETE"; `body` is sent as application/json when non-empty,
/// as radiantd requires for a scene.
HttpReply http_request(const ServerUrl& server, const std::string& method,
                       const std::string& target, const std::string& body = "");

/// GETs a text/event-stream and calls `on_event(event, data)` for each event as it arrives, until
/// the server closes the stream or `on_event` returns false. Returns the HTTP status; a non-200
/// answer's body goes into `error_body`.
unsigned stream_events(const ServerUrl& server, const std::string& target,
                       const std::function<bool(const std::string&, const std::string&)>& on_event,
                       std::string& error_body);

}  // namespace radiant::cli
