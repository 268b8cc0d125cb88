#include "command_line.h"

#include <algorithm>

namespace command_line {

Walk walkArguments(const std::vector<std::string>& arguments, std::initializer_list<std::string_view> stopFlags,
                   const OptionHandler& handle) {
    Walk walk;
    for (std::size_t i = 0; i < arguments.size(); ++i) {
        const std::string& arg = arguments[i];
        if (arg == "--help" || arg == "-h" || std::find(stopFlags.begin(), stopFlags.end(), arg) != stopFlags.end()) {
            walk.stoppedAt = arg;
            return walk;
        }
        if (arg.rfind("--", 0) != 0) {
            if (!walk.scenePath.empty()) {
                walk.error = "more than one scene given: '" + arg + "'";
                return walk;
            }
            walk.scenePath = arg;
            continue;
        }
        if (i + 1 >= arguments.size()) {
            walk.error = "option " + arg + " needs a value";
            return walk;
        }
        if (std::optional<std::string> error = handle(arg, arguments[++i])) {
            walk.error = std::move(*error);
            return walk;
        }
    }
    return walk;
}

}  // namespace command_line
