#include "json_text.h"

#include <string>
#include <vector>

namespace radiant::proto {
namespace {

using Json = nlohmann::ordered_json;

/// Line and column (1-based) of the character at 1-based byte position `position`.
std::string line_and_column(std::string_view text, std::size_t position) {
    const std::size_t end = std::min(position, text.size());
    std::size_t line = 1, line_start = 0;
    for (std::size_t i = 0; i + 1 < end; ++i) {
        if (text[i] == '\n') {
            ++line;
            line_start = i + 1;
        }
    }
    const std::size_t column = end > line_start ? end - line_start : 1;
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// nlohmann's message without its "[json.exception...] parse error at line L, column C: " prefix.
std::string detail_of(const nlohmann::json::exception& e) {
    const std::string what = e.what();
    const std::size_t column = what.find("column ");
    const std::size_t colon = what.find(": ", column == std::string::npos ? 0 : column);
    return colon == std::string::npos ? what : what.substr(colon + 2);
}

/// A SAX pass that only tracks where it is, so that an error that carries no location of its
/// own (a number overflowing to infinity) can be reported at the pointer of the value.
class Locator : public nlohmann::json_sax<Json> {
public:
    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override {
        frames_.push_back({false, 0, {}});
        return true;
    }
    bool key(string_t& key) override {
        frames_.back().key = key;
        return true;
    }
    bool end_object() override { return end_container(); }
    bool start_array(std::size_t) override {
        frames_.push_back({true, 0, {}});
        return true;
    }
    bool end_array() override { return end_container(); }
    bool parse_error(std::size_t position, const std::string&,
                     const nlohmann::json::exception& e) override {
        position_ = position;
        error_id_ = e.id;
        message_ = detail_of(e);
        for (const Frame& f : frames_) {
            pointer_ /= f.in_array ? std::to_string(f.index) : f.key;
        }
        return false;
    }

    std::size_t position_ = 0;
    int error_id_ = 0;
    std::string message_;
    Json::json_pointer pointer_;

private:
    struct Frame {
        bool in_array;
        std::size_t index;
        std::string key;
    };

    bool value() {
        if (!frames_.empty() && frames_.back().in_array) ++frames_.back().index;
        return true;
    }
    bool end_container() {
        frames_.pop_back();
        return value();
    }

    std::vector<Frame> frames_;
};

constexpr int kNumberOverflow = 406;  // nlohmann's out_of_range.406

}  // namespace

std::variant<Json, Problem> parse_json_text(std::string_view text) {
    try {
        return Json::parse(text);
    } catch (const nlohmann::json::exception&) {
        // Parse again to locate the error; only the failing path pays for this.
        Locator locator;
        (void)Json::sax_parse(text, &locator);
        const std::string where = line_and_column(text, locator.position_);
        if (locator.error_id_ == kNumberOverflow) {
            return Problem{locator.pointer_.to_string(),
                           "number is too large to be finite (" + where + ")"};
        }
        return Problem{"", "invalid JSON at " + where + ": " + locator.message_};
    }
}

}  // namespace radiant::proto
