#include "atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

namespace radiant::cli {

void check_output_path(const std::filesystem::path& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status) || std::filesystem::is_regular_file(status)) return;
    throw OutputRefused(path.string() +
                        " is not a regular file; the output goes to a new or regular file only");
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
    check_output_path(path);
    // Same directory as the target, so that rename() does not cross file systems.
    std::string temp = path.string() + ".XXXXXX";
    const int fd = mkstemp(temp.data());
    if (fd < 0) {
        throw std::runtime_error("cannot create a file beside " + path.string() + ": " +
                                 std::strerror(errno));
    }
    auto fail = [&](const char* what) {
        const std::string reason = std::strerror(errno);
        ::close(fd);
        std::remove(temp.c_str());
        throw std::runtime_error(std::string(what) + " " + path.string() + ": " + reason);
    };
    for (std::size_t done = 0; done < content.size();) {
        const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail("cannot write");
        }
        done += static_cast<std::size_t>(n);
    }
    // mkstemp creates 0600; a result file is an ordinary document.
    if (::fchmod(fd, 0644) != 0 || ::fsync(fd) != 0) fail("cannot write");
    if (::close(fd) != 0) {
        std::remove(temp.c_str());
        throw std::runtime_error("cannot write " + path.string());
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(errno);
        std::remove(temp.c_str());
        throw std::runtime_error("cannot write " + path.string() + ": " + reason);
    }
}

}  // namespace radiant::cli
