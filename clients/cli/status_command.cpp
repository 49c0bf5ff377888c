#include "status_command.h"

#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "exit_codes.h"
#include "service_client.h"

namespace radiant::cli {

void add_status_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("status", "Print a radiantd job's state as JSON");
    auto id = std::make_shared<std::string>();
    auto url = std::make_shared<std::string>();
    cmd->add_option("id", *id, "job id")->required();
    add_server_option(cmd, url);
    cmd->callback([id, url, &exit_code] {
        const HttpReply reply = http_request(server_of(*url), "GET", "/v1/jobs/" + *id);
        if (reply.status != 200) {
            exit_code = report_error(*id, reply);
            return;
        }
        std::cout << nlohmann::json::parse(reply.body).dump(2) << '\n';
        exit_code = kExitOk;
    });
}

}  // namespace radiant::cli
