#include "service_client.h"

#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "exit_codes.h"
#include "progress_text.h"

namespace radiant::cli {

void add_server_options(CLI::App* cmd, const std::shared_ptr<ServerOptions>& options) {
    options->url = default_server_url();
    cmd->add_option("--server", options->url,
                    "radiantd base URL (default $RADIANT_SERVER or " + options->url + ")");
    cmd->add_option("--token-file", options->token_file,
                    "file holding the service's bearer token (default $RADIANT_TOKEN_FILE; the "
                    "token itself may be in $RADIANT_TOKEN)")
        ->envname("RADIANT_TOKEN_FILE");
}

ServerUrl server_of(const ServerOptions& options) {
    auto server = parse_server_url(options.url);
    if (!server) {
        throw CLI::ValidationError("--server", "expected http://HOST[:PORT], got " + options.url);
    }
    if (!options.token_file.empty()) {
        std::ifstream in(options.token_file);
        if (!in || !std::getline(in, server->token)) {
            throw CLI::ValidationError("--token-file", "cannot read " + options.token_file);
        }
        // The first line, as radiantd reads it; a trailing newline or CR is no part of it.
        while (!server->token.empty() &&
               std::isspace(static_cast<unsigned char>(server->token.back())))
            server->token.pop_back();
    } else if (const char* token = std::getenv("RADIANT_TOKEN")) {
        server->token = token;
    }
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
                std::fprintf(stderr, "\r%s", service_progress_line(json).c_str());
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
