#include "radiant/server/session.h"

#include <spdlog/spdlog.h>

#include <array>
#include <functional>

#include <boost/asio/dispatch.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/thread_pool.hpp>
#include <boost/asio/write.hpp>

namespace radiant::server {

namespace beast = boost::beast;
namespace net = boost::asio;

namespace {

/// How long a refused connection may keep sending before it is closed: reading (and dropping)
/// what is in flight lets the client see the error instead of a connection reset.
constexpr std::chrono::seconds kLingerTime{1};
/// Pictures and CSV files take a fraction of a second each: a busy pool frees up quickly.
constexpr const char* kBusyRetrySeconds = "1";

}  // namespace

Session::Session(net::ip::tcp::socket&& socket, Router& router, const SessionLimits& limits)
    : stream_(std::move(socket)),
      buffer_(limits.read_buffer_bytes),
      router_(router),
      limits_(limits),
      timer_(stream_.get_executor()) {}

void Session::run() {
    net::dispatch(stream_.get_executor(), [self = shared_from_this()] { self->do_read(); });
}

void Session::do_read() {
    parser_.emplace();
    parser_->header_limit(static_cast<std::uint32_t>(limits_.header_bytes));
    parser_->body_limit(limits_.body_bytes);
    method_ = "-";
    target_ = "-";
    stream_.expires_after(limits_.read_timeout);
    http::async_read_header(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_header(ec); });
}

void Session::on_header(beast::error_code ec) {
    started_ = std::chrono::steady_clock::now();
    if (!parser_->get().target().empty()) {  // also for a refused body, so the log names it
        method_ = std::string(parser_->get().method_string());
        target_ = std::string(parser_->get().target());
    }
    if (!ec) {
        const auto& header = parser_->get();
        if (beast::iequals(header[http::field::expect], "100-continue")) {
            // curl asks before sending large bodies; answering saves it a one-second wait.
            auto cont = std::make_shared<http::response<http::empty_body>>(http::status::continue_,
                                                                           header.version());
            in_flight_ = cont;
            http::async_write(
                stream_, *cont, [self = shared_from_this()](beast::error_code wec, std::size_t) {
                    if (wec) return;
                    http::async_read(
                        self->stream_, self->buffer_, *self->parser_,
                        [self](beast::error_code rec, std::size_t) { self->on_read(rec); });
                });
            return;
        }
        http::async_read(stream_, buffer_, *parser_,
                         [self = shared_from_this()](beast::error_code rec, std::size_t) {
                             self->on_read(rec);
                         });
        return;
    }
    on_read(ec);
}

void Session::on_read(beast::error_code ec) {
    if (ec == http::error::end_of_stream || ec == net::error::eof) return close();
    if (ec == http::error::body_limit) {
        return refuse(
            http::status::payload_too_large, "too_large",
            "the request body is larger than " + std::to_string(limits_.body_bytes) + " bytes");
    }
    if (ec == http::error::header_limit) {
        return refuse(http::status::request_header_fields_too_large, "headers_too_large",
                      "the request headers are larger than " +
                          std::to_string(limits_.header_bytes) + " bytes");
    }
    if (ec == beast::error::timeout) return close();  // idle keep-alive connections end here
    if (ec) {
        // Malformed requests get a 400; resets and the like have nobody left to answer.
        if (ec.category() == http::make_error_code(http::error::bad_target).category()) {
            return refuse(http::status::bad_request, "bad_request",
                          "malformed HTTP request: " + ec.message());
        }
        return;
    }
    auto request = std::make_shared<Request>(parser_->release());
    boost::asio::thread_pool* pool = router_.context().scene_pool;
    if (pool && Router::parses_scene(*request)) {
        // A scene takes time in proportion to its size to parse: off the I/O threads, so that
        // every other connection (/healthz included) keeps being answered; back on this strand.
        net::post(*pool, [self = shared_from_this(), request] {
            auto routed = std::make_shared<RouteResult>(self->router_.route(*request));
            net::post(self->stream_.get_executor(),
                      [self, routed, request] { self->deliver(std::move(*routed), *request); });
        });
        return;
    }
    deliver(router_.route(*request), *request);
}

void Session::deliver(RouteResult routed, const Request& request) {
    if (routed.events) return start_events(std::move(routed.response), *routed.events);
    if (routed.deferred) return run_deferred(std::move(routed.deferred), request);
    send(std::move(routed.response));
}

void Session::run_deferred(DeferredResponse work, const Request& request) {
    BlockingPool* pool = router_.context().blocking;
    if (!pool) return send(work());
    // The connection reads nothing more until this answer is written, as for any request.
    auto task = [self = shared_from_this(), work = std::move(work)] {
        net::post(self->stream_.get_executor(),
                  [self, response = work()]() mutable { self->send(std::move(response)); });
    };
    if (pool->try_post(std::move(task))) return;
    Response busy = error_response(request, http::status::service_unavailable, "busy",
                                   "the service is busy drawing; retry later");
    busy.set(http::field::retry_after, kBusyRetrySeconds);
    send(std::move(busy));
}

void Session::refuse(http::status status, const std::string& code, const std::string& message) {
    Request request{http::verb::unknown, "", 11};
    request.keep_alive(false);
    Response response = error_response(request, status, code, message);
    response.keep_alive(false);
    send(std::move(response));
}

void Session::send(Response response) {
    log(response.result_int());
    auto message = std::make_shared<Response>(std::move(response));
    in_flight_ = message;
    stream_.expires_after(limits_.read_timeout);
    http::async_write(stream_, *message,
                      [self = shared_from_this(), close = message->need_eof()](
                          beast::error_code ec, std::size_t) { self->on_write(close, ec); });
}

void Session::on_write(bool close_after, beast::error_code ec) {
    in_flight_.reset();
    if (ec) return;
    if (close_after) return close();
    do_read();
}

void Session::close() {
    beast::error_code ignored;
    stream_.socket().shutdown(net::ip::tcp::socket::shutdown_send, ignored);
    // Drain briefly so unread request bytes do not turn the close into a reset.
    auto scratch = std::make_shared<std::array<char, 4096>>();
    stream_.expires_after(kLingerTime);
    auto drain = std::make_shared<std::function<void()>>();
    *drain = [self = shared_from_this(), scratch, drain] {
        self->stream_.async_read_some(net::buffer(*scratch),
                                      [self, scratch, drain](beast::error_code ec, std::size_t) {
                                          if (!ec) return (*drain)();
                                          beast::error_code ignore;
                                          self->stream_.socket().close(ignore);
                                          *drain = nullptr;  // break the cycle
                                      });
    };
    (*drain)();
}

void Session::start_events(Response header, const EventStreamStart& start) {
    log(header.result_int());
    auto response =
        std::make_shared<http::response<http::empty_body>>(header.result(), header.version());
    for (const auto& field : header) response->set(field.name_string(), field.value());
    // The stream ends when the job does; without a length, closing the connection ends the body.
    response->keep_alive(false);
    auto serializer = std::make_shared<http::response_serializer<http::empty_body>>(*response);
    in_flight_ =
        std::make_shared<std::pair<decltype(response), decltype(serializer)>>(response, serializer);
    events_.emplace(start.last_event_id);
    event_job_ = start.job_id;
    stream_.expires_after(limits_.read_timeout);
    http::async_write_header(stream_, *serializer,
                             [self = shared_from_this()](beast::error_code ec, std::size_t) {
                                 self->on_event_written(ec);
                             });
}

void Session::poll_events() {
    JobQueue& jobs = router_.context().jobs;
    // A job another replica runs is read from the store only when the store says it changed:
    // asked before reading, so that a change made meanwhile is read at the next poll.
    const std::optional<std::uint64_t> token = jobs.change_token(event_job_);
    std::string text;
    if (!token || token != event_token_) {
        const std::optional<JobRecord> job = jobs.find(event_job_);
        if (!job) return close();
        const std::shared_ptr<const JobSnapshot> snapshot = jobs.snapshot(event_job_);
        text = events_->next(*job, snapshot.get());
        event_token_ = token;
    }
    const auto now = std::chrono::steady_clock::now();
    if (text.empty() && now - last_event_write_ >= limits_.keep_alive) text = kKeepAliveComment;
    if (text.empty()) {
        timer_.expires_after(limits_.event_poll);
        timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
            if (!ec) self->poll_events();
        });
        return;
    }
    event_text_ = std::move(text);
    // A client that stops reading is dropped after this, instead of holding the session forever.
    stream_.expires_after(limits_.read_timeout);
    net::async_write(stream_, net::buffer(event_text_),
                     [self = shared_from_this()](beast::error_code ec, std::size_t) {
                         self->on_event_written(ec);
                     });
}

void Session::on_event_written(beast::error_code ec) {
    if (ec) return;
    last_event_write_ = std::chrono::steady_clock::now();
    if (events_->finished()) return close();
    // Polling, not waking per progress report, caps the event rate and decouples the solver.
    timer_.expires_after(limits_.event_poll);
    timer_.async_wait([self = shared_from_this()](beast::error_code wec) {
        if (!wec) self->poll_events();
    });
}

void Session::log(unsigned status) {
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started_)
            .count();
    spdlog::info("{} {} {} {:.1f} ms", method_, target_, status, ms);
    router_.context().metrics.count_request(status);
}

}  // namespace radiant::server
