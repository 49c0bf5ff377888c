#include "service_client.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "exit_codes.h"

namespace radiant::cli {

void add_server_option(CLI::App* cmd, const std::shared_ptr<std::string>& url) {
    *url = default_server_url();
    cmd->add_option("--server", *url,
                    "radiantd base URL (default $RADIANT_SERVER or " + *url + ")");
}

ServerUrl server_of(const std::string& url) {
    const auto server = parse_server_url(url);
    if (!server) throw CLI::ValidationError("--server", "expected http://HOST[:PORT], got " + url);
    return *server;
}

int report_error(const std::string& what, const HttpReply& reply) {
    const auto body = nlohmann::json::parse(reply.body, nullptr, false);
    const auto error =
        body.is_object() ? body.value("error", nlohmann::json::object()) : nlohmann::json::object();
    if (error.contains("problems")) {
        for (const auto& p : error["problems"]) {
            std::cerr << what << ": " << p.value("pointer", "") << ": " << p.value("message", "")
                      << '\n';
        }
    } else {
        std::cerr << what << ": HTTP " << reply.status << ": "
                  << (error.contains("message") ? error["message"].get<std::string>() : reply.body)
                  << '\n';
    }
    return reply.status >= 400 && reply.status < 500 && reply.status != 429 ? kExitBadInput
                                                                            : kExitFailure;
}

std::string watch_job(const ServerUrl& server, const std::string& id) {
    const bool tty = ::isatty(STDERR_FILENO);
    bool drawn = false;
    std::string final_status;
    std::string error_body;
    const unsigned status = stream_events(
        server, "/v1/jobs/" + id + "/events",
        [&](const std::string& event, const std::string& data) {
            const auto json = nlohmann::json::parse(data, nullptr, false);
            if (!json.is_object()) return true;
            if (event == "done") {
                final_status = json.value("status", "");
                if (json.contains("error")) std::cerr << id << ": " << json["error"] << '\n';
                return false;
            }
            if (event == "progress" && tty) {
                constexpr int kWidth = 30;
                const double fraction = json.value("fraction", 0.0);
                const int filled = static_cast<int>(fraction * kWidth + 0.5);
                std::fprintf(stderr, "\r[%s%s] %5.1f%%  %-12s it %-6zu err %.1e  %.1fs ",
                             std::string(static_cast<std::size_t>(filled), '#').c_str(),
                             std::string(static_cast<std::size_t>(kWidth - filled), '-').c_str(),
                             100 * fraction, json.value("stage", "").c_str(),
                             json.value("iterations", std::size_t{0}),
                             json.value("error_estimate", 0.0), json.value("elapsed_seconds", 0.0));
                std::fflush(stderr);
                drawn = true;
            }
            return true;
        },
        error_body);
    if (drawn) std::fputc('\n', stderr);
    if (status != 200) report_error(id, {status, error_body});
    return final_status;
}

}  // namespace radiant::cli
