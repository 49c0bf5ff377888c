#include "radiant/server/router.h"

#include "job_errors.h"

#include <spdlog/spdlog.h>

#include <charconv>
#include <exception>
#include <string_view>
#include <vector>

namespace radiant::server {
namespace {

std::vector<std::string_view> split_path(std::string_view path) {
    std::vector<std::string_view> parts;
    while (!path.empty()) {
        if (path.front() == '/') {
            path.remove_prefix(1);
            continue;
        }
        const std::size_t slash = path.find('/');
        parts.push_back(path.substr(0, slash));
        if (slash == std::string_view::npos) break;
        path.remove_prefix(slash);
    }
    return parts;
}

Response method_not_allowed(const Request& request, const char* allow) {
    Response response =
        error_response(request, http::status::method_not_allowed, "method_not_allowed",
                       std::string(request.method_string()) + " is not allowed");
    response.set(http::field::allow, allow);
    return response;
}

/// Catch at the boundary: a broken request or store is one 500, not a dead daemon.
Response internal_error(const Request& request, const std::exception& e) {
    spdlog::error("{} {}: {}", std::string(request.method_string()), std::string(request.target()),
                  e.what());
    return error_response(request, http::status::internal_server_error, "internal",
                          "internal error; see the server log");
}

}  // namespace

Query parse_query(std::string_view query) {
    Query out;
    while (!query.empty()) {
        const std::size_t amp = query.find('&');
        const std::string_view pair = query.substr(0, amp);
        const std::size_t eq = pair.find('=');
        if (!pair.empty()) {
            out[percent_decode(pair.substr(0, eq), true)] =
                eq == std::string_view::npos ? std::string()
                                             : percent_decode(pair.substr(eq + 1), true);
        }
        if (amp == std::string_view::npos) break;
        query.remove_prefix(amp + 1);
    }
    return out;
}

bool Router::parses_scene(const Request& request) {
    const std::string_view path = to_std(request.target()).substr(0, request.target().find('?'));
    return request.method() == http::verb::post || path.ends_with("/result.glb");
}

RouteResult Router::route(const Request& request) {
    try {
        if (auto refused = check_access(ctx_.access, ctx_.listen_host, request)) {
            return {std::move(*refused), std::nullopt};
        }
        RouteResult routed = dispatch(request);
        add_cors_headers(ctx_.access, request, routed.response);
        if (routed.deferred) {
            // Deferred work runs later, on another thread: it gets the same boundary and headers.
            routed.deferred = [work = std::move(routed.deferred), request,
                               &access = ctx_.access]() -> Response {
                Response response;
                try {
                    response = work();
                } catch (const std::exception& e) {
                    response = internal_error(request, e);
                }
                add_cors_headers(access, request, response);
                return response;
            };
        }
        return routed;
    } catch (const std::exception& e) {
        return {internal_error(request, e), std::nullopt};
    }
}

RouteResult Router::dispatch(const Request& request) {
    const std::string_view target = to_std(request.target());
    const std::size_t question = target.find('?');
    const std::string_view path = target.substr(0, question);
    const Query query =
        question == std::string_view::npos ? Query{} : parse_query(target.substr(question + 1));
    const std::vector<std::string_view> parts = split_path(path);
    const http::verb method = request.method();
    const bool get = method == http::verb::get;

    if (parts.size() == 1 && parts[0] == "healthz") {
        if (!get) return {method_not_allowed(request, "GET"), std::nullopt};
        return {handlers::healthz(ctx_, request), std::nullopt};
    }
    if (parts.size() == 1 && parts[0] == "readyz") {
        if (!get) return {method_not_allowed(request, "GET"), std::nullopt};
        return {handlers::readyz(ctx_, request), std::nullopt};
    }
    if (parts.size() == 1 && parts[0] == "metrics") {
        if (!get) return {method_not_allowed(request, "GET"), std::nullopt};
        return {handlers::metrics(ctx_, request), std::nullopt};
    }
    if (parts.empty() || parts[0] != "v1") {
        // Everything outside the API is the web viewer's.
        if (!get && method != http::verb::head) {
            return {method_not_allowed(request, "GET, HEAD"), std::nullopt};
        }
        return {web_.serve(request, path), std::nullopt};
    }
    if (parts.size() == 2 && parts[1] == "openapi.yaml") {
        if (!get) return {method_not_allowed(request, "GET"), std::nullopt};
        return {handlers::openapi(request), std::nullopt};
    }
    if (parts.size() < 2 || parts[1] != "jobs") {
        return {handlers::not_found(request), std::nullopt};
    }
    if (parts.size() == 2) {
        if (method == http::verb::post) return {handlers::submit_job(ctx_, request), std::nullopt};
        if (get) return {handlers::list_jobs(ctx_, request, query), std::nullopt};
        return {method_not_allowed(request, "GET, POST"), std::nullopt};
    }
    const std::string id(parts[2]);
    if (!is_job_id(id)) return {unknown_job(request, id), std::nullopt};
    if (parts.size() == 3) {
        if (get) return {handlers::get_job(ctx_, request, id), std::nullopt};
        if (method == http::verb::delete_) {
            return {handlers::cancel_job(ctx_, request, id), std::nullopt};
        }
        return {method_not_allowed(request, "GET, DELETE"), std::nullopt};
    }
    if (parts.size() == 4 && parts[3] == "result") {
        if (!get) return {method_not_allowed(request, "GET"), std::nullopt};
        return {handlers::get_result(ctx_, request, id, query), std::nullopt};
    }
    if (parts.size() == 4 && parts[3] == "result.glb") {
        if (!get) return {method_not_allowed(request, "GET"), std::nullopt};
        return {handlers::get_result_glb(ctx_, request, id), std::nullopt};
    }
    if (parts.size() == 4 && parts[3] == "scenes") {
        if (method != http::verb::post) return {method_not_allowed(request, "POST"), std::nullopt};
        return {handlers::post_light_scene(ctx_, request, id), std::nullopt};
    }
    // Files made from the stored result: their work leaves the I/O thread.
    if (parts.size() == 4 &&
        (parts[3] == "sensors.csv" || parts[3] == "plan.png" || parts[3] == "view.png")) {
        if (!get) return {method_not_allowed(request, "GET"), std::nullopt};
        RouteResult routed{Response{}, std::nullopt};
        if (parts[3] == "sensors.csv")
            routed.deferred = handlers::get_sensors_csv(ctx_, request, id);
        if (parts[3] == "plan.png")
            routed.deferred = handlers::get_plan_png(ctx_, request, id, query);
        if (parts[3] == "view.png")
            routed.deferred = handlers::get_view_png(ctx_, request, id, query);
        return routed;
    }
    if (parts.size() == 4 && parts[3] == "events") {
        if (!get) return {method_not_allowed(request, "GET"), std::nullopt};
        if (!ctx_.jobs.find(id)) return {handlers::get_job(ctx_, request, id), std::nullopt};
        std::uint64_t last = 0;
        const std::string_view header = to_std(request["Last-Event-ID"]);
        std::from_chars(header.data(), header.data() + header.size(), last);
        Response response{http::status::ok, request.version()};
        response.set(http::field::server, "radiantd");
        response.set(http::field::content_type, "text/event-stream");
        response.set(http::field::cache_control, "no-cache");
        return {std::move(response), EventStreamStart{id, last}};
    }
    return {handlers::not_found(request), std::nullopt};
}

}  // namespace radiant::server
