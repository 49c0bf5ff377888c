#include "job_document_command.h"

#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "exit_codes.h"
#include "service_client.h"

namespace radiant::cli {

void add_job_document_command(CLI::App& app, int& exit_code, const std::string& name,
                              const std::string& description, const std::string& suffix) {
    auto* cmd = app.add_subcommand(name, description);
    auto id = std::make_shared<std::string>();
    auto url = std::make_shared<std::string>();
    cmd->add_option("id", *id, "job id")->required();
    add_server_option(cmd, url);
    cmd->callback([id, url, suffix, &exit_code] {
        const HttpReply reply = http_request(server_of(*url), "GET", "/v1/jobs/" + *id + suffix);
        if (reply.status != 200) {
            exit_code = report_error(*id, reply);
            return;
        }
        // Pretty, like `radiant solve`: the store keeps documents compact.
        std::cout << nlohmann::json::parse(reply.body).dump(2) << '\n';
        exit_code = kExitOk;
    });
}

}  // namespace radiant::cli
