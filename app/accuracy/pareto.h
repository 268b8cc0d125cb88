#pragma once
// The Pareto front of error against cost: the points no other point beats on both. Shared by the
// accuracy benchmark and interplay-sweep.

#include <cstddef>
#include <span>
#include <vector>

namespace accuracy {

// Indices of the points on the front, cheapest first. A point whose error is not finite (a failed
// run) is never on it; of points with equal cost the smaller error comes first.
std::vector<std::size_t> paretoFront(std::span<const double> cost, std::span<const double> error);

}  // namespace accuracy
