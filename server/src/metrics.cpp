#include "radiant/server/metrics.h"

#include <sstream>
#include <utility>

namespace radiant::server {
namespace {

/// A label value as the text format needs it: backslash, double quote and newline escaped.
std::string escape_label(const std::string& value) {
    std::string out;
    for (const char c : value) {
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        if (c == '\\' || c == '"') out += '\\';
        out += c;
    }
    return out;
}

}  // namespace

Metrics::Metrics(std::string replica) : replica_(std::move(replica)) {}

std::string Metrics::labels(const std::string& name, const std::string& value) const {
    std::string out;
    if (!replica_.empty()) out = "replica=\"" + escape_label(replica_) + "\"";
    if (!name.empty()) out += (out.empty() ? "" : ",") + name + "=\"" + value + "\"";
    return out.empty() ? out : "{" + out + "}";
}

void Metrics::count_request(unsigned status) {
    const std::lock_guard lock(mutex_);
    ++requests_by_status_[status];
}

void Metrics::count_solve(double seconds, std::uint64_t rays) {
    const std::lock_guard lock(mutex_);
    ++solves_;
    solve_seconds_ += seconds;
    rays_ += rays;
}

std::string Metrics::render(const std::map<JobStatus, std::size_t>& jobs,
                            std::size_t queue_length) const {
    std::ostringstream out;
    out << "# HELP radiant_jobs Jobs in the store by state.\n# TYPE radiant_jobs gauge\n";
    for (JobStatus s : {JobStatus::queued, JobStatus::running, JobStatus::done, JobStatus::failed,
                        JobStatus::cancelled}) {
        const auto it = jobs.find(s);
        out << "radiant_jobs" << labels("state", to_string(s)) << ' '
            << (it == jobs.end() ? 0 : it->second) << '\n';
    }
    const std::string replica = labels();
    out << "# HELP radiant_queue_length Jobs waiting for a worker.\n"
           "# TYPE radiant_queue_length gauge\n"
        << "radiant_queue_length" << replica << ' ' << queue_length << '\n';
    const std::lock_guard lock(mutex_);
    out << "# HELP radiant_solves_total Solves run to their end (done, failed or cancelled).\n"
           "# TYPE radiant_solves_total counter\n"
        << "radiant_solves_total" << replica << ' ' << solves_ << '\n';
    out << "# HELP radiant_solve_seconds_total Wall-clock seconds spent solving.\n"
           "# TYPE radiant_solve_seconds_total counter\n"
        << "radiant_solve_seconds_total" << replica << ' ' << solve_seconds_ << '\n';
    out << "# HELP radiant_rays_total Visibility rays cast by finished solves.\n"
           "# TYPE radiant_rays_total counter\n"
        << "radiant_rays_total" << replica << ' ' << rays_ << '\n';
    out << "# HELP radiant_http_requests_total HTTP requests answered, by status.\n"
           "# TYPE radiant_http_requests_total counter\n";
    for (const auto& [status, count] : requests_by_status_) {
        out << "radiant_http_requests_total" << labels("status", std::to_string(status)) << ' '
            << count << '\n';
    }
    return out.str();
}

}  // namespace radiant::server
