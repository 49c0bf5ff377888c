#include "radiant/server/access_policy.h"

#include <algorithm>
#include <cctype>
#include <string_view>

namespace radiant::server {
namespace {

/// How long a browser may cache a preflight answer: an hour of fewer OPTIONS round trips.
constexpr const char* kPreflightMaxAgeSeconds = "3600";

std::string lower(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

/// The name in a Host header: "[::1]:8080" → "::1", "Example.com:80" → "example.com".
std::string host_name(std::string_view host) {
    if (host.starts_with('[')) return lower(host.substr(1, host.find(']') - 1));
    const std::size_t colon = host.rfind(':');
    // One colon is a port; more would be a bare IPv6 address, which Host does not allow anyway.
    if (colon != std::string_view::npos && host.find(':') == colon) host = host.substr(0, colon);
    return lower(host);
}

/// A browser tricked by DNS rebinding sends the attacker's name as Host: only names this
/// service is known by get through. A request without Host comes from no browser.
bool host_allowed(const AccessPolicy& policy, const std::string& listen_host,
                  std::string_view header) {
    if (header.empty()) return true;
    const std::string name = host_name(header);
    const bool wildcard_listen = listen_host == "0.0.0.0" || listen_host == "::";
    if (name == "localhost" || name == "127.0.0.1" || name == "::1" ||
        (!wildcard_listen && name == lower(listen_host))) {
        return true;
    }
    return std::any_of(policy.allowed_hosts.begin(), policy.allowed_hosts.end(),
                       [&](const std::string& h) { return h == "*" || lower(h) == name; });
}

bool same_origin(std::string_view origin, std::string_view host) {
    const std::string o = lower(origin), h = lower(host);
    return o == "http://" + h || o == "https://" + h;
}

bool listed_origin(const AccessPolicy& policy, std::string_view origin) {
    return std::any_of(policy.cors_origins.begin(), policy.cors_origins.end(),
                       [&](const std::string& o) { return o == "*" || lower(o) == lower(origin); });
}

/// Browsers send Origin with cross-origin requests and with same-origin POSTs; other clients
/// send none. A foreign origin must be listed.
bool origin_allowed(const AccessPolicy& policy, std::string_view origin, std::string_view host) {
    return origin.empty() || same_origin(origin, host) || listed_origin(policy, origin);
}

std::string_view path_of(std::string_view target) { return target.substr(0, target.find('?')); }

}  // namespace

bool constant_time_equal(std::string_view a, std::string_view b) {
    // Every byte of the longer one is read, and differences are OR-ed, never branched on.
    const std::size_t n = std::max(a.size(), b.size());
    unsigned difference = a.size() == b.size() ? 0u : 1u;
    for (std::size_t i = 0; i < n; ++i) {
        const auto x = static_cast<unsigned char>(i < a.size() ? a[i] : 0);
        const auto y = static_cast<unsigned char>(i < b.size() ? b[i] : 0);
        difference |= static_cast<unsigned>(x ^ y);
    }
    return difference == 0;
}

std::optional<Response> check_access(const AccessPolicy& policy, const std::string& listen_host,
                                     const Request& request) {
    const std::string_view host = to_std(request[http::field::host]);
    if (!host_allowed(policy, listen_host, host)) {
        return error_response(request, http::status::forbidden, "host_not_allowed",
                              "this service does not answer to the host \"" + std::string(host) +
                                  "\"; radiantd --allow-host adds names");
    }
    const std::string_view origin = to_std(request[http::field::origin]);
    if (!origin_allowed(policy, origin, host)) {
        return error_response(request, http::status::forbidden, "origin_not_allowed",
                              "requests from the origin \"" + std::string(origin) +
                                  "\" are not allowed; radiantd --cors-origin adds origins");
    }
    const bool preflight = request.method() == http::verb::options && !origin.empty() &&
                           request.count(http::field::access_control_request_method) > 0;
    if (preflight) {
        Response response = text_response(request, http::status::no_content, "", "text/plain");
        add_cors_headers(policy, request, response);
        response.set(http::field::access_control_allow_methods, "GET, POST, DELETE");
        response.set(http::field::access_control_allow_headers,
                     "Authorization, Content-Type, Idempotency-Key, Last-Event-ID");
        response.set(http::field::access_control_max_age, kPreflightMaxAgeSeconds);
        return response;
    }
    // Probes (a load balancer's, Kubernetes') carry no token.
    const std::string_view path = path_of(to_std(request.target()));
    if (policy.token.empty() || path == "/healthz" || path == "/readyz") return std::nullopt;
    const std::string_view authorization = to_std(request[http::field::authorization]);
    constexpr std::string_view kBearer = "Bearer ";
    const bool bearer = authorization.size() > kBearer.size() &&
                        lower(authorization.substr(0, kBearer.size())) == "bearer ";
    if (!bearer || !constant_time_equal(authorization.substr(kBearer.size()), policy.token)) {
        Response response =
            error_response(request, http::status::unauthorized, "unauthorized",
                           bearer ? "the bearer token is wrong"
                                  : "this service needs an Authorization: Bearer token");
        response.set(http::field::www_authenticate, "Bearer realm=\"radiantd\"");
        add_cors_headers(policy, request, response);
        return response;
    }
    return std::nullopt;
}

void add_cors_headers(const AccessPolicy& policy, const Request& request, Response& response) {
    const std::string_view origin = to_std(request[http::field::origin]);
    if (origin.empty() || !listed_origin(policy, origin)) return;
    response.set(http::field::access_control_allow_origin, std::string(origin));
    response.set(http::field::vary, "Origin");
    response.set(http::field::access_control_expose_headers, "Location, Retry-After");
}

}  // namespace radiant::server
