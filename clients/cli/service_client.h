// What the service commands (submit, status, watch, result) share: the --server option, turning
// server answers into the CLI's messages and exit codes, and following a job's event stream.
#pragma once

#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "http_client.h"

namespace radiant::cli {

/// The options that say which service to talk to, and how.
struct ServerOptions {
    std::string url;
    std::string token_file;
};

/// Adds --server URL (default $RADIANT_SERVER or http://127.0.0.1:8080) and --token-file FILE
/// (default $RADIANT_TOKEN_FILE); the values land in `*options`.
void add_server_options(CLI::App* cmd, const std::shared_ptr<ServerOptions>& options);

/// The server of `options`, with the token of its token file, else $RADIANT_TOKEN. Throws
/// CLI::ValidationError for a URL other than http://HOST[:PORT] or an unreadable token file.
ServerUrl server_of(const ServerOptions& options);

/// Prints a service error body ({"error": {...}}) on stderr, prefixed with `what`, and returns
/// the exit code for the HTTP status: 2 for a refusal of the input (4xx), 1 otherwise.
int report_error(const std::string& what, const HttpReply& reply);

/// Follows /v1/jobs/{id}/events until `done`, drawing a progress bar on stderr when it is a
/// terminal. Returns the final status ("done", "failed", "cancelled"), or "" when the job is
/// unknown or the stream broke.
std::string watch_job(const ServerUrl& server, const std::string& id);

}  // namespace radiant::cli
