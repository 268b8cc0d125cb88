#pragma once
// Whether a step gains from the pool's workers on this machine, learnt from the steps' own timings
// as the world steps. A stage's results do not depend on which threads ran its chunks
// (task_pool.h), so the choice changes only the time a step takes, never its bits.
//
// Why: a stage's jobs are a few microseconds each (a colour of the solver), and what a second
// thread gains on them depends on the machine. On one 2-core machine two threads stepped pyramid20
// 1.8x faster than one (2026-12-03); on another, whose second core adds little (two independent
// 1-thread runs each slowed by 1.45x), they stepped pyramid10 at 0.64x the speed (2026-12-04). A
// fixed rule (a grain, a minimum size) right for one is wrong for the other; a measurement is
// right for both.
//
// How: the tuner keeps an estimate of the step's time with and without workers (the faster of the
// last two steps that ran it that way: for the way it runs, the latest; for the other, its latest
// probe), runs the way that is faster, and now and then tries the other (a probe) for two steps. A
// step that runs the other way than the step before moves the data to the cores that way keeps it
// on, and the host's preemptions (one step in a few hundred took 40-80 us longer, a tower of 40's
// whole step) only add time too: so two steps one way are judged by the faster, and the first step
// of a probe and the step after it count as the probe's cost (the step after, no more than the
// first: what it takes beyond moving the data is the scene's). (Judged by its first step, an
// inline probe paid for gathering onto one core what the workers had spread over two: pyramid10 at
// 2 threads on cores that share no cache stepped at 1.75 ms with workers, 1.9 ms in the probe, and
// kept the workers; 1 thread took 1.27 ms, 2026-12-06.) A probe that confirms the choice doubles
// the time to the next one (up to kMaxProbeInterval steps, so a settled choice costs almost nothing
// to check), and the next probe also waits until the chosen way has run long enough for the
// probe's loss (or the learning's, before the first probe) to be at most kProbeCostShare of that
// time: on a step of microseconds a probe that wakes the workers costs several steps (a tower of 40
// stepped 0.92x as fast on 2 threads as on 1, 2026-12-06). A probe that lost, but took less than
// the chosen way's steps after it, ran while the scene's step grew: the next one comes soon. A
// probe that wins switches and starts probing often again, as a scene that grows or falls asleep
// can change the answer.

#include <algorithm>
#include <cmath>
#include <utility>

namespace simcore {

class WorkerTuner {
public:
    static constexpr int kMinProbeInterval = 8;    // steps
    static constexpr int kMaxProbeInterval = 256;  // steps: about 4 s at 60 Hz
    // The other way must be this much faster to be chosen: timing noise alone does not flip it.
    static constexpr double kSwitchRatio = 0.95;
    static constexpr double kProbeCostShare = 0.02;
    // A step whose time has grown or shrunk this many times since the choice was made probes at
    // the next step the probes' cost allows, not after the interval.
    static constexpr double kRejudgeFactor = 2.0;

    // Which way is learnt first: the tuner runs that way in its first two steps, the other way in
    // two, and the first way again in two, each time learning from the faster of the two (a world's
    // first step makes every pair and manifold: pyramid20 45-70 ms, then about 12), then the
    // faster. The first way's time is the mean of its two, which cancels a scene's own trend: a
    // tower of 40 settling took 0.046, 0.054 and 0.058 ms in steps 1, 3 and 5 at 1 thread, and
    // learnt from steps 1 and 3 alone, 2 threads chose workers in 4 runs of 6 and ran 30 steps each
    // 10 us slower (2026-12-07).
    enum class FirstWay { Inline, Workers };
    WorkerTuner() = default;
    explicit WorkerTuner(FirstWay firstWay) : first_(firstWay == FirstWay::Workers ? kWorkers : kInline) {}

    // Whether this step runs with workers.
    bool useWorkers() const {
        if (!learnt()) return (measurements_ == 1 ? 1 - first_ : first_) == kWorkers;
        return probeDue() ? !workersChosen_ : workersChosen_;
    }

    // The time of a step that ran as useWorkers() said.
    void record(double ms) {
        const int way = useWorkers() ? kWorkers : kInline;
        const bool probing = learnt() && probeDue();
        const double previousMs = std::exchange(previousMs_, ms);
        const bool afterProbe = std::exchange(lastStepProbed_, probing);
        if (way != lastWay_) {  // the step moved the data: not this way's time
            lastWay_ = way;
            if (!learnt()) return;  // learning: the next step is learnt from
            const double excessMs = std::max(0.0, ms - estimateMs_[chosen()]);
            // Back after a probe that lost, moving the data back costs what moving it out did; more
            // is the scene's own change. mixed1k's step grew from 0.5 to 1.3 ms as its bodies
            // landed, and charged in full, the step back put off the next probe by 39 ms, past the
            // landing (2026-12-07).
            if (probing) probeMoveMs_ = excessMs;  // the probe's first step; it goes on
            else if (afterProbe) msToProbe_ += std::min(excessMs, probeMoveMs_) / kProbeCostShare;
            // Otherwise the step follows the learning, or steps the tuner was not told about (with
            // nothing the workers could share): what it takes now is not a probe's cost.
            return;
        }
        // This step and the one before ran this way. Their faster is its time, not an average over
        // more: in pile1k the step grew from 0.35 to 2 ms in 13 steps as the boxes landed, and a
        // probe of workers judged against the inline steps' average, which lagged, lost in 2 runs
        // of 4 and left 17 steps inline (2026-12-07).
        const double wayMs = std::min(ms, previousMs);
        if (!learnt()) {
            learn(way, wayMs);
            return;
        }
        estimateMs_[way] = wayMs;
        if (probing) {
            if (estimateMs_[way] < kSwitchRatio * estimateMs_[chosen()]) {
                workersChosen_ = way == kWorkers;
                probeInterval_ = kMinProbeInterval;
                msToProbe_ = 0.0;
            } else {
                probeInterval_ = std::min(2 * probeInterval_, kMaxProbeInterval);
                const double lossMs = probeMoveMs_ + std::max(0.0, estimateMs_[way] - estimateMs_[chosen()]);
                msToProbe_ = lossMs / kProbeCostShare;
                probeLost_ = true;
            }
            stepsToProbe_ = probeInterval_;
            decidedMs_ = estimateMs_[chosen()];
        } else {
            // Chosen while the scene was another size: pile1k's solve took 0.03 ms a step when the
            // first boxes landed, when inline was right, and 1 ms twenty steps later, and stayed
            // inline for the rest of the scene in 2 runs of 5 (2026-12-07).
            if (wayMs > kRejudgeFactor * decidedMs_ || kRejudgeFactor * wayMs < decidedMs_) {
                decidedMs_ = wayMs;
                stepsToProbe_ = 0;
            }
            if (stepsToProbe_ > 0) --stepsToProbe_;
            msToProbe_ -= ms;
            // The first two steps back after a probe that lost: if they took longer than the probe,
            // the scene's step grew while it ran, and the probe lost to the steps before it, not
            // to the way. Its loss is not the way's, and the next probe comes soon. pile1k at 2
            // threads, cores far apart (2026-12-07): an inline probe in step 54 took 1.10 ms
            // against 0.83 before it, the workers' steps after it 1.3 and 1.1, then 0.73-0.86
            // where inline took 0.6, and the loss put the next probe off past the scene's sleep.
            // In 80 rounds with the cores far, 2 threads took 1.046 of 1 thread's time on pile1k
            // before this and 1.015 after (pyramid10 1.026 -> 1.013, mixed1k 1.023 -> 1.011); in
            // 1303 rounds with them near, the same time to within 0.4%.
            if (probeLost_) {
                if (estimateMs_[1 - way] < wayMs) {  // the other way's estimate is the probe's time
                    msToProbe_ = 0.0;
                    stepsToProbe_ = std::min(stepsToProbe_, kMinProbeInterval);
                }
                probeLost_ = false;
            }
        }
    }

private:
    static constexpr int kInline = 0, kWorkers = 1;
    static constexpr int kNone = -1;
    static constexpr int kLearningMeasurements = 3;  // first way, other way, first way again
    bool learnt() const { return measurements_ == kLearningMeasurements; }
    bool probeDue() const { return stepsToProbe_ == 0 && msToProbe_ <= 0.0; }
    int chosen() const { return workersChosen_ ? kWorkers : kInline; }
    void learn(int way, double ms) {
        double& estimate = estimateMs_[way];
        estimate = estimate < 0.0 ? ms : 0.5 * (estimate + ms);
        if (++measurements_ < kLearningMeasurements) return;
        // The faster to start. The first probe waits as after one that lost what the slower way's
        // two steps did: pyramid20 at 2 threads lost 10 ms in a probe 8 steps after learning, 8% of
        // the benchmark's 120 steps.
        workersChosen_ = estimateMs_[kWorkers] < estimateMs_[kInline];
        decidedMs_ = estimateMs_[chosen()];
        stepsToProbe_ = probeInterval_;
        msToProbe_ = 2.0 * std::abs(estimateMs_[kWorkers] - estimateMs_[kInline]) / kProbeCostShare;
    }

    int first_ = kInline;                  // or kWorkers
    double estimateMs_[2] = {-1.0, -1.0};  // by way; negative: not measured yet
    int measurements_ = 0;                 // learning steps measured, up to kLearningMeasurements
    bool workersChosen_ = false;
    int probeInterval_ = kMinProbeInterval;
    int stepsToProbe_ = 0;         // steps the choice runs before the next probe
    double msToProbe_ = 0.0;       // and its time (ms) before it, after a probe that lost
    double probeMoveMs_ = 0.0;     // the probe's first step over the chosen way's estimate
    double previousMs_ = 0.0;      // the last step's time
    double decidedMs_ = 0.0;       // the chosen way's time when it was chosen (or confirmed)
    bool probeLost_ = false;       // the last probe lost, and no step since has been compared with it
    bool lastStepProbed_ = false;  // whether the last step was a probe's
    int lastWay_ = kNone;          // the way the last step ran
};

}  // namespace simcore
