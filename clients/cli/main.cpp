// radiant: solve or validate radiant-scene/1 files locally, or submit them to radiantd and follow
// the jobs (contract §1, §4).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "atomic_file.h"
#include "exit_codes.h"
#include "http_client.h"
#include "import_command.h"
#include "job_document_command.h"
#include "plan_command.h"
#include "render_command.h"
#include "solve_command.h"
#include "submit_command.h"
#include "validate_command.h"
#include "watch_command.h"

int main(int argc, char** argv) {
    int exit_code = radiant::cli::kExitOk;
    try {
        CLI::App app("Radiant radiosity lighting simulation", "radiant");
        app.require_subcommand(1);
        radiant::cli::add_solve_command(app, exit_code);
        radiant::cli::add_validate_command(app, exit_code);
        radiant::cli::add_import_command(app, exit_code);
        radiant::cli::add_render_command(app, exit_code);
        radiant::cli::add_plan_command(app, exit_code);
        radiant::cli::add_submit_command(app, exit_code);
        radiant::cli::add_job_document_command(app, exit_code, "status",
                                               "Print a radiantd job's state as JSON", "");
        radiant::cli::add_watch_command(app, exit_code);
        radiant::cli::add_job_document_command(app, exit_code, "result",
                                               "Print a radiantd job's radiant-result/1 document",
                                               "/result");
        try {
            app.parse(argc, argv);
        } catch (const CLI::ParseError& e) {
            // Usage errors are bad input (2); --help is a success.
            return app.exit(e) == 0 ? radiant::cli::kExitOk : radiant::cli::kExitBadInput;
        }
    } catch (const radiant::cli::OutputRefused& e) {
        std::cerr << "radiant: " << e.what() << '\n';
        return radiant::cli::kExitBadInput;
    } catch (const radiant::cli::ConnectionError& e) {
        std::cerr << "radiant: " << e.what() << '\n';
        return radiant::cli::kExitFailure;
    } catch (const std::exception& e) {
        std::cerr << "radiant: " << e.what() << '\n';
        return radiant::cli::kExitFailure;
    } catch (...) {
        std::cerr << "radiant: unknown internal error\n";
        return radiant::cli::kExitFailure;
    }
    // Output that did not arrive (a full disk, a closed pipe) is a failure, not a success.
    std::cout.flush();
    if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::cerr << "radiant: cannot write the output to stdout: " << std::strerror(errno) << '\n';
        return radiant::cli::kExitFailure;
    }
    return exit_code;
}
