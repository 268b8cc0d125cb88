#include "support/scene_builders.h"

namespace scene_builders {

using simcore::MotionType;

BodyId addGround(World& world, float friction, float restitution, float halfSize) {
    BodyCreationSettings g;
    g.name = "ground";
    g.motion = MotionType::Static;
    g.shape = Shape::box(Vec3(halfSize, 0.5f, halfSize));
    g.position = Vec3(0.0f, -0.5f, 0.0f);
    g.friction = friction;
    g.restitution = restitution;
    return world.createBody(g);
}

void addArena(World& world, float inner) {
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

BodyCreationSettings cube(const Vec3& position, float mass, float halfSize, float friction) {
    BodyCreationSettings b;
    b.name = "cube";
    b.shape = Shape::box(Vec3(halfSize));
    b.position = position;
    b.mass = mass;
    b.friction = friction;
    return b;
}

std::vector<Vec3> gridCentres(int nx, int ny, int nz, float spacing, float lowestY) {
    std::vector<Vec3> centres;
    const float centreX = 0.5f * static_cast<float>(nx - 1), centreZ = 0.5f * static_cast<float>(nz - 1);
    for (int y = 0; y < ny; ++y)
        for (int z = 0; z < nz; ++z)
            for (int x = 0; x < nx; ++x)
                centres.emplace_back((static_cast<float>(x) - centreX) * spacing, lowestY + static_cast<float>(y) * spacing,
                                     (static_cast<float>(z) - centreZ) * spacing);
    return centres;
}

std::vector<Vec3> towerCentres(int count) { return gridCentres(1, count, 1, 1.0f, 0.5f); }

std::vector<Vec3> squarePyramidCentres(int base) {
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

Incline::Incline(World& world, const Shape& shape, float offsetAlongNormal, float friction, float rollingResistance)
    : rotation(glm::angleAxis(kTheta, Vec3(0.0f, 0.0f, 1.0f))),
      normal(rotation * Vec3(0.0f, 1.0f, 0.0f)),
      downSlope(rotation * Vec3(-1.0f, 0.0f, 0.0f)) {
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

float Incline::slopeSpeed(const World& world) const { return glm::dot(world.linearVelocity(body), downSlope); }

}  // namespace scene_builders
