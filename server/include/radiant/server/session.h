// One HTTP/1.1 connection: read a request (with hard limits), route it, write the answer; or,
// for an event stream, poll the job and push events until it finishes.
#pragma once

#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include "radiant/server/event_stream.h"
#include "radiant/server/router.h"

namespace radiant::server {

struct SessionLimits {
    /// Real clients send a few hundred bytes of headers; 16 KiB refuses abuse early.
    std::size_t header_bytes = 16 * 1024;
    std::size_t body_bytes = 64u << 20;  ///< larger bodies get 413 before they are read
    /// An idle or trickling client frees its connection after this.
    std::chrono::seconds read_timeout{30};
    /// Requests are answered one at a time per connection, so pipelined requests wait in this
    /// read buffer; bounding it bounds what one connection can queue.
    std::size_t read_buffer_bytes = 64 * 1024;
    /// Polling period of event streams: at most this many events per second reach a client.
    std::chrono::milliseconds event_poll{100};
    /// A comment is sent on an idle event stream this often so proxies keep it open.
    std::chrono::seconds keep_alive{15};
};

class Session : public std::enable_shared_from_this<Session> {
public:
    Session(boost::asio::ip::tcp::socket&& socket, Router& router, const SessionLimits& limits);
    void run();

private:
    void do_read();
    void on_header(boost::beast::error_code ec);
    void on_read(boost::beast::error_code ec);
    /// Sends what route() answered: a response, an event stream, or deferred work.
    void deliver(RouteResult routed, const Request& request);
    /// Runs `work` on the context's BlockingPool (503 when it is full) and sends its answer.
    void run_deferred(DeferredResponse work, const Request& request);
    void refuse(http::status status, const std::string& code, const std::string& message);
    void send(Response response);
    void on_write(bool close, boost::beast::error_code ec);
    void close();

    void start_events(Response header, const EventStreamStart& start);
    void poll_events();
    void on_event_written(boost::beast::error_code ec);

    void log(unsigned status);

    boost::beast::tcp_stream stream_;
    boost::beast::flat_buffer buffer_;
    Router& router_;
    const SessionLimits limits_;
    std::optional<http::request_parser<http::string_body>> parser_;
    std::string method_, target_;
    std::chrono::steady_clock::time_point started_;
    std::shared_ptr<void> in_flight_;  ///< keeps the message being written alive

    std::optional<EventStream> events_;
    std::string event_job_;
    std::optional<std::uint64_t> event_token_;  ///< JobQueue::change_token at the last read
    std::string event_text_;
    boost::asio::steady_timer timer_;
    std::chrono::steady_clock::time_point last_event_write_;
};

}  // namespace radiant::server
