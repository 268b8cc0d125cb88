// interplay-bench-mesh: the mesh narrow phase's cost, a box over a 20 000-triangle terrain.
//
// The same rolling terrain (101 x 101 samples, 1 m cells, 20 000 triangles) as a HeightField and as
// the TriangleMesh of its samples; 1000 boxes (0.5 m, random orientation) placed on it, 0-10 cm
// deep. Times per box: the midphase query of the box's bounds (plus the speculative margin), and
// the query with collideTriangleConvex on every triangle it returns, best of several repeats.
// Then whole worlds: 1000 such boxes dropped on the terrain as each of the two, and on a box floor,
// stepped for STEPS steps (ms per step, and how many bodies ended with their centre below the
// surface, which must be none).
//   interplay-bench-mesh [REPEATS [STEPS]]   (defaults 20 and 300)

#include "simcore/collision/collide_mesh.h"
#include "simcore/shapes/height_field.h"
#include "simcore/shapes/triangle_mesh.h"
#include "simcore/world/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <vector>

#ifndef INTERPLAY_BUILD_TYPE
#define INTERPLAY_BUILD_TYPE "unknown"
#endif

using namespace simcore;

namespace {

constexpr int kSamples = 101;
constexpr float kCell = 1.0f;
constexpr int kBoxes = 1000;
constexpr float kSpeculative = 0.02f;  // m

struct Totals {
    double queryMicroseconds = 1e30, collideMicroseconds = 1e30;  // per box, best repeat
    std::size_t triangles = 0, manifolds = 0, points = 0;          // per pass over all boxes
};

template <class Surface>
Totals run(const Surface& surface, const Shape& box, const std::vector<Transform>& poses, int repeats) {
    Totals totals;
    using Clock = std::chrono::steady_clock;
    for (int r = 0; r < repeats; ++r) {
        std::size_t triangles = 0;
        auto start = Clock::now();
        for (const Transform& pose : poses) {
            Aabb bounds = worldBounds(box, pose);
            bounds.min -= Vec3(kSpeculative);
            bounds.max += Vec3(kSpeculative);
            surface.forEachTriangleOverlapping(bounds, [&](std::uint32_t) { ++triangles; });
        }
        const double query = std::chrono::duration<double, std::micro>(Clock::now() - start).count();
        std::size_t manifolds = 0, points = 0;
        start = Clock::now();
        for (const Transform& pose : poses) {
            Aabb bounds = worldBounds(box, pose);
            bounds.min -= Vec3(kSpeculative);
            bounds.max += Vec3(kSpeculative);
            surface.forEachTriangleOverlapping(bounds, [&](std::uint32_t t) {
                ContactManifold m;
                if (collideTriangleConvex(surface.triangle(t), box, pose, kSpeculative, m)) {
                    ++manifolds;
                    points += std::size_t(m.pointCount);
                }
            });
        }
        const double collide = std::chrono::duration<double, std::micro>(Clock::now() - start).count();
        totals.queryMicroseconds = std::min(totals.queryMicroseconds, query / double(poses.size()));
        totals.collideMicroseconds = std::min(totals.collideMicroseconds, collide / double(poses.size()));
        totals.triangles = triangles;
        totals.manifolds = manifolds;
        totals.points = points;
    }
    return totals;
}

void print(const char* name, const Totals& t, std::size_t boxes) {
    std::printf("%-12s query %6.3f us/box (%.1f triangles/box)   query+collide %7.3f us/box (%.2f manifolds, %.2f points/box)\n",
                name, t.queryMicroseconds, double(t.triangles) / double(boxes), t.collideMicroseconds,
                double(t.manifolds) / double(boxes), double(t.points) / double(boxes));
}

// 1000 boxes dropped from 1.5 m over the ground (a 32 x 32 grid, 3 m apart, over the 100 m
// square), stepped `steps` times. surfaceBelow(x, z) is the ground's height there.
template <class SurfaceHeight>
void dropBoxes(const char* name, const Shape& ground, const Vec3& groundPosition, SurfaceHeight surfaceBelow, int steps) {
    World world;
    BodyCreationSettings floor;
    floor.motion = MotionType::Static;
    floor.shape = ground;
    floor.position = groundPosition;
    world.createBody(floor);
    std::vector<BodyId> boxes;
    for (int i = 0; i < 32 && boxes.size() < std::size_t(kBoxes); ++i)
        for (int k = 0; k < 32 && boxes.size() < std::size_t(kBoxes); ++k) {
            BodyCreationSettings b;
            b.shape = Shape::box(Vec3(0.5f));
            const float x = 3.0f + 3.0f * float(i), z = 3.0f + 3.0f * float(k);
            b.position = Vec3(x, surfaceBelow(x, z) + 1.5f, z);
            b.orientation = glm::angleAxis(0.1f * float(i * 32 + k), glm::normalize(Vec3(1.0f, 2.0f, 3.0f)));
            boxes.push_back(world.createBody(b));
        }
    // Process CPU time (one thread: the default), so other work on a shared machine does not count.
    const std::clock_t start = std::clock();
    for (int s = 0; s < steps; ++s) world.step();
    const double ms = 1000.0 * double(std::clock() - start) / CLOCKS_PER_SEC;
    int below = 0, asleep = 0;
    for (BodyId id : boxes) {
        const Vec3 p = world.position(id);
        if (p.y < surfaceBelow(p.x, p.z)) ++below;
        if (!world.isAwake(id)) ++asleep;
    }
    std::printf("%-12s %zu boxes, %d steps: %7.3f ms/step (CPU); centres below the surface %d; asleep at the end %d\n", name,
                boxes.size(), steps, ms / double(steps), below, asleep);
}

}  // namespace

int main(int argc, char** argv) {
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 20;
    const int steps = argc > 2 ? std::max(1, std::atoi(argv[2])) : 300;
    std::vector<float> heights;
    for (int r = 0; r < kSamples; ++r)
        for (int c = 0; c < kSamples; ++c)
            heights.push_back(std::sin(0.21f * float(c)) + std::cos(0.17f * float(r)) + 0.3f * std::sin(0.9f * float(r + c)));
    const auto field = HeightField::build(kSamples, kSamples, kCell, 1.0f, heights).field;
    std::vector<Vec3> vertices;
    std::vector<TriangleMesh::Indices> triangles;
    for (int r = 0; r < kSamples; ++r)
        for (int c = 0; c < kSamples; ++c) vertices.push_back(field->sample(r, c));
    for (std::uint32_t t = 0; t < field->triangleCount(); ++t) {
        // Index the mesh's vertices by sample, so it is the field's surface exactly.
        const Triangle tri = field->triangle(t);
        TriangleMesh::Indices index{};
        for (int k = 0; k < 3; ++k)
            index[k] = std::uint32_t(std::lround(tri.vertices[k].z / kCell)) * kSamples + std::uint32_t(std::lround(tri.vertices[k].x / kCell));
        triangles.push_back(index);
    }
    const auto mesh = TriangleMesh::build(vertices, triangles).mesh;

    const Shape box = Shape::box(Vec3(0.5f));
    std::mt19937 random(1);
    std::uniform_real_distribution<float> position(2.0f, 98.0f), unit(-1.0f, 1.0f), depth(0.0f, 0.1f);
    std::vector<Transform> poses;
    for (int i = 0; i < kBoxes; ++i) {
        Transform pose{{position(random), 0.0f, position(random)},
                       glm::normalize(Quat(unit(random), unit(random), unit(random), unit(random)))};
        const auto under = field->rayCast(pose.position + Vec3(0, 100, 0), {0, -200, 0});
        const Vec3 lowest = pose.rotate(support(box, pose.rotateInverse(Vec3(0, -1, 0))));
        pose.position.y = (under ? under->point.y : 0.0f) - lowest.y - depth(random);
        poses.push_back(pose);
    }

    std::printf("interplay-bench-mesh (%s build): %zu triangles, %d boxes of 1 m, best of %d repeats\n",
                INTERPLAY_BUILD_TYPE, mesh->triangleCount(), kBoxes, repeats);
    print("heightField", run(*field, box, poses, repeats), poses.size());
    print("mesh", run(*mesh, box, poses, repeats), poses.size());

    const auto terrainHeight = [&](float x, float z) {
        const auto under = field->rayCast(Vec3(x, 100.0f, z), Vec3(0.0f, -200.0f, 0.0f));
        return under ? under->point.y : -1e9f;
    };
    dropBoxes("heightField", Shape::heightFieldOf(field), Vec3(0.0f), terrainHeight, steps);
    dropBoxes("mesh", Shape::triangleMesh(mesh), Vec3(0.0f), terrainHeight, steps);
    dropBoxes("box floor", Shape::box(Vec3(50.0f, 0.5f, 50.0f)), Vec3(50.0f, -0.5f, 50.0f),
              [](float, float) { return 0.0f; }, steps);
    return 0;
}
