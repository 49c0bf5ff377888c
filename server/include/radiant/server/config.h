// radiantd's settings (flags, with RADIANT_* environment variables as fallbacks).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace radiant::server {

struct ServerConfig {
    std::string listen = "127.0.0.1:8080";  ///< ADDR:PORT; port 0 picks a free one
    std::string data_dir = "./data";
    /// A postgresql:// URI: a store that several radiantd share, instead of SQLite in data_dir.
    std::string store_uri;
    std::string replica;  ///< this process's name among those sharing a store (default host:pid)
    /// How long a shared store's job stays with a replica that stopped renewing its lease.
    double lease_seconds = 10;
    /// After SIGTERM, how long running solves may go on before they are handed back to the
    /// queue: most short solves end within it, and it stays below a container platform's grace
    /// period (Kubernetes: 30 s) so that a hand-back never meets a SIGKILL.
    double drain_seconds = 20;
    std::size_t workers = 1;       ///< concurrent solves; each one uses every core
    std::size_t queue_limit = 64;  ///< waiting jobs; bounded so memory and latency stay bounded
    /// Largest request body; the scene parser's own limit, so nothing bigger is ever buffered.
    std::size_t max_body_bytes = 64u << 20;
    /// Per-job solve time cap on top of the scene's own: one job cannot hold a worker for good.
    double job_seconds = 3600;
    /// Per-job memory budget in MiB; 0: half the physical memory divided among the workers.
    double job_memory_mb = 0;
    /// The job store's size cap in MiB; 0: the disk's.
    double max_store_mb = 0;
    std::size_t io_threads = 2;  ///< handlers are short; solves run on the workers
    /// Parses submitted scenes; one, so that parsing never takes both cores from the I/O
    /// threads and the parser's memory is that of one body at a time.
    std::size_t scene_threads = 1;
    std::string token_file;  ///< a bearer token required on every route but /healthz
    std::vector<std::string> allowed_hosts;  ///< Host names answered besides the loopback ones
    std::vector<std::string> cors_origins;   ///< browser origins allowed cross-origin access
    std::string web_root;                    ///< the viewer's files (empty: default_web_root())
};

/// The token in `path`: its first line, without surrounding white space. Throws when the file
/// cannot be read or holds no token.
std::string read_token_file(const std::string& path);

struct ListenAddress {
    std::string host;
    std::uint16_t port = 0;
};

/// Where an installed radiantd finds the web viewer: PREFIX/share/radiant/web for
/// PREFIX/bin/radiantd. The build tree has the same layout (build/bin, build/share), so a built
/// daemon finds the viewer the build made.
std::filesystem::path default_web_root(const std::filesystem::path& executable);

/// "127.0.0.1:8080" or "[::1]:8080"; nothing for anything else.
std::optional<ListenAddress> parse_listen(const std::string& text);

}  // namespace radiant::server
