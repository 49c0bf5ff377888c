#include "watch_command.h"

#include <iostream>
#include <memory>
#include <string>

#include "exit_codes.h"
#include "service_client.h"

namespace radiant::cli {

void add_watch_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("watch", "Follow a radiantd job's progress until it finishes");
    auto id = std::make_shared<std::string>();
    auto server = std::make_shared<ServerOptions>();
    cmd->add_option("id", *id, "job id")->required();
    add_server_options(cmd, server);
    cmd->callback([id, server, &exit_code] {
        const std::string status = watch_job(server_of(*server), *id);
        if (status.empty()) {
            exit_code = kExitBadInput;
            return;
        }
        std::cout << *id << ": " << status << '\n';
        exit_code = status == "done" ? kExitOk : kExitFailure;
    });
}

}  // namespace radiant::cli
