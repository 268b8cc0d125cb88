#pragma once
// The scenes that tests and benchmarks build in code: a static ground, an arena, cubes, and the
// centres of towers, pyramids, grids and piles of cubes, and a 30 degree incline. One place, so a
// "ground" or a "pile" means the same body everywhere. Library interplay_scene_builders (simcore
// only). Bodies are created in the order and with the values documented here: the suites' bounds
// and the benchmarks' tables depend on both.

#include "simcore/world/world.h"

#include <vector>

namespace scene_builders {

using simcore::BodyCreationSettings;
using simcore::BodyId;
using simcore::Quat;
using simcore::Shape;
using simcore::Vec3;
using simcore::World;

// Static ground: a box 1 m thick whose top face is y = 0, `halfSize` either way in x and z.
BodyId addGround(World& world, float friction = 0.6f, float restitution = 0.0f, float halfSize = 50.0f);

// A ground with four static walls 4 m high around a square arena `inner` metres across, so that
// rolling bodies stay on it: the ground first, then the walls at +x, -x, +z, -z.
void addArena(World& world, float inner);

// A dynamic cube of `mass` kg (not a density: the tests reason in masses).
BodyCreationSettings cube(const Vec3& position, float mass = 1.0f, float halfSize = 0.5f, float friction = 0.6f);

// Centres of a box of nx x ny x nz cubes `spacing` apart, centred on the y axis, the lowest layer's
// centres at `lowestY`: x fastest, then z, then y (layer by layer, from the bottom). A pile of n
// cubes is the first n of a grid large enough to hold them.
std::vector<Vec3> gridCentres(int nx, int ny, int nz, float spacing, float lowestY);

// Centres of a tower of `count` unit cubes standing on y = 0, touching: (0, 0.5 + i, 0).
std::vector<Vec3> towerCentres(int count);

// Centres of the unit cubes of a square pyramid standing on y = 0: `base` x `base` at the bottom,
// each layer one cube narrower and centred on the one below.
std::vector<Vec3> squarePyramidCentres(int base);

// A static 30 degree ramp (a box 12 x 0.1 x 2 m in half extents turned about z, rising towards +x)
// centred at the origin, with a 1 kg body of `shape` resting on its top face 8 m up the slope,
// `offsetAlongNormal` from it (the shape's half height to touch exactly). Both have `friction`.
struct Incline {
    static constexpr float kTheta = simcore::kPi / 6.0f;  // 30 degrees
    Quat rotation;
    Vec3 normal;     // (-sin, cos, 0)
    Vec3 downSlope;  // (-cos, -sin, 0)
    BodyId body;

    Incline(World& world, const Shape& shape, float offsetAlongNormal, float friction, float rollingResistance = 0.0f);
    float slopeSpeed(const World& world) const;
};

}  // namespace scene_builders
