#include "radiant/server/stored_solutions.h"

#include <algorithm>

namespace radiant::server {
namespace {

/// The sensor values a solution holds: its own, and its groups' (with their initial values).
std::size_t values_of(const Result& r) {
    std::size_t n = 0;
    for (const SensorResult& s : r.sensors) n += s.illuminance.size();
    for (const GroupContribution& g : r.groups) {
        for (const GroupContribution::Sensors& s : g.sensors)
            n += s.illuminance.size() + s.initial_illuminance.size();
    }
    return n;
}

}  // namespace

std::shared_ptr<const Result> StoredSolutions::find(const std::string& id) {
    const std::lock_guard lock(mutex_);
    const auto it =
        std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.id == id; });
    if (it == entries_.end()) return nullptr;
    entries_.splice(entries_.begin(), entries_, it);
    return it->solution;
}

void StoredSolutions::keep(const std::string& id, std::shared_ptr<const Result> solution) {
    const std::size_t values = values_of(*solution);
    if (values > max_values_) return;
    const std::lock_guard lock(mutex_);
    if (std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.id == id; }))
        return;  // another request read it first
    while (!entries_.empty() && values_ + values > max_values_) {
        values_ -= entries_.back().values;
        entries_.pop_back();
    }
    entries_.push_front({id, std::move(solution), values});
    values_ += values;
}

}  // namespace radiant::server
