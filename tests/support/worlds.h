#pragma once
// Building blocks of the physics tests' worlds: settings, running for a time, the energy the tests
// bound, and the ports of other engines' samples. Grounds, cubes, stacks and inclines come from the
// scene builders (support/scene_builders.h), shared with the benchmarks.

#include "simcore/io/scene.h"
#include "simcore/shapes/convex_hull.h"
#include "simcore/world/world.h"
#include "support/scene_builders.h"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace test_support {

using namespace simcore;
using namespace scene_builders;

inline WorldSettings awakeSettings() {
    WorldSettings s;
    s.sleep.enabled = false;
    return s;
}

inline int stepsFor(const World& world, float seconds) {
    return static_cast<int>(std::lround(seconds / world.settings().timeStep));
}

inline void run(World& world, float seconds) {
    for (int i = 0, n = stepsFor(world, seconds); i < n; ++i) world.step();
}

// Arithmetic-geometric mean: a pendulum's exact large-amplitude period is T0 / agm(1, cos(theta0 / 2)).
inline double agm(double a, double b) {
    for (int i = 0; i < 30; ++i) {
        const double m = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = m;
    }
    return a;
}

// Kinetic + potential energy of the dynamic bodies (potential relative to y = 0).
inline double totalEnergy(const World& world) { return world.kineticEnergy() + world.potentialEnergy(); }

// ---------------------------------------------------------------------------------------------
// Ports of other engines' hard-case samples (tests/test_sample_ports.cpp; scenes/ports/ holds each
// as a scene file). Each is rebuilt from the sample's description - its geometry, masses,
// materials and gravity, nothing of its solver settings - so that it runs at the engine's
// defaults, in simcore and, through the same scene file, in the reference engines. Where a sample
// uses something simcore has no equivalent of (motion locks, rolling resistance, scaled hulls,
// meshes), the builder says what it does instead.

// A fast body thrown at a surface: the surface is a body (a wall, a floor, another body) with its
// origin in the middle of its bounds, whose local `axis` is the direction the mover comes along,
// from its `front` side (+1 or -1 along it).
struct ThrownAt {
    std::size_t mover = 0;
    std::size_t surface = 0;
    int axis = 1;
    float front = 1.0f;
};

struct PortedSample {
    std::string name;  // also the scene file's name: scenes/ports/NAME.json
    Scene scene;
    // Per body: where its origin rests once the gaps the sample leaves under it have closed (the
    // sample's own drops); the start for bodies created resting, and for static ones.
    std::vector<Vec3> rest;
    std::vector<ThrownAt> thrown;
    std::vector<std::size_t> restitutionZero;  // bodies that land with restitution 0: must not bounce

    std::size_t add(BodyCreationSettings body, const Vec3& restsAt) {
        scene.bodies.push_back({std::move(body), std::nullopt, std::nullopt});
        rest.push_back(restsAt);
        return scene.bodies.size() - 1;
    }
    std::size_t add(const BodyCreationSettings& body) { return add(body, body.position); }
};

// Box3D's and Box2D's samples run at g = 10 m/s^2 (b3DefaultWorldDef, b2DefaultWorldDef), Jolt's
// at 9.81 (simcore's default). Their default material: friction 0.6 (Box2D, Box3D) or 0.2 (Jolt),
// restitution 0, density 1000 kg/m^3 (Box3D, Jolt) or 1 (Box2D).
inline PortedSample portedSample(const std::string& name, float gravity = 9.81f) {
    PortedSample sample;
    sample.name = name;
    sample.scene.settings.gravity = Vec3(0.0f, -gravity, 0.0f);
    return sample;
}

inline BodyCreationSettings portBody(const std::string& name, const Shape& shape, const Vec3& position,
                                     float friction, float density = 1000.0f) {
    BodyCreationSettings b;
    b.name = name;
    b.shape = shape;
    b.position = position;
    b.friction = friction;
    b.density = density;
    return b;
}

// The samples' static ground: a box `halfThickness` thick below y = 0, as their AddGroundBox /
// CreateFloor make it.
inline std::size_t addPortGround(PortedSample& sample, float halfSize, float friction, float halfThickness = 1.0f) {
    BodyCreationSettings g = portBody("ground", Shape::box(Vec3(halfSize, halfThickness, halfSize)),
                                      Vec3(0.0f, -halfThickness, 0.0f), friction);
    g.motion = MotionType::Static;
    return sample.add(g);
}

inline Quat aboutAxis(float radians, const Vec3& axis) { return glm::angleAxis(radians, axis); }

// Box3D Robustness "HighMassRatio1": three one-cube-deep pyramids of 2 m cubes (rows of 10 down to
// 2, touching) of density 1, each carrying a top cube of density 100, 200 or 300 (100-300:1 by
// mass) dropped from 2 m above its resting place.
inline PortedSample box3dHighMassRatio1() {
    PortedSample s = portedSample("box3d_high_mass_ratio1", 10.0f);
    addPortGround(s, 50.0f, 0.6f);
    const float e = 1.0f;  // half extent
    for (int j = 0; j < 3; ++j) {
        const float offset = -20.0f * e + 2.0f * 11.0f * e * static_cast<float>(j);
        float y = e;
        for (int count = 10; count > 0; --count, y += 2.0f * e) {
            for (int i = 0; i < count; ++i) {
                const float x = 2.0f * e * (static_cast<float>(i) - 0.5f * static_cast<float>(count)) + offset;
                const bool top = count == 1;
                const float density = top ? 100.0f * static_cast<float>(j + 1) : 1.0f;
                BodyCreationSettings b = portBody(top ? "heavy " + std::to_string(100 * (j + 1)) + ":1" : "cube",
                                                  Shape::box(Vec3(e)), Vec3(x, top ? y + 2.0f : y, 0.0f), 0.6f, density);
                s.add(b, Vec3(x, y, 0.0f));
            }
        }
    }
    return s;
}

// Box2D v3 Robustness "HighMassRatio2" and "HighMassRatio3", extruded 20 m deep (the big box's
// size), so that the 2D sample's mass ratios hold and nothing can topple sideways that cannot in
// 2D: a 20 m box dropped 15 m onto two 1 m square bars under its edges (400:1 at density 1), or
// 3 m onto the ridges of two triangular prisms 1 m wide and high (800:1).
inline PortedSample box2dHighMassRatio(int variant) {
    const bool prisms = variant == 3;
    PortedSample s = portedSample(prisms ? "box2d_high_mass_ratio3" : "box2d_high_mass_ratio2", 10.0f);
    const std::size_t ground = addPortGround(s, 50.0f, 0.6f);
    const float depth = 10.0f;  // half
    Shape support = Shape::box(Vec3(0.5f, 0.5f, depth));
    if (prisms) {
        // Its origin half way up (the sample's is the middle of the base), so that it is the middle
        // of the prism's bounds as a box's is.
        std::vector<Vec3> points;
        for (float z : {-depth, depth})
            for (const Vec3& p : {Vec3(-0.5f, -0.5f, z), Vec3(0.5f, -0.5f, z), Vec3(0.0f, 0.5f, z)}) points.push_back(p);
        support = Shape::convexHull(ConvexHull::build(points).hull);
    }
    std::vector<std::size_t> supports;
    for (float x : {-9.0f, 9.0f}) {
        // The sample creates the prisms with their base 0.5 m above the ground, the boxes resting on it.
        const BodyCreationSettings b = portBody(prisms ? "prism" : "small box", support, Vec3(x, prisms ? 1.0f : 0.5f, 0.0f), 0.6f, 1.0f);
        supports.push_back(s.add(b, Vec3(x, 0.5f, 0.0f)));
    }
    const float bigY = prisms ? 14.0f : 26.0f;
    const float restY = 1.0f + 10.0f;  // on supports 1 m high
    const std::size_t big =
        s.add(portBody("big box", Shape::box(Vec3(10.0f, 10.0f, depth)), Vec3(0.0f, bigY, 0.0f), 0.6f, 1.0f), Vec3(0.0f, restY, 0.0f));
    for (std::size_t support : supports) {
        s.thrown.push_back({support, ground, 1, 1.0f});
        s.thrown.push_back({big, support, 1, 1.0f});
    }
    s.thrown.push_back({big, ground, 1, 1.0f});
    s.restitutionZero = {supports[0], supports[1], big};
    return s;
}

// Box3D Robustness "Tiny Pyramid": a one-cube-deep pyramid of 5 cm cubes, base 30 (465 cubes),
// touching.
inline PortedSample box3dTinyPyramid() {
    PortedSample s = portedSample("box3d_tiny_pyramid", 10.0f);
    addPortGround(s, 20.0f, 0.6f);
    const float e = 0.025f;
    const int base = 30;
    for (int i = 0; i < base; ++i) {
        const float y = (2.0f * static_cast<float>(i) + 1.0f) * e;
        for (int j = i; j < base; ++j) {
            const float x = (static_cast<float>(i) + 1.0f) * e + 2.0f * static_cast<float>(j - i) * e - static_cast<float>(base) * e;
            s.add(portBody("cube", Shape::box(Vec3(e)), Vec3(x, y, 0.0f), 0.6f));
        }
    }
    return s;
}

// Box3D Robustness "Overlap Recovery": a one-cube-deep pyramid of ten 1 kg unit cubes, base 4, each
// overlapping its neighbours and the row below by 25 % of its size. (The sample sets Box3D's
// contact tuning to 30 Hz, damping ratio 10, push 3 m/s - Box3D's defaults; the port sets none.)
inline PortedSample box3dOverlapRecovery() {
    PortedSample s = portedSample("box3d_overlap_recovery", 10.0f);
    addPortGround(s, 20.0f, 0.6f);
    const float e = 0.5f, fraction = 0.75f;
    const int base = 4;
    float y = e;
    for (int i = 0; i < base; ++i, y += 2.0f * fraction * e) {
        float x = fraction * e * static_cast<float>(i - base);
        for (int j = i; j < base; ++j, x += 2.0f * fraction * e)
            s.add(portBody("cube", Shape::box(Vec3(e)), Vec3(x, y, 0.0f), 0.6f, 1.0f));
    }
    return s;
}

// Box3D Stacking "Card House" (from PEEL): five storeys of cards 2 mm x 0.4 m x 0.2 m, leaning in
// pairs at 25 degrees with flat cards across the tops, friction 0.7; 40 cards. (The sample gives
// them rolling resistance 0.05, which simcore does not have yet: the port leaves it out.)
inline PortedSample box3dCardHouse() {
    PortedSample s = portedSample("box3d_card_house", 10.0f);
    addPortGround(s, 10.0f, 0.6f);
    const float height = 0.2f, thickness = 0.001f, depth = 0.1f;  // half extents
    const Shape card = Shape::box(Vec3(thickness, height, depth));
    const float lean = 25.0f * kPi / 180.0f;
    const Vec3 z(0.0f, 0.0f, 1.0f);
    // The sample leaves gaps of 2-3 mm under each flat card and each storey (and the lowest cards
    // 1.7 mm in the ground): at rest a leaning card's lowest corner is on the card or ground under
    // it, a flat card on the leaning cards' tops. (A leaning pair's tops are also 4 mm apart, which
    // lowers them by under 1 mm as they close.)
    const float leaningHalfHeight = height * std::cos(lean) + thickness * std::sin(lean);
    float x0 = 0.0f, y = height - 0.02f, restY = leaningHalfHeight;
    for (int storey = 5; storey > 0; --storey, y += 2.0f * height - 0.03f, x0 += 0.175f) {
        float x = x0;
        const float flatRestY = restY + leaningHalfHeight + thickness;
        for (int i = 0; i < storey; ++i) {
            if (i != storey - 1) {
                BodyCreationSettings flat = portBody("flat card", card, Vec3(x + 0.25f, y + height - 0.015f, 0.0f), 0.7f);
                flat.orientation = aboutAxis(0.5f * kPi, z);
                s.add(flat, Vec3(flat.position.x, flatRestY, 0.0f));
            }
            BodyCreationSettings left = portBody("leaning card", card, Vec3(x, y, 0.0f), 0.7f);
            left.orientation = aboutAxis(-lean, z);
            s.add(left, Vec3(x, restY, 0.0f));
            x += 0.175f;
            BodyCreationSettings right = portBody("leaning card", card, Vec3(x, y, 0.0f), 0.7f);
            right.orientation = aboutAxis(lean, z);
            s.add(right, Vec3(x, restY, 0.0f));
            x += 0.175f;
        }
        restY = flatRestY + thickness + leaningHalfHeight;
    }
    return s;
}

// Box3D Stacking "Jenga Stack" (hull variant): 30 layers of two 2 m x 0.2 m x 0.2 m bars 1.6 m
// apart, each layer turned 90 degrees, created 1 cm apart (the first 5 cm into the ground).
inline PortedSample box3dJenga() {
    PortedSample s = portedSample("box3d_jenga", 10.0f);
    addPortGround(s, 20.0f, 0.6f);
    const float h = 1.0f, r = 0.1f;
    for (int i = 0; i < 30; ++i) {
        const bool odd = (i & 1) == 1;
        const float x = odd ? 0.0f : h - 2.0f * r, z = odd ? h - 2.0f * r : 0.0f;
        const float y = (2.1f * static_cast<float>(i) + 0.5f) * r, restY = (2.0f * static_cast<float>(i) + 1.0f) * r;
        for (float side : {1.0f, -1.0f}) {
            BodyCreationSettings bar = portBody("bar", Shape::box(Vec3(h, r, r)), Vec3(side * x, y, side * z), 0.6f);
            bar.orientation = aboutAxis(odd ? 0.0f : 0.5f * kPi, Vec3(0.0f, 1.0f, 0.0f));
            s.add(bar, Vec3(side * x, restY, side * z));
        }
    }
    return s;
}

// Box3D Stacking "Cylinder Stack": ten cylinders 1 m high, radius 0.5 m, created 10 cm apart (the
// lowest on the ground). The sample scales a 15-sided hull cylinder by (1, 1, 1), (0.75, 1, 1),
// (1.2, 1, 0.9), (0.9, 0.9, 0.9) in turn; simcore's cylinders are round, so the port gives each the
// round cross-section of the same area (radius 0.5 sqrt(sx sz)) and height 1 sy.
inline PortedSample box3dCylinderStack() {
    PortedSample s = portedSample("box3d_cylinder_stack", 10.0f);
    addPortGround(s, 10.0f, 0.6f);
    const Vec3 scales[4] = {Vec3(1.0f), Vec3(0.75f, 1.0f, 1.0f), Vec3(1.2f, 1.0f, 0.9f), Vec3(0.9f)};
    float restBase = 0.0f;
    for (int i = 0; i < 10; ++i) {
        const Vec3 k = scales[i % 4];
        const float halfHeight = 0.5f * k.y;
        const BodyCreationSettings c = portBody("cylinder", Shape::cylinder(0.5f * std::sqrt(k.x * k.z), halfHeight),
                                                Vec3(0.0f, 1.1f * static_cast<float>(i) + halfHeight, 0.0f), 0.6f);
        s.add(c, Vec3(0.0f, restBase + halfHeight, 0.0f));
        restBase += 2.0f * halfHeight;
    }
    return s;
}

// Box3D Stacking "Capsule Stack": twenty capsules of radius 0.5 m with a 2 m segment, lying along x
// and stacked touching, the lowest 25 cm above the ground. The sample locks their rotation and z
// motion (motion locks), which simcore does not have: the port relies on the stack being exactly
// symmetric, so it checks that the solver makes no sideways motion out of nothing.
inline PortedSample box3dCapsuleStack() {
    PortedSample s = portedSample("box3d_capsule_stack", 10.0f);
    addPortGround(s, 40.0f, 0.6f);
    for (int i = 0; i < 20; ++i) {
        BodyCreationSettings c = portBody("capsule", Shape::capsule(0.5f, 1.0f), Vec3(0.0f, 0.75f + static_cast<float>(i), 0.0f), 0.6f);
        c.orientation = aboutAxis(0.5f * kPi, Vec3(0.0f, 0.0f, 1.0f));
        s.add(c, Vec3(0.0f, 0.5f + static_cast<float>(i), 0.0f));
    }
    return s;
}

// Box3D Issues "Wheel Stack" (the GMod metal_wheel1 prop): thirty wheels 0.171 m thick and 0.497 m
// in radius stacked flat 6 mm apart, the lowest 4 mm above the ground. The sample wraps the prop's
// 37-piece decomposition in one hull, a 32-sided prism; the port builds that prism. (The sample
// also stiffens Box3D's contacts to 240 Hz; the port runs at the defaults.)
inline PortedSample box3dWheelStack() {
    PortedSample s = portedSample("box3d_wheel_stack", 10.0f);
    addPortGround(s, 10.0f, 0.6f);
    const float radius = 0.497f, height = 0.171f;
    std::vector<Vec3> points;
    for (int k = 0; k < 32; ++k) {
        const float a = 2.0f * kPi * static_cast<float>(k) / 32.0f;
        for (float y : {-0.5f * height, 0.5f * height}) points.emplace_back(radius * std::sin(a), y, radius * std::cos(a));
    }
    const Shape wheel = Shape::convexHull(ConvexHull::build(points).hull);
    const float spacing = height + 0.006f, startY = 0.5f * height + 0.004f;
    for (int i = 0; i < 30; ++i)
        s.add(portBody("wheel", wheel, Vec3(0.0f, startY + static_cast<float>(i) * spacing, 0.0f), 0.6f),
              Vec3(0.0f, 0.5f * height + static_cast<float>(i) * height, 0.0f));
    return s;
}

// Jolt General "HeavyOnLightTest": ten pairs of 10 m cubes 15 m apart, a light one (1000 kg/m^3)
// dropped 5 m onto the floor and a heavy one (5000, 10000, ... 50000 kg/m^3: 5:1 to 50:1) dropped
// from 15 m above it; Jolt's default material (friction 0.2, restitution 0).
inline PortedSample joltHeavyOnLight() {
    PortedSample s = portedSample("jolt_heavy_on_light");
    const std::size_t floor = addPortGround(s, 100.0f, 0.2f);
    for (int i = 1; i <= 10; ++i) {
        const float x = -75.0f + 15.0f * static_cast<float>(i);
        const std::size_t light = s.add(portBody("light", Shape::box(Vec3(5.0f)), Vec3(x, 10.0f, 0.0f), 0.2f), Vec3(x, 5.0f, 0.0f));
        const std::size_t heavy = s.add(portBody("heavy " + std::to_string(5 * i) + ":1", Shape::box(Vec3(5.0f)),
                                                 Vec3(x, 30.0f, 0.0f), 0.2f, 5000.0f * static_cast<float>(i)),
                                        Vec3(x, 15.0f, 0.0f));
        s.thrown.push_back({light, floor, 1, 1.0f});
        s.thrown.push_back({heavy, light, 1, 1.0f});
        s.restitutionZero.push_back(light);
        s.restitutionZero.push_back(heavy);
    }
    return s;
}

// Jolt General "HighSpeedTest", its "Simple" scene, in rows 5 m apart along z: 0.1 m spheres and
// boxes at 240 m/s (friction 0, restitution 1, swept: Jolt's LinearCast is simcore's `ccd`) into a
// U of static walls 2 cm thick (the sample's are mesh triangles with gaps between them; the port's
// walls are whole, so that nothing passes them but by tunnelling), into U's of dynamic dominoes
// (1.8 x 2 x 0.2 m, 2000 kg/m^3), half into the floor moving up and down, inside four kinematic
// walls, and at each other (head on, off centre, against a slower unswept box, against boxes at
// rest); and 1.6 m bars at 100 m/s onto the floor, flat and at 45 degrees, with restitution 0 and 1
// (friction 1). Jolt's floor: friction 0.2, restitution 0.
inline PortedSample joltHighSpeed() {
    PortedSample s = portedSample("jolt_high_speed");
    const std::size_t floor = addPortGround(s, 100.0f, 0.2f);
    const float radius = 0.1f, speed = 240.0f;
    const Vec3 y(0.0f, 1.0f, 0.0f);
    auto fast = [&](const std::string& name, const Shape& shape, const Vec3& at, const Vec3& velocity, bool swept = true) {
        BodyCreationSettings b = portBody(name, shape, at, 0.0f);
        b.restitution = 1.0f;
        b.linearVelocity = velocity;
        b.ccd = swept;
        const std::size_t i = s.add(b);
        s.thrown.push_back({i, floor, 1, 1.0f});
        return i;
    };
    auto staticWall = [&](const Vec3& half, const Vec3& at) {
        BodyCreationSettings w = portBody("wall", Shape::box(half), at, 0.0f);
        w.motion = MotionType::Static;
        w.restitution = 1.0f;
        return s.add(w);
    };
    // The U's open end faces +x; the mover enters it at x = 9 heading for the -z wall.
    auto dominoes = [&](float z0) {
        std::vector<std::pair<std::size_t, float>> walls;  // body, side the inside of the U is on
        for (int i = 0; i < 5; ++i)
            for (float side : {-1.0f, 1.0f}) {
                BodyCreationSettings d = portBody("domino", Shape::box(Vec3(0.9f, 1.0f, 0.1f)),
                                                  Vec3(2.0f * static_cast<float>(i), 1.0f, z0 + side * (1.1f + radius)), 0.2f, 2000.0f);
                walls.push_back({s.add(d), -side});
            }
        BodyCreationSettings end = portBody("domino", Shape::box(Vec3(0.9f, 1.0f, 0.1f)), Vec3(-1.1f - radius, 1.0f, z0), 0.2f, 2000.0f);
        end.orientation = aboutAxis(0.5f * kPi, y);  // its local z is world x
        walls.push_back({s.add(end), 1.0f});
        return walls;
    };
    float z = -30.0f;
    {  // a sphere into a U of static walls
        const float t = 0.01f;
        const std::size_t left = staticWall(Vec3(5.0f, 1.0f, t), Vec3(4.0f, 1.0f, z - 1.0f - radius - t));
        const std::size_t right = staticWall(Vec3(5.0f, 1.0f, t), Vec3(4.0f, 1.0f, z + 1.0f + radius + t));
        const std::size_t end = staticWall(Vec3(t, 1.0f, 1.0f), Vec3(-1.0f - radius - t, 1.0f, z));
        const std::size_t ball = fast("sphere", Shape::sphere(radius), Vec3(9.0f, 1.0f, z), Vec3(-speed, 0.0f, -speed));
        s.thrown.push_back({ball, left, 2, 1.0f});
        s.thrown.push_back({ball, right, 2, -1.0f});
        s.thrown.push_back({ball, end, 0, 1.0f});
    }
    for (int k = 0; k < 2; ++k) {  // a sphere, then a box, into a U of dominoes
        z += 5.0f;
        const auto walls = dominoes(z);
        const Shape shape = k == 0 ? Shape::sphere(radius) : Shape::box(Vec3(radius));
        const std::size_t mover = fast(k == 0 ? "sphere" : "box", shape, Vec3(9.0f, 1.0f, z), Vec3(-speed, 0.0f, -speed));
        for (const auto& [wall, inside] : walls) s.thrown.push_back({mover, wall, 2, inside});
    }
    z += 5.0f;  // boxes half in the floor, one moving up, one down
    fast("box up", Shape::box(Vec3(radius)), Vec3(-1.0f, 0.0f, z), Vec3(0.0f, speed, 0.0f));
    fast("box down", Shape::box(Vec3(radius)), Vec3(1.0f, 0.0f, z), Vec3(0.0f, -speed, 0.0f));
    z += 5.0f;
    {  // a sphere inside four kinematic walls
        std::vector<std::pair<std::size_t, float>> walls;
        for (int k = 0; k < 4; ++k) {
            const float side = k % 2 == 0 ? 1.0f : -1.0f;
            BodyCreationSettings w = portBody("kinematic wall", Shape::box(Vec3(1.0f, 1.0f, 0.1f)),
                                              k < 2 ? Vec3(0.0f, 1.0f, z + side) : Vec3(side, 1.0f, z), 0.0f);
            w.motion = MotionType::Kinematic;
            w.restitution = 1.0f;
            if (k >= 2) w.orientation = aboutAxis(0.5f * kPi, y);
            walls.push_back({s.add(w), -side});
        }
        const std::size_t ball = fast("sphere", Shape::sphere(radius), Vec3(0.0f, 0.5f, z), Vec3(-speed, 0.0f, -0.5f * speed));
        for (const auto& [wall, inside] : walls) s.thrown.push_back({ball, wall, 2, inside});
    }
    // Boxes on a collision course along x: head on, off centre, one slower and unswept, one at
    // rest (swept or not).
    struct Pair { float offsetZ, speedB, startB; bool sweptB; };
    for (const Pair& p : {Pair{0.0f, speed, -1.0f, true}, Pair{radius, speed, -1.0f, true}, Pair{0.0f, 60.0f, -1.0f, false},
                          Pair{0.0f, 0.0f, 0.0f, true}, Pair{0.0f, 0.0f, 0.0f, false}}) {
        z += 5.0f;
        const std::size_t a = fast("box A", Shape::box(Vec3(radius)), Vec3(1.0f, 0.5f, z), Vec3(-speed, 0.0f, 0.0f));
        const std::size_t b = fast("box B", Shape::box(Vec3(radius)), Vec3(p.startB, 0.5f, z + p.offsetZ), Vec3(p.speedB, 0.0f, 0.0f), p.sweptB);
        s.thrown.push_back({a, b, 0, 1.0f});
        s.thrown.push_back({b, a, 0, -1.0f});
    }
    // Long thin bars onto the floor at 100 m/s: flat and at 45 degrees, restitution 0, then 1.
    for (int k = 0; k < 4; ++k) {
        z += 5.0f;
        BodyCreationSettings bar = portBody(std::string("bar ") + (k % 2 == 0 ? "flat" : "45 deg") + (k < 2 ? ", e 0" : ", e 1"),
                                            Shape::box(Vec3(0.05f, 0.8f, 0.03f)), Vec3(0.0f, 1.0f, z), 1.0f);
        bar.orientation = aboutAxis((k % 2 == 0 ? 0.5f : 0.25f) * kPi, Vec3(1.0f, 0.0f, 0.0f));
        bar.linearVelocity = Vec3(0.0f, -100.0f, 0.0f);
        bar.restitution = k < 2 ? 0.0f : 1.0f;
        bar.ccd = true;
        const std::size_t i = s.add(bar);
        s.thrown.push_back({i, floor, 1, 1.0f});
        if (k < 2) s.restitutionZero.push_back(i);
    }
    return s;
}

// Box3D Stacking "Edge Crossing": three rows of 21 thin bars (half extents 0.2 x 0.02 x 0.04 m,
// lying flat or on edge) with a second bar dropped across each from 20 half-thicknesses up,
// turned about a nearly vertical axis by -pi ... pi in steps of pi / 10, so that bars meet edge
// on at every angle. Where each dropped bar comes to rest is left open: the check is the overlap.
inline PortedSample box3dEdgeCrossing() {
    PortedSample s = portedSample("box3d_edge_crossing", 10.0f);
    addPortGround(s, 40.0f, 0.6f);
    const Vec3 flat(0.2f, 0.02f, 0.04f), onEdge(0.2f, 0.04f, 0.02f);
    const Vec3 axis = glm::normalize(Vec3(0.1f, 0.9f, 0.0f));
    const struct Row {
        float z;
        Vec3 lower, upper;
    } rows[] = {{-2.0f, flat, flat}, {0.0f, onEdge, onEdge}, {2.0f, flat, onEdge}};
    for (const Row& row : rows) {
        for (int k = 0; k <= 20; ++k) {
            const float x = -10.0f + float(k);
            s.add(portBody("bar", Shape::box(row.lower), Vec3(x, row.lower.y, row.z), 0.6f));
            BodyCreationSettings dropped = portBody("dropped bar", Shape::box(row.upper), Vec3(x, 20.0f * row.lower.y, row.z), 0.6f);
            dropped.orientation = aboutAxis(-kPi + 0.1f * kPi * float(k), axis);
            s.add(dropped);
        }
    }
    return s;
}

// Every port, in the order of the suite.
inline std::vector<PortedSample> allPortedSamples() {
    return {box3dHighMassRatio1(), box2dHighMassRatio(2), box2dHighMassRatio(3), box3dTinyPyramid(), box3dOverlapRecovery(),
            box3dCardHouse(), box3dJenga(), box3dCylinderStack(), box3dCapsuleStack(), box3dWheelStack(),
            joltHeavyOnLight(), box3dEdgeCrossing(), joltHighSpeed()};
}

}  // namespace test_support
