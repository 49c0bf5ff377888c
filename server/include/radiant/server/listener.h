// Accepts TCP connections and hands each one to a Session.
#pragma once

#include <chrono>
#include <cstddef>
#include <memory>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include "radiant/server/router.h"
#include "radiant/server/session.h"

namespace radiant::server {

class Listener : public std::enable_shared_from_this<Listener> {
public:
    /// Binds at once (throws boost::system::system_error when the address is taken), so the
    /// caller can report the chosen port before anything is served.
    Listener(boost::asio::io_context& ioc, const boost::asio::ip::tcp::endpoint& endpoint,
             Router& router, SessionLimits limits);
    boost::asio::ip::tcp::endpoint local_endpoint() const { return acceptor_.local_endpoint(); }
    void run();
    /// Stops accepting; open connections finish on their own.
    void stop();

private:
    void do_accept();
    /// Out of file descriptors (or kernel memory), accept fails at once every time: accepting
    /// again pauses, longer while it lasts, and the log gets one line a period, not one a try.
    void pause_accepting(const boost::system::error_code& ec);
    boost::asio::io_context& ioc_;
    boost::asio::ip::tcp::acceptor acceptor_;
    boost::asio::steady_timer pause_;  ///< on the acceptor's strand
    std::chrono::milliseconds pause_length_{0};
    std::chrono::steady_clock::time_point last_log_{};
    std::size_t failures_since_log_ = 0;
    Router& router_;
    const SessionLimits limits_;
};

}  // namespace radiant::server
