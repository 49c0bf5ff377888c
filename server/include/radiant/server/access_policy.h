// Who may call the API: an optional bearer token, the Host names the service answers to (against
// DNS rebinding), and the browser origins allowed cross-origin access. docs/security.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "radiant/server/http.h"

namespace radiant::server {

struct AccessPolicy {
    /// When not empty, every route but /healthz needs "Authorization: Bearer <token>".
    std::string token;
    /// Host names answered besides localhost, 127.0.0.1, ::1 and the listen address; "*": any.
    std::vector<std::string> allowed_hosts;
    /// Origins ("https://app.example.com") that browsers may call from; the page's own origin
    /// (the same host and port) always may.
    std::vector<std::string> cors_origins;
};

/// The refusal of a request the policy does not let through (403 for its Host or Origin, 401
/// without the token), or the answer to a CORS preflight; nothing when it goes on to routing.
/// `listen_host` is the address the service listens on.
std::optional<Response> check_access(const AccessPolicy& policy, const std::string& listen_host,
                                     const Request& request);

/// Adds the CORS headers to `response` when `request` comes from an allowed foreign origin.
void add_cors_headers(const AccessPolicy& policy, const Request& request, Response& response);

/// Whether `a` equals `b`, in a time that does not depend on where they differ.
bool constant_time_equal(std::string_view a, std::string_view b);

}  // namespace radiant::server
