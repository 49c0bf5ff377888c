// Starts build/bin/radiantd on an ephemeral loopback port for end-to-end tests, and a minimal
// synchronous HTTP client to talk to it.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

namespace radiant::test {

class Daemon {
public:
    /// Runs radiantd --listen 127.0.0.1:0 --data `data` `args`; returns once it printed its port.
    /// `max_open_files` > 0 lowers its RLIMIT_NOFILE.
    Daemon(const std::filesystem::path& data, const std::vector<std::string>& args,
           const std::filesystem::path& log, rlim_t max_open_files = 0) {
        int fds[2];
        if (pipe(fds) != 0) throw std::runtime_error("pipe");
        pid_ = fork();
        if (pid_ == 0) {
            dup2(fds[1], STDOUT_FILENO);
            const int log_fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
            dup2(log_fd, STDERR_FILENO);
            close(fds[0]);
            if (max_open_files > 0) {
                const rlimit limit{max_open_files, max_open_files};
                if (setrlimit(RLIMIT_NOFILE, &limit) != 0) _exit(126);
            }
            std::vector<std::string> all = {std::string(RADIANT_BIN_DIR) + "/radiantd", "--listen",
                                            "127.0.0.1:0", "--data", data.string()};
            all.insert(all.end(), args.begin(), args.end());
            std::vector<char*> argv;
            for (std::string& a : all) argv.push_back(a.data());
            argv.push_back(nullptr);
            execv(argv[0], argv.data());
            _exit(127);
        }
        close(fds[1]);
        out_ = fds[0];
        std::string line;
        pollfd p{out_, POLLIN, 0};
        while (line.find('\n') == std::string::npos && poll(&p, 1, 10000) == 1) {
            char c[256];
            const ssize_t n = read(out_, c, sizeof c);
            if (n <= 0) break;
            line.append(c, static_cast<std::size_t>(n));
        }
        const std::string prefix = "listening on 127.0.0.1:";
        if (line.rfind(prefix, 0) != 0) {
            // It stopped before listening (or never said so): reap it, with how it ended.
            kill(pid_, SIGKILL);
            int status = 0;
            waitpid(pid_, &status, 0);
            close(out_);
            throw std::runtime_error("radiantd said: " + line +
                                     (WIFEXITED(status)
                                          ? "; exit code " + std::to_string(WEXITSTATUS(status))
                                          : std::string("; killed")));
        }
        port_ = static_cast<unsigned short>(std::stoi(line.substr(prefix.size())));
    }
    ~Daemon() {
        if (pid_ > 0) {
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
        if (out_ >= 0) close(out_);
    }
    Daemon(const Daemon&) = delete;
    Daemon& operator=(const Daemon&) = delete;

    unsigned short port() const { return port_; }
    pid_t pid() const { return pid_; }

    /// Sends `signal` and returns the exit status (-1 when killed by a signal).
    int stop(int signal) {
        kill(pid_, signal);
        int status = 0;
        waitpid(pid_, &status, 0);
        pid_ = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

private:
    pid_t pid_ = -1;
    int out_ = -1;
    unsigned short port_ = 0;
};

struct Reply {
    unsigned status = 0;
    std::string body;
    std::map<std::string, std::string> headers;
};

/// One request on a fresh connection; reads the whole answer (event streams until they close).
/// A body goes as application/json unless `headers` name another Content-Type.
inline Reply http_call(unsigned short port, boost::beast::http::verb method,
                       const std::string& target, const std::string& body = "",
                       const std::map<std::string, std::string>& headers = {}) {
    namespace beast = boost::beast;
    namespace http = beast::http;
    boost::asio::io_context ioc;
    boost::asio::ip::tcp::socket socket(ioc);
    socket.connect({boost::asio::ip::make_address("127.0.0.1"), port});
    http::request<http::string_body> request{method, target, 11};
    request.set(http::field::host, "127.0.0.1");
    // As every client sends a scene; a test of other types says so in `headers`.
    if (!body.empty()) request.set(http::field::content_type, "application/json");
    for (const auto& [name, value] : headers) request.set(name, value);
    request.body() = body;
    request.prepare_payload();
    http::write(socket, request);
    beast::flat_buffer buffer;
    http::response_parser<http::string_body> parser;
    parser.body_limit(1u << 30);
    http::read(socket, buffer, parser);
    Reply reply;
    reply.status = parser.get().result_int();
    reply.body = parser.get().body();
    for (const auto& field : parser.get()) {
        reply.headers[std::string(field.name_string())] = std::string(field.value());
    }
    return reply;
}

}  // namespace radiant::test
