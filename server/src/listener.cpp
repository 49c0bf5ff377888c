#include "radiant/server/listener.h"

#include <spdlog/spdlog.h>

#include <boost/asio/strand.hpp>

namespace radiant::server {

namespace net = boost::asio;

Listener::Listener(net::io_context& ioc, const net::ip::tcp::endpoint& endpoint, Router& router,
                   SessionLimits limits)
    : ioc_(ioc), acceptor_(net::make_strand(ioc)), router_(router), limits_(limits) {
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
    });
}

void Listener::do_accept() {
    // Each connection gets its own strand, so its handlers never run concurrently.
    acceptor_.async_accept(
        net::make_strand(ioc_),
        [self = shared_from_this()](boost::system::error_code ec, net::ip::tcp::socket socket) {
            if (ec == net::error::operation_aborted || !self->acceptor_.is_open()) return;
            if (ec) {
                // Out of file descriptors and the like: log and keep accepting.
                spdlog::warn("accept: {}", ec.message());
            } else {
                std::make_shared<Session>(std::move(socket), self->router_, self->limits_)->run();
            }
            self->do_accept();
        });
}

}  // namespace radiant::server
