#include "json_text.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace radiant::proto {
namespace {

using Json = nlohmann::ordered_json;
/// ordered_json's object is a vector of members; appending to it directly skips the linear
/// search that ordered_map::emplace makes for every key (quadratic in the keys of an object).
using Members = Json::object_t::Container;

constexpr int kNumberOverflow = 406;  // nlohmann's out_of_range.406
/// Objects up to this size look for duplicate keys pairwise; larger ones sort their keys.
constexpr std::size_t kPairwiseDuplicateCheck = 16;

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

/// `text` with bytes outside printable ASCII written as \xNN: nlohmann's messages quote the bytes
/// it read, which may be invalid UTF-8, and an error message must itself be valid JSON text.
std::string printable(std::string_view text) {
    std::string out;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f) {
            out += c;
        } else {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
            out += escaped;
        }
    }
    return out;
}

/// nlohmann's message without its "[json.exception...] parse error at line L, column C: " prefix.
std::string detail_of(const nlohmann::json::exception& e) {
    const std::string what = e.what();
    const std::size_t column = what.find("column ");
    const std::size_t colon = what.find(": ", column == std::string::npos ? 0 : column);
    return printable(colon == std::string::npos ? what : what.substr(colon + 2));
}

/// nlohmann's SAX events → an ordered_json DOM (when `build`), counted against the budget as they
/// come. It tracks where it is, so every refusal names the pointer of the value at fault.
class BudgetedReader : public nlohmann::json_sax<Json> {
public:
    BudgetedReader(const JsonBudget& budget, bool build) : budget_(budget), build_(build) {}

    bool null() override { return scalar(nullptr); }
    bool boolean(bool value) override { return scalar(value); }
    bool number_integer(number_integer_t value) override { return scalar(value); }
    bool number_unsigned(number_unsigned_t value) override { return scalar(value); }
    bool number_float(number_float_t value, const string_t&) override { return scalar(value); }
    bool string(string_t& value) override { return scalar(std::move(value)); }
    bool binary(binary_t&) override { return scalar(nullptr); }  // JSON text has no binary
    bool start_object(std::size_t) override { return open(false); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_object() override { return duplicate_free() && close(); }
    bool end_array() override { return close(); }

    bool key(string_t& key) override {
        Frame& frame = frames_.back();
        frame.key = key;
        if (++keys_ > budget_.max_keys) {
            return refuse("more than " + std::to_string(budget_.max_keys) + " object keys", true);
        }
        if (build_) {
            auto& members = static_cast<Members&>(frame.node->get_ref<Json::object_t&>());
            members.emplace_back(key, nullptr);
            slot_ = &members.back().second;
        }
        return true;
    }

    bool parse_error(std::size_t position, const std::string&,
                     const nlohmann::json::exception& e) override {
        const std::string where = line_and_column(text_, position);
        const std::string detail = detail_of(e);
        if (e.id == kNumberOverflow) {
            refusal_ = {{pointer(), "number is too large to be finite (" + where + ")"}, false};
        } else if (detail.find("UTF-8") != std::string::npos) {
            refusal_ = {{pointer(), "invalid UTF-8 in a string (" + where + ")"}, false};
        } else {
            refusal_ = {{"", "invalid JSON at " + where + ": " + detail}, false};
        }
        return false;
    }

    /// Reads `text`; the refusal, if any.
    std::optional<JsonRefusal> read(std::string_view text) {
        text_ = text;
        if (Json::sax_parse(text, this)) return std::nullopt;
        if (!refusal_) refusal_ = JsonRefusal{{"", "invalid JSON"}, false};
        return refusal_;
    }

    Json root_;

private:
    struct Frame {
        Json* node;  ///< the container being filled (null when not building)
        bool in_array;
        std::size_t index;  ///< in an array: elements done so far, so the index of the next
        std::string key;    ///< in an object: the member being read
    };

    /// RFC 6901 pointer of the value being read.
    std::string pointer() const {
        Json::json_pointer p;
        for (const Frame& f : frames_) p = f.in_array ? p / f.index : p / f.key;
        return p.to_string();
    }

    bool refuse(std::string message, bool over_budget) {
        refusal_ = {{pointer(), std::move(message)}, over_budget};
        return false;
    }

    /// Counts one value; false (with the refusal) when it is over the budget.
    bool count_value() {
        if (++values_ > budget_.max_values) {
            return refuse("more than " + std::to_string(budget_.max_values) + " JSON values", true);
        }
        return true;
    }

    /// Stores `value` where the parser is; returns where it went.
    template <class Value>
    Json* place(Value&& value) {
        if (frames_.empty()) {
            root_ = Json(std::forward<Value>(value));
            return &root_;
        }
        if (frames_.back().in_array) {
            auto& array = frames_.back().node->get_ref<Json::array_t&>();
            array.emplace_back(std::forward<Value>(value));
            return &array.back();
        }
        *slot_ = Json(std::forward<Value>(value));
        return slot_;
    }

    void value_done() {
        if (!frames_.empty() && frames_.back().in_array) ++frames_.back().index;
    }

    template <class Value>
    bool scalar(Value&& value) {
        if (!count_value()) return false;
        if (build_) place(std::forward<Value>(value));
        value_done();
        return true;
    }

    bool open(bool array) {
        if (!count_value()) return false;
        if (frames_.size() >= budget_.max_depth) {
            return refuse("nested deeper than " + std::to_string(budget_.max_depth) + " levels",
                          true);
        }
        if (++containers_ > budget_.max_containers) {
            return refuse(
                "more than " + std::to_string(budget_.max_containers) + " arrays and objects",
                true);
        }
        Json* node = build_ ? place(array ? Json::array() : Json::object()) : nullptr;
        frames_.push_back({node, array, 0, {}});
        return true;
    }

    bool close() {
        frames_.pop_back();
        value_done();
        return true;
    }

    /// A duplicate key is refused: which of the two values was meant cannot be known.
    bool duplicate_free() {
        if (!build_) return true;
        const auto& members =
            static_cast<const Members&>(frames_.back().node->get_ref<const Json::object_t&>());
        std::vector<std::string_view> keys;
        keys.reserve(members.size());
        for (const auto& m : members) keys.emplace_back(m.first);
        const std::string_view* duplicate = nullptr;
        if (keys.size() <= kPairwiseDuplicateCheck) {
            for (std::size_t i = 1; i < keys.size() && !duplicate; ++i) {
                for (std::size_t j = 0; j < i && !duplicate; ++j) {
                    if (keys[i] == keys[j]) duplicate = &keys[i];
                }
            }
        } else {
            std::sort(keys.begin(), keys.end());
            const auto it = std::adjacent_find(keys.begin(), keys.end());
            if (it != keys.end()) duplicate = &*it;
        }
        if (!duplicate) return true;
        frames_.back().key = std::string(*duplicate);
        return refuse("duplicate key \"" + std::string(*duplicate) + "\"", false);
    }

    const JsonBudget& budget_;
    const bool build_;
    std::string_view text_;
    std::vector<Frame> frames_;
    Json* slot_ = nullptr;  ///< the member whose key was read last
    std::size_t values_ = 0, containers_ = 0, keys_ = 0;
    std::optional<JsonRefusal> refusal_;
};

}  // namespace

std::variant<Json, JsonRefusal> parse_json_text(std::string_view text, const JsonBudget& budget) {
    BudgetedReader reader(budget, true);
    if (auto refusal = reader.read(text)) return std::move(*refusal);
    return std::move(reader.root_);
}

std::optional<JsonRefusal> check_json_text(std::string_view text, const JsonBudget& budget) {
    BudgetedReader reader(budget, false);
    return reader.read(text);
}

}  // namespace radiant::proto
