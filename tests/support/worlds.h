#pragma once
// Building blocks of the physics tests' worlds: settings, a ground, cubes, running for a time,
// and the energy the tests bound.

#include "simcore/world/world.h"

#include <cmath>
#include <vector>

namespace test_support {

using namespace simcore;

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

// Static ground: top face at y = 0.
inline BodyId addGround(World& world, float friction = 0.6f, float restitution = 0.0f, float halfSize = 50.0f) {
    BodyCreationSettings g;
    g.name = "ground";
    g.motion = MotionType::Static;
    g.shape = Shape::box(Vec3(halfSize, 0.5f, halfSize));
    g.position = Vec3(0.0f, -0.5f, 0.0f);
    g.friction = friction;
    g.restitution = restitution;
    return world.createBody(g);
}

// A ground with four static walls 4 m high around a square arena `inner` metres across, so that
// rolling bodies stay on it.
inline void addArena(World& world, float inner) {
    const float half = 0.5f * inner;
    addGround(world, 0.6f, 0.0f, half + 4.0f);
    for (int side = 0; side < 4; ++side) {
        BodyCreationSettings wall;
        wall.name = "wall";
        wall.motion = MotionType::Static;
        const bool alongX = side < 2;
        const float sign = side % 2 == 0 ? 1.0f : -1.0f;
        wall.shape = Shape::box(alongX ? Vec3(0.5f, 2.0f, half + 1.0f) : Vec3(half + 1.0f, 2.0f, 0.5f));
        wall.position = alongX ? Vec3(sign * (half + 0.5f), 2.0f, 0.0f) : Vec3(0.0f, 2.0f, sign * (half + 0.5f));
        world.createBody(wall);
    }
}

inline BodyCreationSettings cube(const Vec3& position, float mass = 1.0f, float halfSize = 0.5f, float friction = 0.6f) {
    BodyCreationSettings b;
    b.name = "cube";
    b.shape = Shape::box(Vec3(halfSize));
    b.position = position;
    b.mass = mass;
    b.friction = friction;
    return b;
}

// Centres of the unit cubes of a square pyramid standing on y = 0: `base` x `base` at the bottom,
// each layer one cube narrower and centred on the one below.
inline std::vector<Vec3> squarePyramidCentres(int base) {
    std::vector<Vec3> centres;
    for (int layer = 0; layer < base; ++layer) {
        const int side = base - layer;
        const float offset = -0.5f * static_cast<float>(side - 1);
        for (int z = 0; z < side; ++z)
            for (int x = 0; x < side; ++x)
                centres.emplace_back(offset + static_cast<float>(x), 0.5f + static_cast<float>(layer), offset + static_cast<float>(z));
    }
    return centres;
}

// A static 30 degree ramp (a thin box turned about z, rising towards +x) centred at the origin,
// with a body resting on its top face 8 m up the slope, exactly touching.
struct Incline {
    static constexpr float kTheta = kPi / 6.0f;  // 30 degrees
    Quat rotation = glm::angleAxis(kTheta, Vec3(0.0f, 0.0f, 1.0f));
    Vec3 normal = rotation * Vec3(0.0f, 1.0f, 0.0f);     // (-sin, cos, 0)
    Vec3 downSlope = rotation * Vec3(-1.0f, 0.0f, 0.0f);  // (-cos, -sin, 0)
    BodyId body;

    Incline(World& world, const Shape& shape, float offsetAlongNormal, float friction, float rollingResistance = 0.0f) {
        BodyCreationSettings ramp;
        ramp.name = "ramp";
        ramp.motion = MotionType::Static;
        ramp.shape = Shape::box(Vec3(12.0f, 0.1f, 2.0f));
        ramp.orientation = rotation;
        ramp.friction = friction;
        world.createBody(ramp);

        BodyCreationSettings b;
        b.name = "slider";
        b.shape = shape;
        b.mass = 1.0f;
        b.orientation = rotation;
        b.position = normal * (0.1f + offsetAlongNormal) - downSlope * 8.0f;
        b.friction = friction;  // both sides the same: the combined sqrt(mu mu) is mu
        b.rollingResistance = rollingResistance;  // the ramp's is 0: the pair's lever is C r
        body = world.createBody(b);
    }
    float slopeSpeed(const World& world) const { return glm::dot(world.linearVelocity(body), downSlope); }
};

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

}  // namespace test_support
