#include "app/simulation/run_series.h"

#include "simcore/world/world.h"

#include <algorithm>
#include <stdexcept>

namespace interplay {

RunSeries::RunSeries(std::size_t capacity) : m_capacity(capacity) {
    if (capacity == 0) throw std::invalid_argument("RunSeries: the capacity must be at least one sample");
}

RunSample RunSeries::sample(const simcore::World& world) {
    const simcore::StepProfile& profile = world.lastStepProfile();
    RunSample sample;
    sample.step = world.stepCount();
    sample.time = world.simulatedTime();
    sample.kineticEnergy = world.kineticEnergy();
    sample.potentialEnergy = world.potentialEnergy();
    sample.maxPenetration = profile.maxPenetration;
    sample.jointError = world.worstJointError().position;
    sample.stageMs = profile.stageMs;
    sample.totalMs = profile.totalMs;
    return sample;
}

void RunSeries::append(const RunSample& sample) {
    if (m_samples.size() == m_capacity) m_samples.pop_front();
    m_samples.push_back(sample);
}

void RunSeries::clear() { m_samples.clear(); }

void RunSeries::truncateAfterStep(std::uint64_t step) {
    while (!m_samples.empty() && m_samples.back().step > step) m_samples.pop_back();
}

std::optional<std::size_t> RunSeries::nearest(double time) const {
    if (m_samples.empty()) return std::nullopt;
    // Times increase with the steps: the first sample at or after `time`, or the one before it.
    const auto after = std::lower_bound(m_samples.begin(), m_samples.end(), time,
                                        [](const RunSample& s, double t) { return s.time < t; });
    if (after == m_samples.begin()) return 0;
    if (after == m_samples.end()) return m_samples.size() - 1;
    const auto before = std::prev(after);
    const auto index = static_cast<std::size_t>(after - m_samples.begin());
    return time - before->time <= after->time - time ? index - 1 : index;
}

}  // namespace interplay
