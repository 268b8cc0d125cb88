#pragma once
// Sequential impulses on contact manifolds: accumulated impulses with clamping, warm starting,
// Coulomb friction per manifold (two tangent rows at the friction centre and a twist row, bounded
// by the summed normal impulse), rolling resistance per manifold (an angular block bounded by the
// contact's rolling lever times the summed normal impulse), restitution above a velocity
// threshold, speculative contacts, soft-step or Baumgarte position correction, and soft-step
// springs stiffened by the load a manifold carries (kStiffLoad) and offset by their give under it
// (kGiveOffsetRate).
//
// Within one World::step the solver is used as:
//   prepare (once) -> for each substep { [resolveCollisions, first substep only], warmStart,
//   solve(useBias=true) x N, [positions move, followPositions], [resolveCollisions], relax =
//   solve(useBias=false) x M, then relaxWherePushing (and joints) while a deep overlap still
//   pushes } -> storeImpulses,
// with resolveCollisions only when usesRestitution(). Friction and rolling resistance are solved
// in the relax passes (in the velocity passes when there are none); friction also in the velocity
// passes of a manifold that impacts. Within a pass a manifold's normal rows are swept until they
// stop changing each other (kMaxNormalSweeps). Each velocity pass (solve with useBias) ends with up
// to kStiffPasses more over the batches of the stiffened manifolds.
//
// Restitution is a collision pass before the contact solve (as in Guendelman, Bridson and Fedkiw
// 2003): every point that closes faster than the restitution threshold and would touch within a
// substep gets an impulse that reverses its normal velocity, times the restitution, with friction
// bounded by that impulse; the pass repeats while anything collided, so an impact travels through
// a row of touching bodies (Newton's cradle) as a sequence of two-body collisions instead of being
// shared out by the contact solve. Each such collision conserves momentum and cannot add energy.
//
// Data parallel: prepare colours the manifolds so that no two of one colour share a moving body,
// and packs each colour into batches of simd::kWidth manifolds, one per lane, in structure-of-
// arrays form. A batch is solved in one pass of wide arithmetic; colours run one after another,
// which is Gauss-Seidel between colours and exact within one (its lanes touch disjoint bodies).
// The batches of one colour touch disjoint moving bodies too, so they run on the pool's threads;
// each writes back only its moving bodies' velocities (a static or sleeping body, which any number
// of batches share, is only read), so the result is the same for any thread count.

#include "simcore/dynamics/contact_manager.h"
#include "simcore/dynamics/body_storage.h"
#include "simcore/dynamics/joint_storage.h"
#include "simcore/dynamics/constraint_math.h"
#include "simcore/math/simd.h"
#include "simcore/parallel/large_array_allocator.h"
#include "simcore/parallel/task_pool.h"
#include "simcore/world_settings.h"

#include <array>
#include <cstdint>
#include <vector>

namespace simcore {

class ContactSolver {
public:
    struct Params {
        float substepDt = 1.0f / 240.0f;
        float timeStep = 1.0f / 60.0f;  // s, the whole step: storeImpulses moves the give offsets once per step
        bool friction = true;
        bool restitution = true;
        Vec3 gravity{0.0f};  // m/s^2 when the gravity effect runs: impacts account for it (resolveCollisions)
        SolverSettings solver;
        ContactSettings contact;
    };

    // Builds constraints for touching contacts with an awake dynamic body. Sleeping and static
    // bodies take part with infinite mass. The passes until the next prepare run on `pool`.
    void prepare(const ContactManager& contactManager, const BodyStorage& bodies, const JointStorage& joints,
                 const Params& params, TaskPool& pool);
    // After the warm start the velocities go back to the bodies, or stay in the solver's rows for
    // the solve that follows, where nothing else reads or changes them in between (no joints):
    // storing 1000 bodies' velocities only to load them again took both passes over every body,
    // and with 2 threads carried every row to the caller and back.
    enum class AfterWarmStart { Store, HoldForSolve };
    void warmStart(BodyStorage& bodies, AfterWarmStart after);
    // The bodies moved (a substep's position update): the passes after this one see the new
    // separations. Positions stand still between position updates, so the passes in between share
    // the bodies' motion since prepare and each manifold's separations.
    void followPositions(const BodyStorage& bodies);
    // `passes` passes in a row. After relax passes (useBias false) returns whether in the last some
    // normal row of an overlap deeper than the slop still changed a relative velocity by more than
    // kRelaxTolerance: push velocity is still being taken out. After velocity passes, false.
    bool solve(BodyStorage& bodies, bool useBias, int passes);
    // Up to `passes` relax passes after the configured ones, while the last still took push
    // velocity out, each over only the manifolds with a body whose velocity a row changed by more
    // than kRelaxTolerance in the pass before or in this one so far (World runs kMaxExtraRelaxPasses
    // in all; one at a time between joint passes). Returns whether push velocity was still being
    // taken out.
    bool relaxWherePushing(BodyStorage& bodies, int passes);
    // The substep's last pass over the contacts of bodies of uneven mass (kUnevenMassRatio): each
    // moves only the body further from the ground, counted in contacts (supportDepth_), as if the
    // one under it were immovable (bodies at one depth are left as the relax passes left them), and
    // its impulses are not kept. Gauss-Seidel passes take a heavy body's push out only about the
    // mass ratio's share at a time, and what was left threw it and the light bodies under it about: with restitution 0, Box2D's 400:1 box left its supports at
    // 0.26 m/s and pushed one 36 cm sideways, and the figures moved from 0.26 to 0.8 m/s and 4 to
    // 27 cm with the supports placed 10 um aside; with this pass, 0.03 m/s and 5-8 mm at any of
    // those placements. Kept, its impulses warm-started the next substep pressing the light bodies
    // down with what they had not pushed, and a pyramid carrying 300:1 boxes fell. Bouncy contacts
    // (restitution above 0) and jointed bodies keep the ordinary passes' answer.
    void settleOnSupports(BodyStorage& bodies);
    // m/s. Deep overlaps in a stack leave push velocity that one pass cannot remove: ten cubes
    // overlapping by a quarter threw the top one at 6.5 m/s. Where a heavy body presses a light one
    // into the ground, Gauss-Seidel passes each take out only about the mass ratio's share: Jolt's
    // 50:1 box on a light one left at 7.3 m/s with restitution 0 after 3 more passes, 0.06 m/s after
    // 100. After kEvenExtraRelaxPasses only contacts of a body touching another moving one whose
    // mass differs by more than kUnevenMassRatio keep the passes going (the light box's contact
    // with the ground among them): a heap of like bodies (mixed1k's landings) would otherwise take
    // 11-30 passes in a third of its substeps, tripling the relax stage's cost.
    static constexpr float kRelaxTolerance = 0.1f;
    static constexpr int kMaxExtraRelaxPasses = 100;
    static constexpr int kEvenExtraRelaxPasses = 3;
    static constexpr float kUnevenMassRatio = 4.0f;
    // A manifold's normal rows are swept again within a pass, up to kMaxNormalSweeps times, while a
    // row still changes its relative velocity by more than kSweepTolerance (m/s). Rows solved once
    // each, one after another, let the first point of a symmetric impact take most of it: a bar
    // dropped edge first was rolled out of its plane at 27 rad/s, a box landing flat was tipped and
    // then slid. Resting contacts, warm started, settle in one sweep.
    static constexpr int kMaxNormalSweeps = 8;
    static constexpr float kSweepTolerance = 0.01f;
    // Loaded manifolds are stiffer. The soft contact's spring gives under its load, load / (row
    // mass * omega^2): a tower of 40 cubes sank 11 cm (16 cm while the load first came down) with
    // the same spring at every contact. A manifold whose normal impulse in the last substep was
    // more than kStiffLoad times its pair's weight (reduced mass times gravity times the substep)
    // gets a spring stiffer by that ratio / kStiffLoad, up to kMaxStiffening (hertz times its
    // square root). Springs past the substep cap need a solve that converges further, or they
    // shake a stack apart (Box3D's Jenga port: 15 cm to 6.5 m sideways): after each velocity pass
    // the batches holding such manifolds (first in each colour) are solved again, up to
    // kStiffPasses times, while one of their rows still changed a velocity by more than
    // kStiffTolerance, each time only those next to such a change. A resting tower, warm started,
    // needs none; 5 cm cubes in a pyramid need the tolerance this fine.
    static constexpr float kStiffLoad = 4.0f;
    static constexpr float kMaxStiffening = 2.0f;
    static constexpr int kStiffPasses = 3;
    static constexpr float kStiffTolerance = 0.003f;  // m/s
    // Loaded contacts rest nearly touching. A soft spring holds its load only pressed in by its
    // give, and the gives add up along a stack: 1.1 cm under a pyramid of 5 cm cubes 30 rows
    // high, 4 cm under a stack of 30 wheels. Each manifold's spring acts as though its points were
    // deeper by the manifold's give offset (ManifoldRecord::giveOffset), which storeImpulses moves
    // once per step, at kGiveOffsetRate per second, towards what would leave the points' mean
    // overlap at kRestingGive times the spring's give under the manifold's load (its normal
    // impulse / (row mass * omega^2 * substep)), and holds at no more than kMaxGiveOffset times
    // that give, so that a manifold pressed by more than its load (a wedge, bodies created
    // overlapping) does not wind the offset up. Brought to touching (kRestingGive 0) that wall of
    // 5 cm cubes, one cube deep, leaned out of its plane and fell within 25 s with sleeping off:
    // boxes that only touch lose and regain their face contact as they rock; pressed by 0.3 of
    // the give it stands 40 s. A faster rate (6 per second) kept the pyramid from sleeping within
    // 10 s; a slower one (1.2) left the wheel stack asleep before its offsets caught up. Jointed
    // bodies keep no offset, for the reason they keep the base spring (prepare).
    static constexpr float kGiveOffsetRate = 3.0f;  // 1/s
    static constexpr float kRestingGive = 0.3f;
    static constexpr float kMaxGiveOffset = 1.5f;
    // When the collision pass runs: after the substep's velocity update and before the position
    // update (the first substep), or after the position update.
    enum class ImpactTiming { BeforePositions, AfterPositions };
    void resolveCollisions(BodyStorage& bodies, ImpactTiming timing);
    void storeImpulses(ContactManager& contactManager) const;

    std::size_t constraintCount() const { return constraintCount_; }
    std::size_t colorCount() const { return colorCount_; }
    // Whether any prepared constraint has friction or rolling-resistance rows / can bounce (effects
    // that ran; rolling resistance belongs to the friction effect).
    bool usesFriction() const { return usesFriction_; }
    bool usesRestitution() const { return usesRestitution_; }
    float maxPenetration() const { return maxPenetration_; }  // at prepare time (m)

private:
    using FloatW = simd::FloatW;
    static constexpr int kLanes = simd::kWidth;
    // Collision passes per substep at most: enough for an impact to cross a row of this many
    // touching bodies in the worst solve order. Most substeps stop after the first pass.
    static constexpr int kMaxCollisionPasses = 8;
    // Colours at most; a manifold that finds none free goes to the overflow, one manifold per batch,
    // whose batches may share bodies and so run one after another.
    static constexpr int kColorCount = 64;
    static constexpr int kOverflow = kColorCount;
    // Batches per chunk of a colour run in parallel: a batch costs a few hundred nanoseconds, more
    // than taking a chunk from a thread's own share. Two, so that the 11 to 31 batches of
    // pyramid10's colours split evenly between two threads (with 4, a colour of 5 chunks went 2 and
    // 3): its step at 2 threads 0.7-1.4% shorter, pyramid20's unchanged; 8 was 3-4% longer.
    static constexpr std::size_t kBatchGrain = 2;
    // Manifolds per chunk of finding their stiffening: a few microseconds of work.
    static constexpr std::size_t kEntryGrain = 2048;
    // Solver bodies per chunk of loading and storing their rows: a few microseconds of work.
    static constexpr std::size_t kBodyGrain = 1024;
    // Slices of each colour per thread when filling and storing (forEachColorSlice): more than one,
    // so a thread that finishes first can take over part of a late one's; but a slice of at least
    // kMinBatchesPerSlice batches in all: a tower of 40 (6 batches) split in two took about 4%
    // longer a step at 2 threads than filled on one.
    static constexpr std::size_t kSlicesPerThread = 4;
    static constexpr std::size_t kMinBatchesPerSlice = 16;

    // One contact point in every lane: anchors relative to each centre of mass at prepare (world
    // axes), the normal row's levers, effective mass and accumulated impulse.
    struct PointBatch {
        FloatW anchorA[3], anchorB[3];
        FloatW angularA[3], angularB[3];  // anchor x normal: the normal row's lever on each body
        FloatW baseSeparation;  // m, at prepare
        FloatW separation;      // m, at the last position update (ManifoldBatch::separationMotion)
        FloatW leverArm;        // m, from the friction centre: the reach of its twist friction
        FloatW normalMass, normalImpulse;
    };
    // kLanes manifolds. Unused lanes and points have zero masses and so change nothing.
    struct ManifoldBatch {
        std::int32_t bodyA[kLanes], bodyB[kLanes];  // solver body indices (0: the immovable body)
        // The rows the pass writes back to: the body's own where it moves, else this batch's scratch
        // row, so that batches running side by side never write a row another one reads.
        std::int32_t storeA[kLanes], storeB[kLanes];
        FloatW inverseMassA, inverseMassB;
        FloatW inverseInertiaA[6], inverseInertiaB[6];  // world, at prepare: xx yy zz xy xz yz
        FloatW biasRate, massScale, impulseScale;        // each lane's soft spring (SoftConstraint)
        FloatW normal[3], tangent1[3], tangent2[3];     // normal from A to B
        FloatW friction, restitution;
        // 1 where a point of a pair with friction approached faster than the restitution threshold
        // at prepare. Such manifolds solve friction in the velocity passes too: friction held back
        // for the relax passes met the impact's whole normal impulse at once and sent a bar dropped
        // at 100 m/s back up at 5 m/s. Resting lanes keep Box3D's order (see solve).
        FloatW impacting;
        // The spring acts as though the points were giveOffset deeper (m). givePerImpulse is
        // 1 / (substep * omega^2): a row gives impulse * givePerImpulse / row mass under its load.
        // Both 0 where the manifold keeps no offset (kGiveOffsetRate).
        FloatW giveOffset, givePerImpulse;
        // Friction acts on the manifold as a whole (as in Box3D): a two-row block at the friction
        // centre, the mean of the points, bounded by friction times the summed normal impulse, and
        // a twist row about the normal bounded by friction times each point's impulse times its
        // lever arm. Per-point friction rows, solved one after another, let the order of the
        // corners turn a resting box and couple the side faces of neighbours in a pyramid.
        // At a centre off the bodies' centres of mass (a bar resting on two crossing bars) a tangent
        // impulse also turns the bodies about the normal: the twist impulse is found from the
        // three rows together (the third row of the 3x3 block's inverse), then the tangent block
        // from the twist it left. Twist solved alone left that turn for the next pass, and a
        // Jenga tower of 30 layers swayed 3.3 cm as it screwed round.
        FloatW centerA[3], centerB[3];               // the friction centre from each centre of mass
        FloatW tangentMass[3];                       // inverse of the 2x2 tangent block: 11, 22, 12
        FloatW twistMass[3];                         // third row of the 3x3 block's inverse: 31, 32, 33
        FloatW tangentImpulse1, tangentImpulse2;     // N s
        FloatW twistImpulse;                         // N m s
        // Rolling resistance (as in Box3D): a three-row block on the relative angular velocity
        // wB - wA with the mass matrix (IA^-1 + IB^-1)^-1, its accumulated angular impulse clamped
        // to the ball of radius rollingLever times the summed normal impulse. Zero where the pair
        // has no rolling resistance.
        FloatW rollingLever;                         // m: Contact::rollingLever
        FloatW rollingMass[6];                       // (IA^-1 + IB^-1)^-1: xx yy zz xy xz yz
        FloatW rollingImpulse[3];                    // N m s, on B (-rollingImpulse on A), world
        // Sphere and capsule radii (0 for other shapes). Rolling turns a round body's surface point
        // away from the contact without changing the gap, so the separation follows the anchors'
        // projections on the core (centre or segment) instead.
        FloatW radiusA, radiusB;
        PointBatch points[kMaxManifoldPoints];
        std::uint32_t contactIndex[kLanes];
        std::uint8_t pointCount[kLanes];
        std::uint8_t maxPointCount;
        std::uint32_t separationMotion;  // the motion_ (motionCount_) the points' separations are at
        bool anyFriction, anyRolling, anyRestitution, anyImpact;
        bool stiff;  // holds a manifold with a stiffened spring
    };
    // Per solver body, rows of 8 floats for the wide gathers: velocity (linear xyz, pad, angular
    // xyz, pad) and motion since prepare (centre of mass xyz, pad, rotation quaternion xyzw).
    struct alignas(32) BodyRow {
        float value[8];
    };
    struct BodyReference {
        std::uint32_t denseIndex;
        bool moves;  // awake and dynamic: velocities are written back
        Vec3 centerOfMass;
        Quat orientation;
    };

    std::int32_t solverBody(std::size_t denseIndex, const BodyStorage& bodies);
    // What colouring the manifolds reads of a body: which body has the dense index (its slot), and
    // whether it is static, or moves (and then with what inverse mass, for kUnevenMassRatio).
    struct ColouredBody {
        std::uint32_t slot;
        float role;  // kStaticRole, kStillRole (kinematic or asleep), or the inverse mass of a moving body
        bool operator==(const ColouredBody&) const = default;
    };
    static constexpr float kStaticRole = -2.0f, kStillRole = -1.0f;
    // Whether a body's slot or role changed since the last call (the first call: true); records them.
    bool bodyRolesChanged(const BodyStorage& bodies);
    // The manifolds' colours, solver bodies and batches, from the contacts with points in contact
    // order: a pure function of the contact list and the bodies' roles, so prepare keeps them from
    // step to step while neither changes (a resting pyramid's never do after its first step), and
    // refreshes only the solver bodies' poses (refreshBodyReferences).
    void colourManifolds(const ContactManager& contactManager, const BodyStorage& bodies);
    void refreshBodyReferences(const BodyStorage& bodies);
    // Each manifold's stiffening, from the load it carried last step, and its lane: in each colour
    // the stiffened manifolds first. Colour by colour on the pool's threads.
    void assignLanes(const std::vector<Contact>& contacts, const BodyStorage& bodies, float weightImpulse, bool soft);
    // Which batches a pass solves: all; those holding a stiffened manifold with a body marked
    // (changedInPass_) in this pass or the one before; in the restricted relax passes, any batch
    // with such a body.
    enum class PassScope { All, Stiff, Pushing };
    // One pass over the batches on the loaded rows.
    bool solvePass(bool useBias, PassScope scope);
    bool touchesChange(const ManifoldBatch& c) const;
    static void computeEffectiveMasses(ManifoldBatch& batch);
    void loadVelocities(const BodyStorage& bodies);
    // The rows a pass sequence starts from: the bodies' velocities, or the rows the warm start held.
    void startFromVelocities(const BodyStorage& bodies);
    void loadMotion(const BodyStorage& bodies);
    void storeVelocities(BodyStorage& bodies) const;
    // visit(s) for every solver body s but the immovable one, on the pool's threads.
    template <class Visit>
    void forEachSolverBody(Visit&& visit) const {
        pool_->parallelFor(references_.size() - 1, kBodyGrain, [&](std::size_t, std::size_t begin, std::size_t end) {
            for (std::size_t s = begin + 1; s < end + 1; ++s) visit(s);
        });
    }
    // visit(beginBatch, endBatch) for every batch, each colour cut into the same number of slices
    // and slice k of every colour visited before slice k + 1, on the pool's threads. A thread then
    // fills and stores about the batches it solves (forEachBatch deals each colour out in order),
    // whose bodies and records stay in its cache: handed over between cores that share no cache,
    // they cost pyramid20 5-7% of its step at 2 threads. At 1 thread visiting neighbouring
    // manifolds of all colours together saved 2-4%. Filling and storing a batch do not depend on
    // the order, so the slices may follow the threads that run them (one, while the workers are
    // off: as at 1 thread).
    template <class Visit>
    void forEachColorSlice(Visit&& visit) const {
        const std::size_t slices =
            std::clamp<std::size_t>(batches_.size() / kMinBatchesPerSlice, 1,
                                    kSlicesPerThread * static_cast<std::size_t>(pool_->activeThreadCount()));
        pool_->parallelFor(slices, 1, [&](std::size_t slice, std::size_t, std::size_t) {
            for (int color = 0; color <= kOverflow; ++color) {
                const std::size_t first = colorFirstBatch_[color], count = colorFirstBatch_[color + 1] - first;
                if (count == 0) continue;  // most of the kColorCount colours, and before two divisions
                const std::size_t begin = first + count * slice / slices, end = first + count * (slice + 1) / slices;
                if (begin < end) visit(begin, end);
            }
        });
    }
    void currentInverseInertia(const std::int32_t (&solverBodies)[kLanes], const BodyStorage& bodies,
                               FloatW (&inverseInertia)[6]) const;
    // solveBatch(batch) for every batch (or only those holding a stiffened manifold), colour by
    // colour in order; the batches of a colour on the pool's threads, the overflow's on this one.
    // Returns whether solveBatch returned true for any.
    template <class SolveBatch>
    bool forEachBatch(SolveBatch&& solveBatch, bool stiffOnly = false);
    // How forEachBatch runs the colours on more than one thread: each thread solves its share of
    // every colour in turn (the shares forEachColorSlice fills), and waits before a batch only for
    // the batches of other shares that last touched its moving bodies, not for the whole colour
    // before. Each batch still reads the rows as the colour before left them, so the results are
    // those of solving colour after colour. With every thread waiting for the others at each colour's
    // end instead, those waits were about 5% of pyramid10's step at 2 threads, cores near (as the
    // step without them, which races), each a hand-over between the cores.
    struct BatchSchedule {
        std::size_t threads = 0;                // its shares; 0: none made for these lanes
        std::vector<std::uint32_t> batches;     // each share's batches in solve order, share after share
        std::vector<std::uint32_t> shareStart;  // by share, and one past the last
        std::vector<std::uint32_t> required;    // by entry of batches, then share: that share's batches done first
    };
    static constexpr std::size_t kMaxScheduledThreads = 64;
    // Scheduled only where a colour has at most this many batches a thread on average: a colour's
    // wait then costs about a tenth of its work (cores near). Longer colours lost more to making
    // the schedule (70 us a step in pyramid20, whose lanes change every step) and to shares that
    // cannot take over each other's batches than the waits cost: near, pyramid20 (80 batches a
    // thread) took 3.5-4.5% longer a step at 2 threads, pile1k (30) 1-2.5%, mixed1k (25) 2-3%,
    // where pyramid10 (10) took 4% less (2026-12-08).
    static constexpr std::size_t kScheduledBatchesPerThread = 16;
    void makeSchedule(BatchSchedule& schedule, const std::uint32_t* colorEnd, std::size_t threads);

    std::vector<ManifoldBatch, LargeArrayAllocator<ManifoldBatch>> batches_;  // colour by colour
    std::array<std::uint32_t, kColorCount + 2> colorFirstBatch_{};  // colour c: [first[c], first[c + 1])
    // Colour c's batches holding a stiffened manifold: [first[c], stiffEnd[c]).
    std::array<std::uint32_t, kColorCount + 1> colorStiffEnd_{};
    // Of every batch, of those holding a stiffened manifold: kept while the colours and lanes stay
    // (a resting pyramid's from step to step), since making one visits every lane.
    std::array<BatchSchedule, 2> schedules_;
    void forgetSchedules() {
        for (BatchSchedule& schedule : schedules_) schedule.threads = 0;
    }
    std::vector<std::uint32_t> lastShare_, lastStep_;  // scratch: by solver body (makeSchedule)
    TaskPool* pool_ = nullptr;                 // prepare's
    std::vector<BodyRow> velocities_, motion_;  // by solver body
    std::uint32_t motionCount_ = 0;             // motion_ loaded since prepare, counting prepare's
    bool velocitiesHeld_ = false;               // velocities_ hold the warm start's velocities, not yet stored
    std::vector<BodyReference> references_;    // by solver body; entry 0 is the immovable body
    // Kept between steps with the colouring (colourManifolds):
    std::vector<std::int32_t> denseToSolver_;  // -1 where a body has no solver entry
    std::vector<std::uint64_t> bodyColors_;    // colours used at each solver body
    std::vector<std::uint32_t> order_;         // the manifolds' contact indices, in contact order
    std::vector<std::uint32_t> colorEntries_;  // entries of order_, colour by colour
    std::array<std::uint32_t, kColorCount + 2> colorFirstEntry_{};  // colour c: [first[c], first[c + 1])
    std::vector<ColouredBody> colouredBodies_;  // by dense index, as last coloured
    std::uint64_t colouredManifoldList_ = ~std::uint64_t{0};  // manifoldListVersion() as last coloured; none yet
    std::vector<std::uint8_t> colorOf_;        // scratch: by entry of order_
    std::vector<float> stiffening_;            // scratch: by entry of order_, the spring's factor (1: none)
    std::vector<std::uint8_t> jointed_;        // scratch: by dense body index, 1 with a joint (empty: none)
    bool jointedBody(std::size_t denseIndex) const { return !jointed_.empty() && jointed_[denseIndex]; }
    bool jointedPair(std::size_t a, std::size_t b) const { return jointedBody(a) || jointedBody(b); }
    static constexpr std::uint32_t kNoConstraint = ~std::uint32_t{0};
    std::vector<std::uint32_t> laneConstraint_;  // scratch: by batch and lane, an index into order_
    std::vector<std::uint32_t> previousLanes_;   // laneConstraint_ as the step before left it
    std::vector<float> batchPenetration_;        // scratch: by batch, its points' deepest overlap (m)
    // By solver body: the last pass in which a row changed a moving body's velocity by more than
    // the pass's tolerance (kStiffTolerance in a velocity pass, where only stiffened manifolds mark,
    // kRelaxTolerance in a relax pass); written only for moving bodies, which a colour's batches
    // never share. Passes are counted from prepare.
    std::vector<std::uint32_t> changedInPass_;
    std::uint32_t pass_ = 0;
    int extraRelaxPasses_ = 0;  // restricted passes since the last full relax pass
    // By solver body: 1 where it touches a moving body of uneven mass (kUnevenMassRatio).
    std::vector<std::uint8_t> unevenBody_;
    // By solver body, in a step with a contact of uneven mass (else empty): the fewest contacts
    // between it and a body that does not move (static, kinematic or asleep: 0); kUnsupported where
    // no chain of contacts reaches one.
    std::vector<std::uint32_t> supportDepth_;
    static constexpr std::uint32_t kUnsupported = ~std::uint32_t{0};
    std::vector<std::uint32_t> neighbourStart_, neighbours_;  // scratch: the moving bodies each touches
    std::vector<std::uint32_t> depthQueue_;                   // scratch: bodies by depth
    void findSupportDepths();
    Params params_;
    float maxPenetration_ = 0.0f;
    std::size_t constraintCount_ = 0, colorCount_ = 0;
    // Colours 0 .. colorsInUse_ - 1 hold manifolds, the overflow aside: a manifold takes the lowest
    // colour free at its bodies, so the colours in use come first.
    std::size_t colorsInUse_ = 0;
    bool usesFriction_ = false;
    bool usesRestitution_ = false;
};

template <class SolveBatch>
inline bool ContactSolver::forEachBatch(SolveBatch&& solveBatch, bool stiffOnly) {
    const std::size_t colors = colorsInUse_;
    const std::uint32_t* colorEnd = stiffOnly ? colorStiffEnd_.data() : colorFirstBatch_.data() + 1;
    const std::size_t overflowEnd = colorEnd[kOverflow];
    const auto batchesOf = [&](std::size_t color) { return colorEnd[color] - colorFirstBatch_[color]; };
    const auto threads = static_cast<std::size_t>(pool_->activeThreadCount());
    std::size_t widestChunks = 0, batches = 0;
    for (std::size_t color = 0; color < colors; ++color) {
        widestChunks = std::max(widestChunks, TaskPool::chunkCount(batchesOf(color), kBatchGrain));
        batches += batchesOf(color);
    }
    // Colours too narrow to share run on this thread, either way.
    const bool shared = threads > 1 && TaskPool::phasesShareable(colors, widestChunks, threads);
    std::uint64_t hits = 0;
    if (shared && threads <= kMaxScheduledThreads && batches <= kScheduledBatchesPerThread * threads * colors) {
        BatchSchedule& schedule = schedules_[stiffOnly ? 1 : 0];
        if (schedule.threads != threads) makeSchedule(schedule, colorEnd, threads);
        hits = pool_->runSequences([&](std::size_t share) {
            std::array<std::uint32_t, kMaxScheduledThreads> seen{};  // each share's steps as last read
            const std::uint32_t first = schedule.shareStart[share], end = schedule.shareStart[share + 1];
            std::uint64_t count = 0;
            for (std::uint32_t entry = first; entry < end; ++entry) {
                const std::uint32_t* required = schedule.required.data() + std::size_t{entry} * threads;
                for (std::size_t other = 0; other < threads; ++other) {
                    if (required[other] <= seen[other]) continue;
                    pool_->publishSteps(share, entry - first);  // so that the other's waits end
                    seen[other] = pool_->awaitSteps(other, required[other]);
                }
                if (solveBatch(batches_[schedule.batches[entry]])) ++count;
                pool_->publishSteps(share, entry + 1 - first);
            }
            return count;
        });
    } else {
        // Colour after colour, as one job.
        hits = pool_->parallelSumInPhases(
            colors, kBatchGrain, batchesOf, [&](std::size_t color, std::size_t begin, std::size_t end) {
                std::uint64_t count = 0;
                for (std::size_t k = colorFirstBatch_[color] + begin; k < colorFirstBatch_[color] + end; ++k)
                    if (solveBatch(batches_[k])) ++count;
                return count;
            });
    }
    bool any = hits > 0;
    // The overflow's batches may share moving bodies: one after another.
    for (std::size_t k = colorFirstBatch_[kOverflow]; k < overflowEnd; ++k)
        if (solveBatch(batches_[k])) any = true;
    return any;
}

}  // namespace simcore
