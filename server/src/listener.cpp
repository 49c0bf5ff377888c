#include "radiant/server/listener.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cerrno>

#include <boost/asio/strand.hpp>

namespace radiant::server {

namespace net = boost::asio;

namespace {

// Accepting pauses this long after the first failure for want of descriptors, twice as long
// after each further one, up to the longest; a pause is long next to a request, short next to
// the time a client waits for a connection.
constexpr std::chrono::milliseconds kFirstPause{10};
constexpr std::chrono::milliseconds kLongestPause{1000};
// At most one log line per this period while accepts keep failing.
constexpr std::chrono::seconds kLogPeriod{10};

/// Errors that say the process or system is out of a resource, not that one client went away.
bool out_of_resources(const boost::system::error_code& ec) {
    if (ec.category() != boost::system::system_category()) return false;
    const int e = ec.value();
    return e == EMFILE || e == ENFILE || e == ENOBUFS || e == ENOMEM;
}

}  // namespace

Listener::Listener(net::io_context& ioc, const net::ip::tcp::endpoint& endpoint, Router& router,
                   SessionLimits limits)
    : ioc_(ioc),
      acceptor_(net::make_strand(ioc)),
      pause_(acceptor_.get_executor()),
      router_(router),
      limits_(limits) {
    acceptor_.open(endpoint.protocol());
    acceptor_.set_option(net::socket_base::reuse_address(true));
    acceptor_.bind(endpoint);
    acceptor_.listen(net::socket_base::max_listen_connections);
}

void Listener::run() { do_accept(); }

void Listener::stop() {
    net::dispatch(acceptor_.get_executor(), [self = shared_from_this()] {
        boost::system::error_code ignored;
        self->acceptor_.close(ignored);
        self->pause_.cancel();
    });
}

void Listener::do_accept() {
    // Each connection gets its own strand, so its handlers never run concurrently.
    acceptor_.async_accept(
        net::make_strand(ioc_),
        [self = shared_from_this()](boost::system::error_code ec, net::ip::tcp::socket socket) {
            if (ec == net::error::operation_aborted || !self->acceptor_.is_open()) return;
            if (out_of_resources(ec)) {
                self->pause_accepting(ec);
                return;
            }
            if (ec) {
                // One client gave up (a reset before accept): nothing to wait for.
                spdlog::warn("accept: {}", ec.message());
            } else {
                self->pause_length_ = std::chrono::milliseconds{0};
                std::make_shared<Session>(std::move(socket), self->router_, self->limits_)->run();
            }
            self->do_accept();
        });
}

void Listener::pause_accepting(const boost::system::error_code& ec) {
    pause_length_ = std::clamp(2 * pause_length_, kFirstPause, kLongestPause);
    ++failures_since_log_;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_log_ >= kLogPeriod) {
        spdlog::warn(
            "accept: {}; pausing accepts up to {} ms at a time ({} failure(s) since the "
            "last such line)",
            ec.message(), kLongestPause.count(), failures_since_log_);
        last_log_ = now;
        failures_since_log_ = 0;
    }
    pause_.expires_after(pause_length_);
    pause_.async_wait([self = shared_from_this()](boost::system::error_code wait_ec) {
        if (wait_ec == net::error::operation_aborted || !self->acceptor_.is_open()) return;
        self->do_accept();
    });
}

}  // namespace radiant::server
