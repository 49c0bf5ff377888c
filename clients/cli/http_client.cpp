#include "http_client.h"

#include <cstdlib>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

namespace radiant::cli {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;

namespace {

/// A result document of a fine scene can be large; this only bounds a broken server.
constexpr std::uint64_t kMaxReplyBytes = 1ull << 30;

net::ip::tcp::socket connect(net::io_context& ioc, const ServerUrl& server) {
    try {
        net::ip::tcp::resolver resolver(ioc);
        net::ip::tcp::socket socket(ioc);
        net::connect(socket, resolver.resolve(server.host, server.port));
        return socket;
    } catch (const boost::system::system_error& e) {
        throw ConnectionError("cannot reach http://" + server.host + ":" + server.port + ": " +
                              e.code().message());
    }
}

http::request<http::string_body> make_request(const ServerUrl& server, http::verb method,
                                              const std::string& target, const std::string& body) {
    http::request<http::string_body> request{method, target, 11};
    request.set(http::field::host, server.host + ":" + server.port);
    request.set(http::field::user_agent, "radiant-cli");
    if (!body.empty()) request.set(http::field::content_type, "application/json");
    if (!server.token.empty()) request.set(http::field::authorization, "Bearer " + server.token);
    request.body() = body;
    request.prepare_payload();
    return request;
}

}  // namespace

std::optional<ServerUrl> parse_server_url(const std::string& url) {
    const std::string scheme = "http://";
    if (url.rfind(scheme, 0) != 0) return std::nullopt;
    std::string rest = url.substr(scheme.size());
    if (!rest.empty() && rest.back() == '/') rest.pop_back();
    if (rest.empty() || rest.find('/') != std::string::npos) return std::nullopt;
    const std::size_t colon = rest.rfind(':');
    if (colon == std::string::npos) return ServerUrl{rest, "80"};
    ServerUrl out{rest.substr(0, colon), rest.substr(colon + 1)};
    if (out.host.empty() || out.port.empty() ||
        out.port.find_first_not_of("0123456789") != std::string::npos) {
        return std::nullopt;
    }
    return out;
}

std::string default_server_url() {
    const char* env = std::getenv("RADIANT_SERVER");
    return env && *env ? env : "http://127.0.0.1:8080";
}

HttpReply http_request(const ServerUrl& server, const std::string& method,
                       const std::string& target, const std::string& body) {
    net::io_context ioc;
    net::ip::tcp::socket socket = connect(ioc, server);
    try {
        http::write(socket, make_request(server, http::string_to_verb(method), target, body));
        beast::flat_buffer buffer;
        http::response_parser<http::string_body> parser;
        parser.body_limit(kMaxReplyBytes);
        http::read(socket, buffer, parser);
        return {parser.get().result_int(), parser.get().body()};
    } catch (const boost::system::system_error& e) {
        throw ConnectionError("connection to the server failed: " + e.code().message());
    }
}

unsigned stream_events(const ServerUrl& server, const std::string& target,
                       const std::function<bool(const std::string&, const std::string&)>& on_event,
                       std::string& error_body) {
    net::io_context ioc;
    net::ip::tcp::socket socket = connect(ioc, server);
    try {
        auto request = make_request(server, http::verb::get, target, "");
        request.set(http::field::accept, "text/event-stream");
        http::write(socket, request);
        beast::flat_buffer buffer;
        http::response_parser<http::buffer_body> parser;
        parser.body_limit(boost::none);  // a stream lasts as long as its job
        http::read_header(socket, buffer, parser);
        const unsigned status = parser.get().result_int();

        std::string pending;  // text of the event being received
        char chunk[4096];
        beast::error_code ec;
        while (!parser.is_done()) {
            parser.get().body().data = chunk;
            parser.get().body().size = sizeof chunk;
            // read_some returns after each socket read, so events surface as they arrive.
            http::read_some(socket, buffer, parser, ec);
            if (ec == http::error::need_buffer) ec = {};
            if (ec == http::error::end_of_stream || ec == net::error::eof) break;
            if (ec) throw boost::system::system_error(ec);
            pending.append(chunk, sizeof chunk - parser.get().body().size);
            if (status != 200) continue;
            for (std::size_t end; (end = pending.find("\n\n")) != std::string::npos;) {
                const std::string block = pending.substr(0, end);
                pending.erase(0, end + 2);
                std::string event = "message", data;
                std::size_t start = 0;
                while (start <= block.size()) {
                    std::size_t nl = block.find('\n', start);
                    if (nl == std::string::npos) nl = block.size();
                    const std::string line = block.substr(start, nl - start);
                    start = nl + 1;
                    if (line.rfind("event: ", 0) == 0) event = line.substr(7);
                    if (line.rfind("data: ", 0) == 0) data += line.substr(6);
                }
                if (!data.empty() && !on_event(event, data)) return status;
            }
        }
        if (status != 200) error_body = pending;
        return status;
    } catch (const boost::system::system_error& e) {
        throw ConnectionError("connection to the server failed: " + e.code().message());
    }
}

}  // namespace radiant::cli
