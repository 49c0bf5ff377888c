#include "submit_command.h"

#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "exit_codes.h"
#include "service_client.h"

namespace radiant::cli {
namespace {

struct SubmitArgs {
    std::string scene;
    bool wait = false;
    std::string idempotency_key;
};

int run_submit(const SubmitArgs& args, const ServerUrl& server) {
    std::ifstream in(args.scene, std::ios::binary);
    if (!in) {
        std::cerr << args.scene << ": cannot read the file\n";
        return kExitBadInput;
    }
    std::ostringstream text;
    text << in.rdbuf();
    const HttpReply posted = http_request(server, "POST", "/v1/jobs", text.str());
    if (posted.status != 202) return report_error(args.scene, posted);
    const std::string id = nlohmann::json::parse(posted.body).at("id");
    if (!args.wait) {
        std::cout << id << '\n';
        return kExitOk;
    }
    std::cerr << "job " << id << '\n';
    const std::string status = watch_job(server, id);
    const HttpReply result = http_request(server, "GET", "/v1/jobs/" + id + "/result");
    if (result.status != 200) return report_error(id, result);
    std::cout << nlohmann::json::parse(result.body).dump(2) << '\n';
    return status == "done" ? kExitOk : kExitFailure;
}

}  // namespace

void add_submit_command(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("submit", "Submit a scene to radiantd; print the job id");
    auto args = std::make_shared<SubmitArgs>();
    auto url = std::make_shared<std::string>();
    cmd->add_option("scene", args->scene, "radiant-scene/1 JSON file")->required();
    cmd->add_flag("--wait", args->wait, "follow the job and print its result when it finishes");
    add_server_option(cmd, url);
    cmd->callback([args, url, &exit_code] { exit_code = run_submit(*args, server_of(*url)); });
}

}  // namespace radiant::cli
