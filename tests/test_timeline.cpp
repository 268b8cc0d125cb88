// The timeline's ring (app/simulation/timeline.h), without a window: its capacity follows the
// memory limit, wrapping keeps the newest frames, a frame restores the world bit for bit as it was
// at that step, and a run resumed from a frame is the recorded run, with the forces it was given.

#include "app/simulation/timeline.h"

#include "support/scene_builders.h"
#include "support/state_hash.h"

#include <QtTest>

using namespace interplay;
using namespace simcore;

namespace {

// A pile of 24 cubes dropped on the ground: contacts come and go, so a restored frame that lost
// any of the solver's state (warm starts, the broad phase's tree) would part from the run at once.
World pile() {
    World world;
    scene_builders::addGround(world);
    for (const Vec3& centre : scene_builders::gridCentres(3, 4, 2, 1.1f, 0.6f)) {
        BodyCreationSettings b = scene_builders::cube(centre);
        b.orientation = glm::angleAxis(0.1f * centre.y, glm::normalize(Vec3(1, 0, 1)));
        world.createBody(b);
    }
    return world;
}

// The force the test pushes body 1 with over steps [20, 50): replayed from the frames' record.
std::optional<AppliedForce> pushAt(const World& world, std::uint64_t step) {
    if (step < 20 || step >= 50) return std::nullopt;
    return AppliedForce{world.bodyIds()[1], Vec3(40.0f, 30.0f, 0.0f), Vec3(0.0f, 5.0f, 0.0f)};
}

// Runs `steps` steps of the pile with the push, recording every one (and the start) in `timeline`,
// and returns the state hash after each step (index 0: before the first).
std::vector<std::uint64_t> recordRun(Timeline& timeline, int steps) {
    World world = pile();
    std::vector<std::uint64_t> hashes{test_support::stateHash(world)};
    timeline.record(world, std::nullopt, false, world.bodyCount());
    for (int i = 0; i < steps; ++i) {
        const std::optional<AppliedForce> push = pushAt(world, world.stepCount() + 1);
        if (push) applyForce(world, *push);
        world.step();
        timeline.record(world, push, false, world.bodyCount());
        hashes.push_back(test_support::stateHash(world));
    }
    return hashes;
}

// A world of `count` spheres floating apart: every keyframe's copy is the same size.
World floatingSpheres(int count) {
    WorldSettings settings;
    settings.gravity = Vec3(0.0f);
    settings.sleep.enabled = false;
    World world(settings);
    for (int i = 0; i < count; ++i) {
        BodyCreationSettings b;
        b.shape = Shape::sphere(0.5f);
        b.position = Vec3(3.0f * float(i), 0.0f, 0.0f);
        b.linearVelocity = Vec3(0.0f, 0.0f, 1.0f);
        world.createBody(b);
    }
    return world;
}

}  // namespace

class TestTimeline : public QObject {
    Q_OBJECT

private slots:
    void capacityFollowsTheMemoryLimit_data();
    void capacityFollowsTheMemoryLimit();
    void loweringTheLimitDropsTheOldest();
    void wrapAroundKeepsTheNewest();
    void frameRestoresTheStateOfItsStep_data();
    void frameRestoresTheStateOfItsStep();
    void resumingFromAFrameReproducesTheRun_data();
    void resumingFromAFrameReproducesTheRun();
    void aChangedWorldStartsAKeyframe();
    void truncatingKeepsTheFrameAndItsPast();
    void unrecordedFrameIsRefused();
};

void TestTimeline::capacityFollowsTheMemoryLimit_data() {
    QTest::addColumn<int>("groups");  // the limit, in groups of one keyframe and the frames after it
    QTest::newRow("1 group") << 1;
    QTest::newRow("3 groups") << 3;
    QTest::newRow("12 groups") << 12;
}

// The limit holds exactly as many whole groups as fit: bytes never exceed it, and the next group
// would not have fitted.
void TestTimeline::capacityFollowsTheMemoryLimit() {
    QFETCH(int, groups);
    World world = floatingSpheres(200);
    Timeline probe(std::numeric_limits<std::size_t>::max());
    for (int i = 0; i < Timeline::kKeyframeInterval; ++i) {
        world.step();  // a world that has stepped holds the step's scratch, which its copies take along
        probe.record(world, std::nullopt, false, world.bodyCount());
    }
    QCOMPARE(probe.keyframeCount(), std::size_t{1});
    const std::size_t groupBytes = probe.bytesUsed();
    // A 200-sphere world is tens of kB; a frame between keyframes is a small record.
    QVERIFY2(groupBytes > 200 * 100, qPrintable(QString::number(groupBytes)));

    // Half a group of slack, so the heap's measurement may vary a little from copy to copy.
    const std::size_t limit = std::size_t(groups) * groupBytes + groupBytes / 2;
    Timeline timeline(limit);
    for (int i = 0; i < 40 * Timeline::kKeyframeInterval; ++i) {
        world.step();
        timeline.record(world, std::nullopt, false, world.bodyCount());
        QVERIFY(timeline.bytesUsed() <= limit);
    }
    QCOMPARE(timeline.frameCount(), std::size_t(groups * Timeline::kKeyframeInterval));
    QCOMPARE(timeline.keyframeCount(), std::size_t(groups));
    QVERIFY(timeline.bytesUsed() + groupBytes > limit);
    QCOMPARE(timeline.secondsCovered(), timeline.timeOf(timeline.frameCount() - 1) - timeline.timeOf(0));
}

void TestTimeline::loweringTheLimitDropsTheOldest() {
    World world = floatingSpheres(50);
    Timeline timeline;
    for (int i = 0; i < 100; ++i) {
        world.step();
        timeline.record(world, std::nullopt, false, world.bodyCount());
    }
    QCOMPARE(timeline.frameCount(), std::size_t{100});
    const std::uint64_t newest = timeline.stepOf(99);
    timeline.setMemoryLimit(timeline.bytesUsed() / 2);
    QVERIFY(timeline.frameCount() < 100);
    QVERIFY(timeline.frameCount() >= 40);  // ten groups of nearly equal size: at least four stay
    QCOMPARE(timeline.stepOf(timeline.frameCount() - 1), newest);
    QVERIFY(timeline.isKeyframe(0));
    timeline.setMemoryLimit(0);
    QVERIFY(timeline.empty());
    QCOMPARE(timeline.bytesUsed(), std::size_t{0});
    timeline.record(world, std::nullopt, false, world.bodyCount());
    QVERIFY(timeline.empty());  // a frame bigger than the limit is not kept
}

void TestTimeline::wrapAroundKeepsTheNewest() {
    World world = floatingSpheres(100);
    Timeline probe;
    probe.record(world, std::nullopt, false, world.bodyCount());
    Timeline timeline(5 * probe.bytesUsed());  // room for a few groups of a keyframe and 9 frames
    for (int i = 0; i < 500; ++i) {
        world.step();
        timeline.record(world, std::nullopt, false, world.bodyCount());
    }
    QVERIFY(timeline.frameCount() > 0 && timeline.frameCount() < 500);
    QVERIFY(timeline.isKeyframe(0));
    const std::size_t last = timeline.frameCount() - 1;
    QCOMPARE(timeline.stepOf(last), world.stepCount());
    for (std::size_t i = 0; i < timeline.frameCount(); ++i) QCOMPARE(timeline.stepOf(i), world.stepCount() - (last - i));
    QCOMPARE(test_support::stateHash(timeline.restore(last)), test_support::stateHash(world));
    QCOMPARE(timeline.restore(0).stepCount(), timeline.stepOf(0));
}

void TestTimeline::frameRestoresTheStateOfItsStep_data() {
    QTest::addColumn<int>("step");
    for (const int step : {0, 1, 9, 10, 11, 19, 20, 37, 49, 50, 80})
        QTest::newRow(qPrintable(QString("step %1").arg(step))) << step;
}

// Frame N is the world stepped N times from the same start (with the same pushes), bit for bit.
void TestTimeline::frameRestoresTheStateOfItsStep() {
    QFETCH(int, step);
    Timeline timeline;
    recordRun(timeline, 80);
    QCOMPARE(timeline.frameCount(), std::size_t{81});
    World reference = pile();
    for (int i = 0; i < step; ++i) {
        if (const auto push = pushAt(reference, reference.stepCount() + 1)) applyForce(reference, *push);
        reference.step();
    }
    const World restored = timeline.restore(std::size_t(step));
    QCOMPARE(restored.stepCount(), std::uint64_t(step));
    QCOMPARE(timeline.stepOf(std::size_t(step)), std::uint64_t(step));
    QCOMPARE(test_support::stateHash(restored), test_support::stateHash(reference));
    QCOMPARE(restored.contactCount(), reference.contactCount());
    QCOMPARE(restored.simulatedTime(), reference.simulatedTime());
}

void TestTimeline::resumingFromAFrameReproducesTheRun_data() {
    QTest::addColumn<int>("from");
    QTest::newRow("a keyframe before the push") << 10;
    QTest::newRow("between keyframes, mid-push") << 33;
    QTest::newRow("after the push") << 64;
}

// Restored and stepped on (with the pushes the run had), a frame retraces every later step.
void TestTimeline::resumingFromAFrameReproducesTheRun() {
    QFETCH(int, from);
    Timeline timeline;
    const std::vector<std::uint64_t> hashes = recordRun(timeline, 120);
    World resumed = timeline.restore(std::size_t(from));
    timeline.truncateAfter(std::size_t(from));
    QCOMPARE(timeline.frameCount(), std::size_t(from + 1));
    for (int step = from + 1; step <= 120; ++step) {
        const std::optional<AppliedForce> push = pushAt(resumed, resumed.stepCount() + 1);
        if (push) applyForce(resumed, *push);
        resumed.step();
        timeline.record(resumed, push, false, resumed.bodyCount());
        QCOMPARE(test_support::stateHash(resumed), hashes[std::size_t(step)]);
    }
    // The re-recorded future restores as the first recording did.
    QCOMPARE(test_support::stateHash(timeline.restore(100)), hashes[100]);
}

void TestTimeline::aChangedWorldStartsAKeyframe() {
    World world = floatingSpheres(3);
    Timeline timeline;
    timeline.record(world, std::nullopt, false, 3);
    world.step();
    timeline.record(world, std::nullopt, false, 3);
    QVERIFY(timeline.isKeyframe(0));
    QVERIFY(!timeline.isKeyframe(1));
    // A body thrown in between steps: stepping from frame 0 would not lead to the next frame.
    BodyCreationSettings b;
    b.shape = Shape::sphere(0.2f);
    b.position = Vec3(0.0f, 5.0f, 0.0f);
    world.createBody(b);
    world.step();
    timeline.record(world, std::nullopt, true, 4);
    QVERIFY(timeline.isKeyframe(2));
    QCOMPARE(timeline.trackedBodiesOf(2), std::size_t{4});
    QCOMPARE(timeline.restore(2).bodyCount(), std::size_t{4});
    QCOMPARE(timeline.restore(1).bodyCount(), std::size_t{3});
    QCOMPARE(test_support::stateHash(timeline.restore(2)), test_support::stateHash(world));
}

void TestTimeline::truncatingKeepsTheFrameAndItsPast() {
    Timeline timeline;
    const std::vector<std::uint64_t> hashes = recordRun(timeline, 30);
    const std::size_t bytesBefore = timeline.bytesUsed();
    timeline.truncateAfter(14);
    QCOMPARE(timeline.frameCount(), std::size_t{15});
    QVERIFY(timeline.bytesUsed() < bytesBefore);
    QCOMPARE(test_support::stateHash(timeline.restore(14)), hashes[14]);
    timeline.truncateAfter(40);  // past the end: nothing to drop
    QCOMPARE(timeline.frameCount(), std::size_t{15});
}

void TestTimeline::unrecordedFrameIsRefused() {
    Timeline timeline;
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, timeline.restore(0));
    recordRun(timeline, 3);
    QVERIFY_THROWS_EXCEPTION(std::out_of_range, timeline.restore(4));
}

QTEST_APPLESS_MAIN(TestTimeline)
#include "test_timeline.moc"
