#include "accuracy/pareto.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace accuracy {

std::vector<std::size_t> paretoFront(std::span<const double> cost, std::span<const double> error) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < error.size(); ++i)
        if (std::isfinite(error[i])) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (cost[a] != cost[b]) return cost[a] < cost[b];
        return error[a] < error[b];
    });
    // Walking from cheap to dear, a point is on the front when it beats every cheaper point's error.
    std::vector<std::size_t> front;
    double bestError = std::numeric_limits<double>::infinity();
    for (std::size_t i : order) {
        if (error[i] < bestError) {
            bestError = error[i];
            front.push_back(i);
        }
    }
    return front;
}

}  // namespace accuracy
