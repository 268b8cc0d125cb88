// interplay-bench-bullet: simcore against Bullet 3 on identical scenes, stepped in the same process.
//
// Each scene is read once through simcore's own loader; the simcore world comes from buildWorld(),
// the Bullet world is built body by body from the same simcore::Scene (same shapes, masses,
// inertia tensors, poses, velocities, friction, restitution, gravity, time step). Only the stepping
// loops are timed. Both engines run at their own default solver settings; what those are is printed
// with the results. See usageText() for the options.

#include "simcore/io/scene.h"
#include "simcore/io/scene_io.h"
#include "simcore/shapes/shape.h"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#ifndef INTERPLAY_SOURCE_DIR
#define INTERPLAY_SOURCE_DIR "."
#endif
#ifndef INTERPLAY_BUILD_TYPE
#define INTERPLAY_BUILD_TYPE "unknown"
#endif
#ifndef INTERPLAY_BULLET_VERSION
#define INTERPLAY_BULLET_VERSION "?"
#endif

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// ----------------------------------------------------------------------------------------------
// Scenes and what to measure

// Stability measure of a scene (issue 3, "Scenes and benchmark"):
//  Resting: everything starts at rest, exactly in contact; the largest displacement of any dynamic
//           body from its start position at the end tells whether the structure stood.
//  Pile:    bodies are dropped; report how many are still awake at the end and whether any fell
//           below y = -1 (through the ground: tunnelling, or no contacts at all).
enum class Measure { Resting, Pile };

struct KnownScene {
    const char* name;
    std::uint64_t steps;
    Measure measure;
};
constexpr KnownScene kKnownScenes[] = {
    {"pile1k", 600, Measure::Pile},
    {"pyramid10", 600, Measure::Resting},
    {"mixed1k", 600, Measure::Pile},
    {"tower20", 3600, Measure::Resting},
};

constexpr float kStandingTolerance = 0.05f;  // m: a resting structure "stands" if no body moved more
constexpr float kBelowGroundY = -1.0f;       // m: a centre of mass below this has left the ground

const char* usageText() {
    return "usage: interplay-bench-bullet [--scene NAME]... [--steps N] [--repeat R] [--scenes-dir DIR]\n"
           "\n"
           "Steps each scene in simcore and in Bullet 3 (same scene, same process) and prints a Markdown\n"
           "table of milliseconds per step, their ratio and a stability check for each engine.\n"
           "\n"
           "  --scene NAME      scene to run: DIR/NAME.json, or a path to a .json file; repeatable\n"
           "                    (default: pile1k pyramid10 mixed1k tower20)\n"
           "  --steps N         steps per scene (default: pile1k 600, pyramid10 600, mixed1k 600,\n"
           "                    tower20 3600; other scenes 600)\n"
           "  --repeat R        run each scene R times and keep each engine's fastest run (default 1)\n"
           "  --scenes-dir DIR  where NAME.json is looked up (default: " INTERPLAY_SOURCE_DIR "/scenes/bench)\n"
           "  --help            this text\n"
           "\n"
           "Exit status: 0 done; 2 bad arguments; 3 a scene that cannot be read or built;\n"
           "4 simcore produced a non-finite value (the table is printed first).\n";
}

struct Options {
    std::vector<std::string> scenes;
    std::optional<std::uint64_t> steps;
    int repeat = 1;
    fs::path scenesDir = fs::path(INTERPLAY_SOURCE_DIR) / "scenes" / "bench";
};

template <typename T>
bool parseNumber(const std::string& text, T& out, T minimum) {
    try {
        std::size_t used = 0;
        const long long v = std::stoll(text, &used);
        if (used != text.size() || v < static_cast<long long>(minimum)) return false;
        out = static_cast<T>(v);
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

// Returns an error message, or nothing.
std::optional<std::string> parseArguments(int argc, char** argv, Options& options, bool& help) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&](std::string& out) -> bool {
            if (i + 1 >= argc) return false;
            out = argv[++i];
            return true;
        };
        std::string v;
        if (arg == "--help" || arg == "-h") {
            help = true;
        } else if (arg == "--scene") {
            if (!value(v) || v.empty()) return "--scene needs a scene name";
            options.scenes.push_back(v);
        } else if (arg == "--steps") {
            std::uint64_t n = 0;
            if (!value(v) || !parseNumber<std::uint64_t>(v, n, 1)) return "--steps needs a whole number >= 1";
            options.steps = n;
        } else if (arg == "--repeat") {
            int n = 0;
            if (!value(v) || !parseNumber<int>(v, n, 1)) return "--repeat needs a whole number >= 1";
            options.repeat = n;
        } else if (arg == "--scenes-dir") {
            if (!value(v) || v.empty()) return "--scenes-dir needs a directory";
            options.scenesDir = v;
        } else {
            return "unknown argument '" + arg + "'";
        }
    }
    if (options.scenes.empty())
        for (const KnownScene& k : kKnownScenes) options.scenes.push_back(k.name);
    return std::nullopt;
}

const KnownScene* findKnown(const std::string& name) {
    for (const KnownScene& k : kKnownScenes)
        if (name == k.name) return &k;
    return nullptr;
}

// ----------------------------------------------------------------------------------------------
// What each engine reports after a run

struct RunResult {
    double ms = std::numeric_limits<double>::infinity();  // stepping loop only
    std::uint64_t steps = 0;
    bool finite = true;
    std::string nonFiniteBody;
    float maxDisplacement = 0.0f;  // m, body origin, end vs start, over dynamic bodies
    std::size_t awake = 0;         // dynamic bodies awake / active at the end
    std::size_t belowGround = 0;   // dynamic bodies whose centre of mass ended below kBelowGroundY
};

bool isFinite(const simcore::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// ----------------------------------------------------------------------------------------------
// simcore

RunResult runSimcore(const simcore::Scene& scene, std::uint64_t steps) {
    simcore::BuiltWorld built = simcore::buildWorld(scene);
    simcore::World& world = built.world;

    const auto start = Clock::now();
    for (std::uint64_t s = 0; s < steps; ++s) world.step();
    const auto end = Clock::now();

    RunResult r;
    r.ms = std::chrono::duration<double, std::milli>(end - start).count();
    r.steps = steps;
    if (auto bad = world.findNonFiniteBody()) {
        r.finite = false;
        r.nonFiniteBody = bad->name + " (" + bad->quantity + ")";
    }
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const simcore::BodyCreationSettings& b = scene.bodies[i].body;
        if (b.motion != simcore::MotionType::Dynamic) continue;
        const simcore::BodyId id = built.bodyIds[i];
        const simcore::Vec3 p = world.position(id);
        const simcore::Vec3 com = world.centerOfMass(id);
        if (!isFinite(p) || !isFinite(com)) continue;
        r.maxDisplacement = std::max(r.maxDisplacement, glm::length(p - b.position));
        if (world.isAwake(id)) ++r.awake;
        if (com.y < kBelowGroundY) ++r.belowGround;
    }
    return r;
}

// ----------------------------------------------------------------------------------------------
// Bullet

btVector3 toBt(const simcore::Vec3& v) { return btVector3(v.x, v.y, v.z); }
btQuaternion toBt(const simcore::Quat& q) { return btQuaternion(q.x, q.y, q.z, q.w); }  // Bullet: (x, y, z, w)
simcore::Vec3 fromBt(const btVector3& v) { return simcore::Vec3(v.x(), v.y(), v.z()); }

// Everything a Bullet world needs, owned together and destroyed in the right order.
class BulletWorld {
public:
    BulletWorld()
        : dispatcher_(&configuration_),
          world_(&dispatcher_, &broadphase_, &solver_, &configuration_) {}

    ~BulletWorld() {
        for (int i = world_.getNumCollisionObjects() - 1; i >= 0; --i)
            world_.removeCollisionObject(world_.getCollisionObjectArray()[i]);
    }
    BulletWorld(const BulletWorld&) = delete;
    BulletWorld& operator=(const BulletWorld&) = delete;

    btDiscreteDynamicsWorld& world() { return world_; }

    btCollisionShape* addShape(std::unique_ptr<btCollisionShape> shape) {
        shapes_.push_back(std::move(shape));
        return shapes_.back().get();
    }
    btRigidBody* addBody(std::unique_ptr<btRigidBody> body) {
        bodies_.push_back(std::move(body));
        return bodies_.back().get();
    }

private:
    // Declaration order is construction order: the world needs all of these.
    btDefaultCollisionConfiguration configuration_;
    btCollisionDispatcher dispatcher_;
    btDbvtBroadphase broadphase_;
    btSequentialImpulseConstraintSolver solver_;
    btDiscreteDynamicsWorld world_;
    std::vector<std::unique_ptr<btCollisionShape>> shapes_;
    std::vector<std::unique_ptr<btRigidBody>> bodies_;
};

// A scene body in Bullet. Bullet places a body by its centre of mass with the inertia tensor
// diagonal in the body frame, so `principal` (body origin frame -> principal frame) is kept to get
// the authored origin back.
struct BulletBody {
    btRigidBody* body = nullptr;
    btTransform principal = btTransform::getIdentity();
    bool dynamic = false;
    simcore::Vec3 startOrigin{0.0f};
};

struct BuildNotes {
    bool kinematicAsStatic = false;
    bool hulls = false;
};

struct BulletScene {
    std::unique_ptr<BulletWorld> world;
    std::vector<BulletBody> bodies;
};

BulletScene buildBullet(const simcore::Scene& scene, BuildNotes& notes) {
    BulletScene out;
    out.world = std::make_unique<BulletWorld>();
    btDiscreteDynamicsWorld& world = out.world->world();

    const simcore::WorldSettings& settings = scene.settings;
    const bool gravityOn = settings.effects[simcore::Effect::Gravity];
    world.setGravity(gravityOn ? toBt(settings.gravity) : btVector3(0, 0, 0));

    // simcore damping: v <- v exp(-rate dt). Bullet: v <- v (1 - d)^dt. Same when 1 - d = exp(-rate).
    const bool dampingOn = settings.effects[simcore::Effect::Damping];
    const btScalar linearDamping = dampingOn ? btScalar(1.0 - std::exp(-double(settings.damping.linear))) : 0;
    const btScalar angularDamping = dampingOn ? btScalar(1.0 - std::exp(-double(settings.damping.angular))) : 0;
    const bool sleepOn = settings.sleep.enabled && settings.effects[simcore::Effect::Sleeping];

    for (const simcore::SceneBody& sb : scene.bodies) {
        const simcore::BodyCreationSettings& b = sb.body;
        const simcore::Shape& shape = b.shape;
        const bool dynamic = b.motion == simcore::MotionType::Dynamic;
        if (b.motion == simcore::MotionType::Kinematic) notes.kinematicAsStatic = true;

        // Mass properties from simcore (exact closed forms), so both engines move the same bodies.
        // (Bullet's own calculateLocalInertia approximates capsules by their bounding box.)
        simcore::MassProperties mp;
        if (dynamic)
            mp = b.mass ? simcore::massPropertiesForMass(shape, *b.mass) : simcore::massProperties(shape, b.density);

        BulletBody bb;
        bb.dynamic = dynamic;
        bb.startOrigin = b.position;
        btVector3 localInertia(0, 0, 0);
        btCollisionShape* collisionShape = nullptr;

        switch (shape.type) {
        case simcore::ShapeType::Box:
            collisionShape = out.world->addShape(std::make_unique<btBoxShape>(toBt(shape.halfExtents)));
            break;
        case simcore::ShapeType::Sphere:
            collisionShape = out.world->addShape(std::make_unique<btSphereShape>(shape.radius));
            break;
        case simcore::ShapeType::Capsule:
            // Bullet's height is the straight part: 2 * halfHeight. Along Y, as in simcore.
            collisionShape = out.world->addShape(std::make_unique<btCapsuleShape>(shape.radius, 2.0f * shape.halfHeight));
            break;
        case simcore::ShapeType::Cylinder:
            collisionShape = out.world->addShape(
                std::make_unique<btCylinderShape>(btVector3(shape.radius, shape.halfHeight, shape.radius)));
            break;
        case simcore::ShapeType::ConvexHull: {
            notes.hulls = true;
            // Points in the principal frame: centred on the centre of mass, along the axes in which
            // the inertia tensor is diagonal.
            btMatrix3x3 rot = btMatrix3x3::getIdentity();
            btVector3 com(0, 0, 0);
            if (dynamic) {
                btMatrix3x3 inertia;
                for (int r = 0; r < 3; ++r)
                    for (int c = 0; c < 3; ++c) inertia[r][c] = mp.inertia[c][r];  // GLM is column-major
                btMatrix3x3 diag = inertia;
                diag.diagonalize(rot, btScalar(1e-9), 64);  // inertia == rot * diag * rot^T
                localInertia = btVector3(diag[0][0], diag[1][1], diag[2][2]);
                com = toBt(mp.centerOfMass);
            }
            bb.principal = btTransform(rot, com);
            auto hull = std::make_unique<btConvexHullShape>();
            const btTransform toPrincipal = bb.principal.inverse();
            for (const simcore::Vec3& p : shape.hull->vertices()) hull->addPoint(toPrincipal(toBt(p)), false);
            hull->recalcLocalAabb();
            collisionShape = out.world->addShape(std::move(hull));
            break;
        }
        case simcore::ShapeType::Compound:
        case simcore::ShapeType::Mesh:
        case simcore::ShapeType::HeightField:
            throw std::runtime_error("the Bullet comparison does not build " +
                                     std::string(simcore::shapeTypeName(shape.type)) + " shapes (body " + b.name + ")");
        }

        if (dynamic && shape.type != simcore::ShapeType::ConvexHull) {
            // Primitives: centre of mass at the origin, inertia diagonal in the shape's axes.
            localInertia = btVector3(mp.inertia[0][0], mp.inertia[1][1], mp.inertia[2][2]);
        }

        const btTransform originTransform(toBt(b.orientation), toBt(b.position));
        btRigidBody::btRigidBodyConstructionInfo info(dynamic ? mp.mass : btScalar(0), nullptr, collisionShape,
                                                      localInertia);
        info.m_startWorldTransform = originTransform * bb.principal;
        info.m_friction = b.friction;
        info.m_restitution = b.restitution;
        info.m_linearDamping = linearDamping;
        info.m_angularDamping = angularDamping;
        btRigidBody* body = out.world->addBody(std::make_unique<btRigidBody>(info));
        if (dynamic) {
            body->setLinearVelocity(toBt(b.linearVelocity));
            body->setAngularVelocity(toBt(b.angularVelocity));
            if (!sleepOn) body->setActivationState(DISABLE_DEACTIVATION);
            if (b.ccd) {
                // Bullet's swept-sphere CCD for bodies the scene marks; off otherwise (Bullet's default).
                const float extent = simcore::minimumExtent(shape);
                body->setCcdMotionThreshold(0.5f * extent);
                body->setCcdSweptSphereRadius(0.4f * extent);
            }
        }
        world.addRigidBody(body);
        bb.body = body;
        out.bodies.push_back(bb);
    }
    return out;
}

RunResult runBullet(const simcore::Scene& scene, std::uint64_t steps, BuildNotes& notes) {
    BulletScene bs = buildBullet(scene, notes);
    btDiscreteDynamicsWorld& world = bs.world->world();
    const btScalar dt = scene.settings.timeStep;

    const auto start = Clock::now();
    for (std::uint64_t s = 0; s < steps; ++s) world.stepSimulation(dt, 0);  // 0 substeps: exactly one step of dt
    const auto end = Clock::now();

    RunResult r;
    r.ms = std::chrono::duration<double, std::milli>(end - start).count();
    r.steps = steps;
    for (std::size_t i = 0; i < bs.bodies.size(); ++i) {
        const BulletBody& bb = bs.bodies[i];
        if (!bb.dynamic) continue;
        const btTransform& com = bb.body->getWorldTransform();
        const simcore::Vec3 origin = fromBt((com * bb.principal.inverse()).getOrigin());
        const simcore::Vec3 c = fromBt(com.getOrigin());
        if (!isFinite(origin) || !isFinite(c)) {
            if (r.finite) r.nonFiniteBody = scene.bodies[i].body.name;
            r.finite = false;
            continue;
        }
        r.maxDisplacement = std::max(r.maxDisplacement, glm::length(origin - bb.startOrigin));
        if (bb.body->isActive()) ++r.awake;
        if (c.y < kBelowGroundY) ++r.belowGround;
    }
    return r;
}

// Bullet's defaults as this program uses them, read from a world rather than restated.
std::string bulletSettingsText() {
    BulletWorld bw;
    const btContactSolverInfo& info = bw.world().getSolverInfo();
    btRigidBody::btRigidBodyConstructionInfo ci(1, nullptr, nullptr);
    btBoxShape box(btVector3(0.5, 0.5, 0.5));
    std::ostringstream s;
    s << "Bullet " << INTERPLAY_BULLET_VERSION << " (single precision; btGetVersion " << btGetVersion()
      << "): btDiscreteDynamicsWorld, btDbvtBroadphase, btSequentialImpulseConstraintSolver at its defaults: "
      << info.m_numIterations << " iterations, split impulse " << (info.m_splitImpulse ? "on" : "off")
      << " (threshold " << info.m_splitImpulsePenetrationThreshold << " m), ERP " << info.m_erp
      << ", warm starting " << info.m_warmstartingFactor << "; stepSimulation(dt, 0) = exactly one step of dt "
      << "per frame; collision margin " << box.getMargin() << " m (inside boxes and cylinders, outside hulls); "
      << "friction and restitution combined by product (cube on cube 0.6 x 0.6 = 0.36); sleeping at "
      << ci.m_linearSleepingThreshold << " m/s and " << ci.m_angularSleepingThreshold << " rad/s for "
      << gDeactivationTime << " s where the scene allows sleep, never where it does not; no CCD unless a "
      << "body sets \"ccd\"; masses and inertia tensors from simcore.";
    return s.str();
}

// ----------------------------------------------------------------------------------------------
// Machine

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) {
                std::string v = line.substr(colon + 1);
                v.erase(0, v.find_first_not_of(" \t"));
                return v;
            }
        }
    }
    return "unknown CPU";
}

int cpuCount() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    int n = 0;
    while (std::getline(in, line))
        if (line.rfind("processor", 0) == 0) ++n;
    return n > 0 ? n : static_cast<int>(std::thread::hardware_concurrency());
}

// ----------------------------------------------------------------------------------------------
// Report

std::string fixed(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string msText(double msPerStep) {
    return fixed(msPerStep, msPerStep < 0.1 ? 4 : 3);
}

std::string stabilityText(const RunResult& r, Measure measure, std::size_t dynamicBodies) {
    if (!r.finite) return "non-finite (" + r.nonFiniteBody + ")";
    std::string below;
    if (r.belowGround > 0)
        below = ", " + std::to_string(r.belowGround) + " below ground";
    if (measure == Measure::Resting) {
        const bool standing = r.maxDisplacement < kStandingTolerance;
        return std::string(standing ? "standing" : "fell") + ", max disp " + fixed(r.maxDisplacement, 3) + " m" + below;
    }
    return std::to_string(r.awake) + "/" + std::to_string(dynamicBodies) + " awake, " +
           (r.belowGround > 0 ? std::to_string(r.belowGround) + " below ground" : "none below ground");
}

struct SceneRow {
    std::string name;
    std::size_t dynamicBodies = 0;
    std::uint64_t steps = 0;
    Measure measure = Measure::Pile;
    RunResult simcore, bullet;
    std::string simcoreSettings;
};

}  // namespace

int main(int argc, char** argv) {
    Options options;
    bool help = false;
    if (auto error = parseArguments(argc, argv, options, help)) {
        std::cerr << "interplay-bench-bullet: " << *error << "\n\n" << usageText();
        return 2;
    }
    if (help) {
        std::cout << usageText();
        return 0;
    }

    std::vector<SceneRow> rows;
    BuildNotes notes;
    bool simcoreNonFinite = false;
    std::set<std::string> simcoreSettingsSeen;

    for (const std::string& name : options.scenes) {
        const bool isPath = name.find('/') != std::string::npos || fs::path(name).extension() == ".json";
        const fs::path path = isPath ? fs::path(name) : options.scenesDir / (name + ".json");
        const std::string label = isPath ? fs::path(name).stem().string() : name;

        simcore::SceneLoadResult loaded = simcore::loadSceneFile(path);
        for (const simcore::Diagnostic& d : loaded.diagnostics) std::cerr << d.toString() << '\n';
        if (!loaded.ok()) {
            std::cerr << "interplay-bench-bullet: cannot read scene '" << name << "' (" << path.string() << ")\n";
            return 3;
        }
        const simcore::Scene& scene = *loaded.scene;

        SceneRow row;
        row.name = label;
        const KnownScene* known = findKnown(label);
        row.steps = options.steps ? *options.steps : (known ? known->steps : 600);
        // Unknown scenes: "resting" when sleep is off (the benchmark's convention for structures
        // that must stand), otherwise a pile.
        row.measure = known ? known->measure : (scene.settings.sleep.enabled ? Measure::Pile : Measure::Resting);
        for (const simcore::SceneBody& b : scene.bodies)
            if (b.body.motion == simcore::MotionType::Dynamic) ++row.dynamicBodies;
        {
            const simcore::WorldSettings& s = scene.settings;
            std::ostringstream text;
            text << "dt " << s.timeStep << " s, " << s.substeps << " substep" << (s.substeps == 1 ? "" : "s") << ", "
                 << s.solver.velocityIterations << " velocity / " << s.solver.positionIterations
                 << " position iterations";
            row.simcoreSettings = text.str();
            simcoreSettingsSeen.insert(row.simcoreSettings);
        }

        std::cerr << "interplay-bench-bullet: " << label << ": " << row.dynamicBodies << " bodies, " << row.steps
                  << " steps, " << options.repeat << " run" << (options.repeat == 1 ? "" : "s") << std::flush;
        try {
            for (int run = 0; run < options.repeat; ++run) {
                // Alternate which engine goes first, so neither always runs on a warmer (or busier) machine.
                RunResult s, b;
                if (run % 2 == 0) {
                    s = runSimcore(scene, row.steps);
                    b = runBullet(scene, row.steps, notes);
                } else {
                    b = runBullet(scene, row.steps, notes);
                    s = runSimcore(scene, row.steps);
                }
                if (s.ms < row.simcore.ms) row.simcore = s;
                if (b.ms < row.bullet.ms) row.bullet = b;
                std::cerr << '.' << std::flush;
            }
        } catch (const std::exception& e) {
            std::cerr << "\ninterplay-bench-bullet: " << path.string() << ": " << e.what() << '\n';
            return 3;
        }
        std::cerr << '\n';
        if (!row.simcore.finite) simcoreNonFinite = true;
        rows.push_back(std::move(row));
    }

    // ---- Report (stdout, Markdown)
    std::cout << "## simcore vs Bullet 3\n\n";
    std::cout << "- Machine: " << cpuModel() << ", " << cpuCount() << " logical CPUs (both engines single-threaded)\n";
    std::cout << "- Build: " << INTERPLAY_BUILD_TYPE << ", " <<
#if defined(__clang__)
        "clang " << __clang_version__
#elif defined(__GNUC__)
        "GCC " << __VERSION__
#else
        "unknown compiler"
#endif
              << "; simcore and this program compiled with it, Bullet is the system library\n";
    std::cout << "- simcore: the scene's settings, engine defaults for keys the scene leaves out (";
    bool first = true;
    for (const std::string& s : simcoreSettingsSeen) {
        std::cout << (first ? "" : "; ") << s;
        first = false;
    }
    std::cout << ")\n";
    std::cout << "- " << bulletSettingsText() << "\n";
    std::cout << "- Timing: wall clock (steady_clock) of the stepping loop only, not building or measuring; "
              << (options.repeat > 1 ? "fastest of " + std::to_string(options.repeat) + " runs per engine"
                                     : std::string("one run per engine"))
              << "; the engines run one after the other in this process.\n";
    std::cout << "- ratio = Bullet ms / simcore ms: above 1 means simcore is faster.\n";
    std::cout << "- Stability, at the end of the run: for resting structures (tower20, pyramid10) the largest "
                 "displacement of any body from where it started, \"standing\" if under "
              << fixed(kStandingTolerance, 2)
              << " m; for piles (pile1k, mixed1k) how many bodies are still awake/active and how many fell below "
                 "y = " << fixed(kBelowGroundY, 0) << " m (through the ground).\n";
    if (notes.kinematicAsStatic)
        std::cout << "- Note: kinematic bodies are static in the Bullet world (this program does not drive them).\n";
    if (notes.hulls)
        std::cout << "- Note: Bullet's convex hulls are inflated by their collision margin; simcore's are not.\n";
    std::cout << "\n";

    std::cout << "| scene | bodies | steps | simcore ms/step | Bullet ms/step | ratio | simcore stability | Bullet stability |\n";
    std::cout << "|---|--:|--:|--:|--:|--:|---|---|\n";
    for (const SceneRow& row : rows) {
        const double sMs = row.simcore.ms / double(row.simcore.steps);
        const double bMs = row.bullet.ms / double(row.bullet.steps);
        std::cout << "| " << row.name << " | " << row.dynamicBodies << " | " << row.steps << " | " << msText(sMs)
                  << " | " << msText(bMs) << " | " << (sMs > 0 ? fixed(bMs / sMs, 2) : std::string("-")) << " | "
                  << stabilityText(row.simcore, row.measure, row.dynamicBodies) << " | "
                  << stabilityText(row.bullet, row.measure, row.dynamicBodies) << " |\n";
    }
    std::cout.flush();
    return simcoreNonFinite ? 4 : 0;
}
