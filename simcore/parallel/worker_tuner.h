#pragma once
// Which of a step's stages gain from the pool's workers on this machine, learnt from the stages'
// own timings as the world steps. A stage's results do not depend on which threads ran its chunks
// (task_pool.h), so the choice changes only the time a step takes, never its bits.
//
// Why: a stage's jobs are a few microseconds each (a colour of the solver), and what a second
// thread gains on them depends on the machine. On one 2-core machine two threads stepped pyramid20
// 1.8x faster than one (2026-12-03); on another, whose second core adds little (two independent
// 1-thread runs each slowed by 1.45x), they stepped pyramid10 at 0.64x the speed (2026-12-04). A
// fixed rule (a grain, a minimum size) right for one is wrong for the other; a measurement is
// right for both.
//
// How: each stage keeps an estimate of its time per unit of work with and without workers (the
// faster of the last two steps that ran it that way: for the way it runs, the latest; for the
// other, its latest probe), runs the way that is faster, and now and then tries the other (a probe)
// for two steps. A step that runs a stage the other way than the step before moves the stage's data
// to the cores that way keeps it on, and the host's preemptions (one step in a few hundred took
// 40-80 us longer, a tower of 40's whole step) only add time too: so two steps one way are judged
// by the faster, and the first step of a probe and the step after it count as the probe's cost
// (the step after, no more than the first: what it takes beyond moving the data is the scene's).
// (Judged by its first step, an inline probe paid for gathering onto one core what the workers had
// spread over two: pyramid10 at 2 threads on cores that share no cache stepped at 1.75 ms with
// workers, 1.9 ms in the probe, and kept the workers; 1 thread took 1.27 ms, 2026-12-06.) A probe
// that confirms the choice doubles the time to the next one (up to kMaxProbeInterval steps, so a
// settled choice costs almost nothing to check), and the next probe also waits until the chosen way
// has run long enough for the probe's loss (or the learning's, before the first probe) to be at
// most kProbeCostShare of that time: on a step of microseconds a probe that wakes the workers costs
// several steps (a tower of 40 stepped 0.92x as fast on 2 threads as on 1, 2026-12-06). A probe
// that wins switches and starts probing often again, as a scene that grows or falls asleep can
// change the answer.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

namespace simcore {

template <std::size_t Stages>
class WorkerTuner {
public:
    static constexpr int kMinProbeInterval = 8;    // steps
    static constexpr int kMaxProbeInterval = 256;  // steps: about 4 s at 60 Hz
    // The other way must be this much faster to be chosen: timing noise alone does not flip it.
    static constexpr double kSwitchRatio = 0.95;
    static constexpr double kProbeCostShare = 0.02;
    // A stage whose time has grown or shrunk this many times since its choice was made probes at
    // the next step its probes' cost allows, not after the interval.
    static constexpr double kRejudgeFactor = 2.0;

    // Which way a stage is learnt first: it runs that way in its first two steps, the other way in
    // two, and the first way again in two, each time learning from the faster of the two (a world's
    // first step makes every pair and manifold: pyramid20 45-70 ms, then about 12), then the
    // faster. The first way's time is the mean of its two, which cancels a scene's own trend: a
    // tower of 40 settling took 0.046, 0.054 and 0.058 ms in steps 1, 3 and 5 at 1 thread, and
    // learnt from steps 1 and 3 alone, 2 threads chose workers in 4 runs of 6 and ran 30 steps each
    // 10 us slower (2026-12-07).
    enum class FirstWay { Inline, Workers };
    WorkerTuner() = default;
    explicit WorkerTuner(FirstWay firstWay) : first_(firstWay == FirstWay::Workers ? kWorkers : kInline) {}

    // Whether this step runs `stage` with workers.
    bool useWorkers(std::size_t stage) const {
        const StageState& state = states_[stage];
        if (!state.learnt()) return (state.measurements == 1 ? 1 - first_ : first_) == kWorkers;
        return state.probeDue() ? !state.workersChosen : state.workersChosen;
    }

    // Whether the stage is still learning (first way, other way, first way again).
    bool learning(std::size_t stage) const { return !states_[stage].learnt(); }
    // Whether useWorkers(stage) is not the settled choice this step: learning, or a probe.
    bool exploring(std::size_t stage) const { return learning(stage) || states_[stage].probeDue(); }

    // The stage's time in a step that ran it as useWorkers said, and the work it did there in any
    // unit proportional to its time on one thread (1 where the stage has none): ways are compared
    // by time per unit of work. A stage whose work changes from step to step is judged unfairly by
    // its time alone: mixed1k's solver did 1000 to 4900 batches a step as its bodies landed, taking
    // 0.19-0.44 us a batch inline and 0.13-0.33 with workers, and a probe of workers judged by time
    // lost against the lighter step before it in 3 runs of 6, leaving the solver inline through
    // the landing. Judged by time per batch, mixed1k at 2 threads took 0.098 ms a step against
    // 0.109 (medians of 10 alternating runs, 2026-12-07).
    void record(std::size_t stage, double ms, double work = 1.0) {
        StageState& state = states_[stage];
        const int way = useWorkers(stage) ? kWorkers : kInline;
        const bool probing = state.learnt() && state.probeDue();
        const double rate = ms / std::max(work, kMinWork);  // ms per unit of work
        const double previousRate = std::exchange(state.previousRate, rate);
        const bool afterProbe = std::exchange(state.lastStepProbed, probing);
        const auto chosen = [&state] { return state.workersChosen ? kWorkers : kInline; };
        if (way != state.lastWay) {  // the step moved the stage's data: not this way's time
            state.lastWay = way;
            if (!state.learnt()) return;  // learning: the next step is learnt from
            const double excessMs = std::max(0.0, ms - state.estimateRate[chosen()] * work);
            // Back after a probe that lost, moving the data back costs what moving it out did; more
            // is the scene's own change. mixed1k's step grew from 0.5 to 1.3 ms as its bodies
            // landed, and charged in full, the step back put off the next probe by 39 ms, past the
            // landing (2026-12-07).
            if (probing)
                state.probeMoveMs = excessMs;  // the probe's first step; it goes on
            else if (afterProbe) state.msToProbe += std::min(excessMs, state.probeMoveMs) / kProbeCostShare;
            // Otherwise the stage has not been timed for a while (the world's stages learn only in
            // steps that use workers): what it takes now is not a probe's cost. Charged as one,
            // mixed1k's prepare and solver, timed last in the learning at 0.07 ms a step and again
            // when the step took workers 47 steps later at 0.45, put off their next probe by 19 ms
            // of steps, past the boxes' landing (2026-12-07).
            return;
        }
        // This step and the one before ran this way. Their faster is its time, not an average over
        // more: in pile1k the step grew from 0.35 to 2 ms in 13 steps as the boxes landed, and a
        // probe of workers judged against the inline steps' average, which lagged, lost in 2 runs
        // of 4 and left 17 steps inline (2026-12-07).
        const double wayRate = std::min(rate, previousRate);
        if (!state.learnt()) {
            learn(state, way, wayRate, work);
            return;
        }
        state.estimateRate[way] = wayRate;
        if (probing) {
            if (state.estimateRate[way] < kSwitchRatio * state.estimateRate[chosen()]) {
                state.workersChosen = way == kWorkers;
                state.probeInterval = kMinProbeInterval;
                state.msToProbe = 0.0;
            } else {
                state.probeInterval = std::min(2 * state.probeInterval, kMaxProbeInterval);
                const double lossMs =
                    state.probeMoveMs + std::max(0.0, state.estimateRate[way] - state.estimateRate[chosen()]) * work;
                state.msToProbe = lossMs / kProbeCostShare;
            }
            state.stepsToProbe = state.probeInterval;
            state.decidedMs = state.estimateRate[chosen()] * work;
        } else {
            // Chosen while it was another size of job: pile1k's solve took 0.03 ms a step when the
            // first boxes landed, when inline was right, and 1 ms twenty steps later, and stayed
            // inline for the rest of the scene in 2 runs of 5 (2026-12-07).
            const double wayMs = wayRate * work;
            if (wayMs > kRejudgeFactor * state.decidedMs || kRejudgeFactor * wayMs < state.decidedMs) {
                state.decidedMs = wayMs;
                state.stepsToProbe = 0;
            }
            if (state.stepsToProbe > 0) --state.stepsToProbe;
            state.msToProbe -= ms;
        }
    }

private:
    static constexpr int kInline = 0, kWorkers = 1;
    static constexpr int kNone = -1;
    static constexpr int kLearningMeasurements = 3;  // first way, other way, first way again
    static constexpr double kMinWork = 1e-9;         // what a stage that reports no work is taken to do
    struct StageState {
        double estimateRate[2] = {-1.0, -1.0};  // ms per unit of work, by way; negative: not measured yet
        int measurements = 0;                   // learning steps measured, up to kLearningMeasurements
        bool workersChosen = false;
        int probeInterval = kMinProbeInterval;
        int stepsToProbe = 0;          // steps the choice runs before the next probe
        double msToProbe = 0.0;        // and its time (ms) before it, after a probe that lost
        double probeMoveMs = 0.0;      // the probe's first step over the chosen way's estimate
        double previousRate = 0.0;     // the last step's time per unit of work
        double decidedMs = 0.0;        // the chosen way's time when it was chosen (or confirmed)
        bool lastStepProbed = false;   // whether the last step was a probe's
        int lastWay = kNone;           // the way the last step ran
        bool learnt() const { return measurements == kLearningMeasurements; }
        bool probeDue() const { return stepsToProbe == 0 && msToProbe <= 0.0; }
    };
    static void learn(StageState& state, int way, double rate, double work) {
        double& estimate = state.estimateRate[way];
        estimate = estimate < 0.0 ? rate : 0.5 * (estimate + rate);
        if (++state.measurements < kLearningMeasurements) return;
        // The faster to start. The first probe waits as after one that lost what the slower way's
        // two steps did: pyramid20 at 2 threads lost 10 ms in a probe 8 steps after learning, 8% of
        // the benchmark's 120 steps.
        state.workersChosen = state.estimateRate[kWorkers] < state.estimateRate[kInline];
        state.decidedMs = state.estimateRate[state.workersChosen ? kWorkers : kInline] * work;
        state.stepsToProbe = state.probeInterval;
        state.msToProbe =
            2.0 * std::abs(state.estimateRate[kWorkers] - state.estimateRate[kInline]) * work / kProbeCostShare;
    }
    int first_ = kInline;  // or kWorkers
    std::array<StageState, Stages> states_{};
};

}  // namespace simcore
