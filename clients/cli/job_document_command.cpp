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
    auto server = std::make_shared<ServerOptions>();
    cmd->add_option("id", *id, "job id")->required();
    add_server_options(cmd, server);
    cmd->callback([id, server, suffix, &exit_code] {
        const HttpReply reply = http_request(server_of(*server), "GET", "/v1/jobs/" + *id + suffix);
        if (reply.status != 200) {
            exit_code = report_error(*id, reply);
            return;
        }
        // Pretty, like `radiant solve`: the store keeps documents compact.
        const nlohmann::json document = nlohmann::json::parse(reply.body);
        std::cout << document.dump(2) << '\n';
        exit_code = kExitOk;
        // A failed solve's document is printed, but the command did not get a result.
        if (suffix == "/result" && document.value("status", "") == "failed") {
            std::cerr << "radiant: job " << *id << " failed: " << document.value("error", "")
                      << '\n';
            exit_code = kExitFailure;
        }
    });
}

}  // namespace radiant::cli
