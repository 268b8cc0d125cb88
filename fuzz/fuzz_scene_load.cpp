// libFuzzer target: scene text (v1 or thesis format) through the loader, save and reload.
#include "scene_checks.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::checkLoad({reinterpret_cast<const char*>(data), size});
    return 0;
}
