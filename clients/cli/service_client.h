// What the service commands (submit, status, watch, result) share: the --server option, turning
// server answers into the CLI's messages and exit codes, and following a job's event stream.
#pragma once

#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "http_client.h"

namespace radiant::cli {

/// Adds --server URL (default $RADIANT_SERVER or http://127.0.0.1:8080); the value lands in
/// `*url`.
void add_server_option(CLI::App* cmd, const std::shared_ptr<std::string>& url);

/// The server of `url`; throws CLI::ValidationError for anything but http://HOST[:PORT].
ServerUrl server_of(const std::string& url);

/// Prints a service error body ({"error": {...}}) on stderr, prefixed with `what`, and returns
/// the exit code for the HTTP status: 2 for a refusal of the input (4xx), 1 otherwise.
int report_error(const std::string& what, const HttpReply& reply);

/// Follows /v1/jobs/{id}/events until `done`, drawing a progress bar on stderr when it is a
/// terminal. Returns the final status ("done", "failed", "cancelled"), or "" when the job is
/// unknown or the stream broke.
std::string watch_job(const ServerUrl& server, const std::string& id);

}  // namespace radiant::cli
