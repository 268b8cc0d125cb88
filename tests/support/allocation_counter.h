#pragma once
// Counts heap allocations between start and stop, to prove that hot paths never allocate. A test
// that links allocation_counter.cpp has every global operator new replaced by a counting one
// (under ThreadSanitizer, whose runtime keeps its own, every heap allocation counted by its hook).

#include <cstddef>

namespace test_support {

void startCountingAllocations();
std::size_t stopCountingAllocations();  // allocations since the matching start

}  // namespace test_support
