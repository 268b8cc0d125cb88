// The contact solver's colouring (see contact_solver.h): which manifolds may be solved side by
// side, the solver's bodies, and each manifold's lane. Kept from step to step while the contacts
// with points and the bodies' roles stay as they were, since recolouring a resting pile every
// step was a serial pass over all its contacts (pyramid20: 0.2 ms of its 5 ms step at 2 threads).

#include "simcore/dynamics/contact_solver.h"

#include <algorithm>
#include <bit>

namespace simcore {

std::int32_t ContactSolver::solverBody(std::size_t denseIndex, const BodyStorage& bodies) {
    if (bodies.motion[denseIndex] == MotionType::Static) return 0;
    std::int32_t& index = denseToSolver_[denseIndex];
    if (index < 0) {
        index = static_cast<std::int32_t>(references_.size());
        const bool moves = bodies.isAwakeDynamic(denseIndex);
        references_.push_back({static_cast<std::uint32_t>(denseIndex), moves, bodies.centerOfMass[denseIndex],
                               bodies.orientation[denseIndex]});
        bodyColors_.push_back(0);
    }
    return index;
}

bool ContactSolver::bodyRolesChanged(const BodyStorage& bodies) {
    bool changed = colouredBodies_.size() != bodies.size();
    colouredBodies_.resize(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const bool moves = bodies.isAwakeDynamic(i);
        const ColouredBody now{bodies.idAt(i).index, bodies.motion[i] == MotionType::Static ? kStaticRole
                                                     : moves                                ? bodies.inverseMass[i]
                                                                                            : kStillRole};
        changed = changed || !(colouredBodies_[i] == now);
        colouredBodies_[i] = now;
    }
    return changed;
}

// Colour greedily in contact order (deterministic): the lowest colour free at both moving bodies.
// Immovable bodies are only read, so any number of lanes may share them. A manifold that finds no
// free colour goes to the overflow, solved one manifold per batch.
void ContactSolver::colourManifolds(const ContactManager& contactManager, const BodyStorage& bodies) {
    const std::vector<Contact>& contacts = contactManager.contacts();
    // Solver bodies: entry 0 stands for every static body (zero velocity, never moves).
    references_.clear();
    references_.push_back({0, false, Vec3(0.0f), Quat(1.0f, 0.0f, 0.0f, 0.0f)});
    bodyColors_.assign(1, 0);
    denseToSolver_.assign(bodies.size(), -1);
    std::array<std::uint32_t, kColorCount + 1> perColor{};
    order_.clear();
    colorOf_.clear();
    unevenBody_.clear();
    for (std::size_t ci = 0; ci < contacts.size(); ++ci) {
        const Contact& contact = contacts[ci];
        if (!contact.hasPoints()) continue;
        const std::size_t a = bodies.denseIndexOfSlot(contact.slotA);
        const std::size_t b = bodies.denseIndexOfSlot(contact.slotB);
        const bool movesA = bodies.isAwakeDynamic(a);
        const bool movesB = bodies.isAwakeDynamic(b);
        if (!movesA && !movesB) continue;
        const std::int32_t sa = solverBody(a, bodies), sb = solverBody(b, bodies);
        const float inverseMassA = bodies.inverseMass[a], inverseMassB = bodies.inverseMass[b];
        if (movesA && movesB &&
            std::max(inverseMassA, inverseMassB) > kUnevenMassRatio * std::min(inverseMassA, inverseMassB)) {
            unevenBody_.resize(references_.size(), 0);
            unevenBody_[static_cast<std::size_t>(sa)] = unevenBody_[static_cast<std::size_t>(sb)] = 1;
        }
        const std::uint64_t used = (movesA ? bodyColors_[sa] : 0) | (movesB ? bodyColors_[sb] : 0);
        int color = kOverflow;
        if (used != ~std::uint64_t{0}) {
            color = std::countr_zero(~used);
            const std::uint64_t bit = std::uint64_t{1} << color;
            if (movesA) bodyColors_[sa] |= bit;
            if (movesB) bodyColors_[sb] |= bit;
        }
        order_.push_back(static_cast<std::uint32_t>(ci));
        colorOf_.push_back(static_cast<std::uint8_t>(color));
        ++perColor[color];
    }
    constraintCount_ = order_.size();
    unevenBody_.resize(references_.size(), 0);

    // Batches colour by colour, and each colour's entries in contact order.
    std::uint32_t batchCount = 0, entryCount = 0;
    colorCount_ = 0;
    colorsInUse_ = 0;
    for (int color = 0; color <= kColorCount; ++color) {
        colorFirstBatch_[color] = batchCount;
        colorFirstEntry_[color] = entryCount;
        const std::uint32_t lanes = color == kOverflow ? 1 : kLanes;
        batchCount += (perColor[color] + lanes - 1) / lanes;
        entryCount += perColor[color];
        if (perColor[color] > 0) ++colorCount_;
        if (perColor[color] > 0 && color != kOverflow) colorsInUse_ = static_cast<std::size_t>(color) + 1;
    }
    colorFirstBatch_[kOverflow + 1] = batchCount;
    colorFirstEntry_[kOverflow + 1] = entryCount;
    std::array<std::uint32_t, kColorCount + 1> filled{};
    colorEntries_.resize(order_.size());
    for (std::size_t k = 0; k < order_.size(); ++k)
        colorEntries_[colorFirstEntry_[colorOf_[k]] + filled[colorOf_[k]]++] = static_cast<std::uint32_t>(k);
    batches_.resize(batchCount);  // cleared in prepare, batch by batch in parallel (megabytes in pyramid20)
    colouredManifoldList_ = contactManager.manifoldListVersion();
    forgetSchedules();
}

void ContactSolver::refreshBodyReferences(const BodyStorage& bodies) {
    forEachSolverBody([&](std::size_t s) {
        BodyReference& ref = references_[s];
        ref.centerOfMass = bodies.centerOfMass[ref.denseIndex];
        ref.orientation = bodies.orientation[ref.denseIndex];
    });
}

void ContactSolver::assignLanes(const std::vector<Contact>& contacts, const BodyStorage& bodies, float weightImpulse,
                                bool soft) {
    // A pair's weight per substep (N s per kg of reduced mass) is the unit of a manifold's load.
    // A jointed body's contacts also carry what its joints hold, which its own mass does not
    // measure, and a stiffer contact fighting a joint's spring pumps energy into the assembly (a
    // light hull fixed to a heavy box gained 2.6 kJ landing): they keep the base spring.
    stiffening_.resize(order_.size());
    pool_->parallelFor(order_.size(), kEntryGrain, [&](std::size_t, std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            const Contact& contact = contacts[order_[k]];
            const std::size_t a = bodies.denseIndexOfSlot(contact.slotA), b = bodies.denseIndexOfSlot(contact.slotB);
            float stiffening = 1.0f;
            if (soft && weightImpulse > 0.0f && !jointedPair(a, b)) {
                const auto movingInverseMass = [&](std::size_t i) {
                    return bodies.isAwakeDynamic(i) ? bodies.inverseMass[i] : 0.0f;
                };
                const float weights = contact.normalImpulse * (movingInverseMass(a) + movingInverseMass(b)) / weightImpulse;
                stiffening = std::clamp(weights / kStiffLoad, 1.0f, kMaxStiffening);
            }
            stiffening_[k] = stiffening;
        }
    });
    // Last step's lanes are kept to compare: while the lanes stay, so do the schedules (makeSchedule).
    previousLanes_.swap(laneConstraint_);
    laneConstraint_.resize(batches_.size() * kLanes);
    const bool comparable = previousLanes_.size() == laneConstraint_.size();
    const std::array<std::uint32_t, kColorCount + 1> previousStiffEnd = colorStiffEnd_;
    const std::size_t colors = colorsInUse_;  // and the overflow after them
    // The colours are this loop's chunks, of uneven sizes: shared out only when the manifolds are
    // more than one chunk of the loop above. A tower's two colours of ten woke a sleeping worker in
    // every step that tried workers, for less work than the wake-up.
    const std::size_t colorsPerChunk = order_.size() > kEntryGrain ? 1 : colors + 1;
    const std::uint64_t changedColors =
        pool_->parallelSum(colors + 1, colorsPerChunk, [&](std::size_t begin, std::size_t end) {
            std::uint64_t changed = 0;
            for (std::size_t index = begin; index < end; ++index) {
                const std::size_t color = index < colors ? index : kOverflow;
                const std::uint32_t* first = colorEntries_.data() + colorFirstEntry_[color];
                const std::uint32_t* last = colorEntries_.data() + colorFirstEntry_[color + 1];
                const auto stiff = static_cast<std::uint32_t>(
                    std::count_if(first, last, [this](std::uint32_t k) { return stiffening_[k] > 1.0f; }));
                const std::uint32_t lanes = color == kOverflow ? 1 : kLanes;
                colorStiffEnd_[color] = colorFirstBatch_[color] + (stiff + lanes - 1) / lanes;
                std::uint32_t* lane = laneConstraint_.data() + colorFirstBatch_[color] * kLanes;
                std::fill(lane, laneConstraint_.data() + colorFirstBatch_[color + 1] * kLanes, kNoConstraint);
                std::uint32_t filledStiff = 0, filledPlain = stiff;
                for (const std::uint32_t* k = first; k != last; ++k) {
                    const std::uint32_t slot = stiffening_[*k] > 1.0f ? filledStiff++ : filledPlain++;
                    lane[slot / lanes * kLanes + slot % lanes] = *k;
                }
                const std::size_t from = colorFirstBatch_[color] * kLanes, to = colorFirstBatch_[color + 1] * kLanes;
                if (!comparable || colorStiffEnd_[color] != previousStiffEnd[color] ||
                    !std::equal(lane, laneConstraint_.data() + to, previousLanes_.data() + from))
                    ++changed;
            }
            return changed;
        });
    for (std::size_t color = colors; color < kOverflow; ++color) colorStiffEnd_[color] = colorFirstBatch_[color];
    if (changedColors > 0) forgetSchedules();
}

void ContactSolver::makeSchedule(BatchSchedule& schedule, const std::uint32_t* colorEnd, std::size_t threads) {
    const std::size_t colors = colorsInUse_;
    const auto shareBegin = [&](std::size_t color, std::size_t share) {
        const std::size_t first = colorFirstBatch_[color], count = colorEnd[color] - first;
        return static_cast<std::uint32_t>(first + count * share / threads);
    };
    schedule.threads = threads;
    schedule.shareStart.assign(threads + 1, 0);
    for (std::size_t share = 0; share < threads; ++share) {
        std::uint32_t size = 0;
        for (std::size_t color = 0; color < colors; ++color)
            size += shareBegin(color, share + 1) - shareBegin(color, share);
        schedule.shareStart[share + 1] = schedule.shareStart[share] + size;
    }
    schedule.batches.resize(schedule.shareStart[threads]);
    schedule.required.assign(schedule.batches.size() * threads, 0);
    // A batch's moving bodies (one that does not move is only read: its lanes write to scratch rows).
    const auto forEachMovingBody = [this](std::size_t batch, auto&& visit) {
        const ManifoldBatch& c = batches_[batch];
        for (int lane = 0; lane < kLanes; ++lane) {
            if (c.storeA[lane] == c.bodyA[lane]) visit(static_cast<std::size_t>(c.bodyA[lane]));
            if (c.storeB[lane] == c.bodyB[lane]) visit(static_cast<std::size_t>(c.bodyB[lane]));
        }
    };
    // Colour by colour, each share's batches in an order of their own: those touching a body that
    // another share touched last go after the rest, so that the other share has longer to get
    // there. Within a colour no two batches share a moving body, so a share's batches see the
    // colours before through lastShare_ and lastStep_, whatever the shares before it in the colour
    // wrote there.
    constexpr std::uint32_t kNoShare = ~std::uint32_t{0};
    lastShare_.assign(references_.size(), kNoShare);
    lastStep_.resize(references_.size());
    std::array<std::uint32_t, kMaxScheduledThreads> next{};  // each share's next entry
    std::copy_n(schedule.shareStart.begin(), threads, next.begin());
    for (std::size_t color = 0; color < colors; ++color) {
        for (std::uint32_t share = 0; share < threads; ++share) {
            const std::uint32_t begin = shareBegin(color, share), end = shareBegin(color, share + 1);
            std::uint32_t* const segment = schedule.batches.data() + next[share];
            std::uint32_t *first = segment, *last = segment + (end - begin);
            for (std::uint32_t k = begin; k < end; ++k) {
                bool crosses = false;
                forEachMovingBody(k, [&](std::size_t body) {
                    crosses = crosses || (lastShare_[body] != kNoShare && lastShare_[body] != share);
                });
                *(crosses ? --last : first++) = k;
            }
            for (std::uint32_t entry = next[share]; entry < next[share] + (end - begin); ++entry) {
                const std::uint32_t step = entry - schedule.shareStart[share] + 1;
                std::uint32_t* required = schedule.required.data() + std::size_t{entry} * threads;
                forEachMovingBody(schedule.batches[entry], [&](std::size_t body) {
                    if (lastShare_[body] != kNoShare && lastShare_[body] != share)
                        required[lastShare_[body]] = std::max(required[lastShare_[body]], lastStep_[body]);
                    lastShare_[body] = share;
                    lastStep_[body] = step;
                });
            }
            next[share] += end - begin;
        }
    }
}

}  // namespace simcore
