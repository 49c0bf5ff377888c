#include "submit_command.h"

#include <array>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "exit_codes.h"
#include "radiant/proto/scene_json.h"
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
    // Read at most one byte over the service's limit, so that /dev/zero or a growing file
    // costs no more than the largest scene the service would take.
    const std::size_t limit = proto::ParseLimits{}.max_bytes;
    std::string text;
    std::array<char, 1 << 16> chunk;
    while (text.size() <= limit && (in.read(chunk.data(), chunk.size()) || in.gcount() > 0)) {
        text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    }
    if (in.bad()) {
        std::cerr << args.scene << ": read error\n";
        return kExitBadInput;
    }
    if (text.size() > limit) {
        std::cerr << args.scene << ": : the scene is over the limit of " << limit << " bytes\n";
        return kExitBadInput;
    }
    const HttpReply posted = http_request(server, "POST", "/v1/jobs", text);
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
    auto server = std::make_shared<ServerOptions>();
    cmd->add_option("scene", args->scene, "radiant-scene/1 JSON file")->required();
    cmd->add_flag("--wait", args->wait, "follow the job and print its result when it finishes");
    add_server_options(cmd, server);
    cmd->callback(
        [args, server, &exit_code] { exit_code = run_submit(*args, server_of(*server)); });
}

}  // namespace radiant::cli
