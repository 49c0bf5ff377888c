// Accepts TCP connections and hands each one to a Session.
#pragma once

#include <memory>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>

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
    boost::asio::io_context& ioc_;
    boost::asio::ip::tcp::acceptor acceptor_;
    Router& router_;
    const SessionLimits limits_;
};

}  // namespace radiant::server
