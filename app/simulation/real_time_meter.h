#pragma once
// How fast playback goes against the wall clock: simulated seconds per wall second over about the
// last second, from the batches of steps as they finish. Plain C++; the times are the caller's.

#include <deque>
#include <optional>

namespace interplay {

class RealTimeMeter {
public:
    static constexpr double kWindowSeconds = 1.0;
    // The least wall time measured before a factor is given: one batch alone says little.
    static constexpr double kMinSpanSeconds = 0.25;

    // Measuring starts over at wall time `now` (s): what ran before does not count.
    void restart(double now);
    // A batch that ran `simulated` seconds of simulated time finished at wall time `now` (s).
    void add(double now, double simulated);
    // Simulated seconds per wall second since the window began, once it spans kMinSpanSeconds.
    std::optional<double> factor() const;

private:
    struct Batch {
        double end;        // wall time (s)
        double simulated;  // s
    };
    std::deque<Batch> m_batches;  // those that ended after m_start, oldest first
    double m_start = 0.0;         // wall time the window begins at (s)
};

}  // namespace interplay
