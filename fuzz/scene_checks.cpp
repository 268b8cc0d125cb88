#include "scene_checks.h"

#include "simcore/io/scene_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>
#include <string>
#include <vector>

namespace fuzz {

namespace {

constexpr std::size_t kMaxDiagnostics = 100;  // simcore::io_detail::kMaxDiagnostics (internal header)

[[noreturn]] void fail(const std::string& what, const std::vector<simcore::Diagnostic>& diagnostics = {}) {
    std::fprintf(stderr, "fuzz check failed: %s\n", what.c_str());
    for (std::size_t i = 0; i < diagnostics.size() && i < 10; ++i)
        std::fprintf(stderr, "  %s\n", diagnostics[i].toString().c_str());
    std::fflush(stderr);
    std::abort();
}

bool hasError(const std::vector<simcore::Diagnostic>& diagnostics) {
    return std::any_of(diagnostics.begin(), diagnostics.end(),
                       [](const simcore::Diagnostic& d) { return d.severity == simcore::Diagnostic::Severity::Error; });
}

simcore::SceneLoadResult parse(std::string_view text, const char* name) {
    try {
        return simcore::parseScene(text, name);
    } catch (const std::exception& e) {
        fail(std::string("parseScene threw: ") + e.what());
    }
}

bool finite(const simcore::Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool strictFinite() {
    static const bool strict = std::getenv("INTERPLAY_FUZZ_STRICT_FINITE") != nullptr;
    return strict;
}

}  // namespace

void checkLoad(std::string_view text) {
    const simcore::SceneLoadResult r = parse(text, "fuzz.json");
    if (r.diagnostics.size() > kMaxDiagnostics + 1)
        fail(std::to_string(r.diagnostics.size()) + " diagnostics, more than the cap", r.diagnostics);
    for (const simcore::Diagnostic& d : r.diagnostics) {
        if (d.file != "fuzz.json") fail("a diagnostic does not name the file", r.diagnostics);
        if (d.message.empty()) fail("a diagnostic with an empty message", r.diagnostics);
        if (d.line < 0 || d.column < 0 || (d.line > 0) != (d.column > 0)) fail("a diagnostic with a bad position", r.diagnostics);
    }
    if (!r.ok()) {
        if (!hasError(r.diagnostics)) fail("a scene refused without an error", r.diagnostics);
        return;
    }
    if (hasError(r.diagnostics)) fail("a scene accepted despite an error", r.diagnostics);

    try {
        (void)simcore::buildWorld(*r.scene);
    } catch (const std::exception& e) {
        fail(std::string("an accepted scene does not build (a gap in the loader's checks): ") + e.what());
    }

    const std::string saved = simcore::serializeScene(*r.scene);
    const simcore::SceneLoadResult again = parse(saved, "saved.json");
    if (!again.ok()) fail("a saved scene does not load back:\n" + saved.substr(0, 4000), again.diagnostics);
    if (!again.diagnostics.empty()) fail("a saved scene loads back with diagnostics", again.diagnostics);
    const std::string resaved = simcore::serializeScene(*again.scene);
    if (resaved != saved) fail("save -> load -> save changed the text:\n" + saved.substr(0, 2000) + "\n--- became ---\n" + resaved.substr(0, 2000));
}

void checkStep(std::string_view text) {
    simcore::SceneLoadResult r = parse(text, "fuzz.json");
    if (!r.ok() || r.scene->bodies.size() > kMaxBodies) return;
    simcore::Scene& scene = *r.scene;
    // Bounded work per input: what these clamp is the number of passes, not what a pass computes.
    scene.settings.substeps = std::min(scene.settings.substeps, 8);
    scene.settings.solver.velocityIterations = std::min(scene.settings.solver.velocityIterations, 16);
    scene.settings.solver.positionIterations = std::min(scene.settings.solver.positionIterations, 8);

    std::optional<simcore::BuiltWorld> built;
    try {
        built.emplace(simcore::buildWorld(scene));
    } catch (const std::exception& e) {
        fail(std::string("an accepted scene does not build (a gap in the loader's checks): ") + e.what());
    }
    simcore::World& world = built->world;
    for (int step = 1; step <= kSteps; ++step) {
        world.step();
        if (const auto bad = world.findNonFiniteBody()) {
            // The runner's exit 4: an error, reported. Not a failure of this check (the brief allows
            // it), unless INTERPLAY_FUZZ_STRICT_FINITE is set, to hunt for such states.
            if (strictFinite())
                fail("body '" + bad->name + "' has a non-finite " + bad->quantity + " at step " + std::to_string(step));
            return;
        }
        // What the runner would print with exit 0 must be finite: every body's origin (computed
        // from the centre of mass the check above covers), orientation and velocities.
        for (const simcore::BodyId id : world.bodyIds())
            if (!finite(world.position(id)))
                fail("body '" + world.name(id) + "' has a non-finite origin at step " + std::to_string(step) +
                     " that findNonFiniteBody does not report");
    }
    const double kinetic = world.kineticEnergy(), potential = world.potentialEnergy();
    if (!std::isfinite(kinetic) || !std::isfinite(potential) || !finite(world.linearMomentum()) ||
        !finite(world.angularMomentum()))
        fail("finite bodies, but a non-finite energy or momentum in the report (kinetic " + std::to_string(kinetic) +
             ", potential " + std::to_string(potential) + ")");
}

}  // namespace fuzz
