#include "app/simulation/real_time_meter.h"

namespace interplay {

void RealTimeMeter::restart(double now) {
    m_batches.clear();
    m_start = now;
}

void RealTimeMeter::add(double now, double simulated) {
    m_batches.push_back({now, simulated});
    // The window starts where a dropped batch ended, so every wall second in it is paired with
    // the simulated time run in it.
    while (m_batches.size() > 1 && now - m_batches.front().end > kWindowSeconds) {
        m_start = m_batches.front().end;
        m_batches.pop_front();
    }
}

std::optional<double> RealTimeMeter::factor() const {
    if (m_batches.empty()) return std::nullopt;
    const double span = m_batches.back().end - m_start;
    if (span < kMinSpanSeconds) return std::nullopt;
    double simulated = 0.0;
    for (const Batch& batch : m_batches) simulated += batch.simulated;
    return simulated / span;
}

}  // namespace interplay
