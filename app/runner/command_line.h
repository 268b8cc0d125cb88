#pragma once
// The command-line conventions interplay-run and interplay-sweep share: one scene file as the only
// word without "--", every option followed by its value, --help or -h anywhere, and numbers read
// whole (no trailing text, no locale).

#include <charconv>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace command_line {

// The whole of `text` as a T, or nothing ("3x", "", " 3" and out-of-range values are refused).
template <typename T>
std::optional<T> parseNumber(const std::string& text) {
    T value{};
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value);
    if (ec != std::errc() || ptr != end) return std::nullopt;
    return value;
}

struct Walk {
    std::string scenePath;
    std::string stoppedAt;  // the stopping flag met (--help, -h or one of the caller's); the rest was not read
    std::string error;      // empty on success: the first problem, as a sentence
};

// Handles one option and its value; returns an error sentence to stop the walk.
using OptionHandler = std::function<std::optional<std::string>(const std::string& option, const std::string& value)>;

// Walks `arguments` (without argv[0]) in order. --help, -h and the `stopFlags` end the walk where
// they stand; a word without "--" is the scene (a second one is an error); any other option takes
// the next argument as its value and goes to `handle`.
Walk walkArguments(const std::vector<std::string>& arguments, std::initializer_list<std::string_view> stopFlags,
                   const OptionHandler& handle);

}  // namespace command_line
