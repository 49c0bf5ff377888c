// The error answers about a job that several handlers give.
#pragma once

#include <string>

#include "radiant/server/http.h"

namespace radiant::server {

inline Response unknown_job(const Request& request, const std::string& id) {
    return error_response(request, http::status::not_found, "not_found",
                          "no job with id \"" + id + "\"");
}

inline Response not_ready(const Request& request, const std::string& id) {
    return error_response(request, http::status::not_found, "not_ready",
                          "job " + id + " is queued; it has no result yet");
}

}  // namespace radiant::server
