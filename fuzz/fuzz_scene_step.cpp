// libFuzzer target: scene text loaded, built into a World and stepped fuzz::kSteps times.
#include "scene_checks.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::checkStep({reinterpret_cast<const char*>(data), size});
    return 0;
}
