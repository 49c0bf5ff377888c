#include "radiant/server/http.h"

#include <utility>

namespace radiant::server {

Response text_response(const Request& request, http::status status, std::string body,
                       const char* content_type) {
    Response response{status, request.version()};
    response.set(http::field::server, "radiantd");
    response.set(http::field::content_type, content_type);
    response.keep_alive(request.keep_alive());
    response.body() = std::move(body);
    response.prepare_payload();
    return response;
}

Response json_response(const Request& request, http::status status, const nlohmann::json& body) {
    // A message may quote request bytes (a path, a job id) that are not UTF-8: replace them
    // rather than throw, so the answer stays the 4xx it should be.
    return text_response(request, status,
                         body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n",
                         "application/json");
}

Response error_response(const Request& request, http::status status, const std::string& code,
                        const std::string& message, const std::string& pointer,
                        const std::vector<Problem>& problems) {
    nlohmann::json error = {{"code", code}, {"message", message}, {"pointer", pointer}};
    if (!problems.empty()) {
        error["message"] = problems.front().message;
        error["pointer"] = problems.front().pointer;
        nlohmann::json list = nlohmann::json::array();
        for (const Problem& p : problems) {
            list.push_back({{"pointer", p.pointer}, {"message", p.message}});
        }
        error["problems"] = std::move(list);
    }
    return json_response(request, status, {{"error", std::move(error)}});
}

}  // namespace radiant::server
