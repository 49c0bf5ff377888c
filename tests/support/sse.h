// Parses a text/event-stream body into its events, for service tests.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radiant::test {

struct SseEvent {
    std::string name;  ///< "message" when the event has no `event:` line
    std::uint64_t id = 0;
    std::string data;
};

/// The events of `body`; comments (keep-alives) are skipped.
inline std::vector<SseEvent> parse_sse(const std::string& body) {
    std::vector<SseEvent> events;
    std::size_t at = 0;
    while (at < body.size()) {
        std::size_t end = body.find("\n\n", at);
        if (end == std::string::npos) end = body.size();
        SseEvent event{"message", 0, ""};
        bool any = false;
        for (std::size_t line = at; line < end;) {
            std::size_t eol = body.find('\n', line);
            if (eol == std::string::npos || eol > end) eol = end;
            const std::string text = body.substr(line, eol - line);
            if (text.rfind("event: ", 0) == 0) {
                event.name = text.substr(7);
                any = true;
            } else if (text.rfind("id: ", 0) == 0) {
                event.id = std::stoull(text.substr(4));
            } else if (text.rfind("data: ", 0) == 0) {
                event.data += text.substr(6);
                any = true;
            }
            line = eol + 1;
        }
        if (any) events.push_back(std::move(event));
        at = end + 2;
    }
    return events;
}

}  // namespace radiant::test
