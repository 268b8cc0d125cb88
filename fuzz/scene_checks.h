#pragma once
// What must hold for every input, whatever its bytes: the checks behind the fuzz targets and their
// regression replays. A violated check prints what went wrong and aborts, which libFuzzer records
// as a crash (and saves the input) and ctest as a failure.

#include <cstddef>
#include <string_view>

namespace fuzz {

// The loader (v1 and thesis format): parseScene returns, never throws, and either
//  - refuses the text with at least one error and at most kMaxDiagnostics + 1 diagnostics, each
//    naming the file and saying something; or
//  - accepts it with no error, and then the scene builds a World without an exception, saves to
//    text that loads back with no diagnostic at all, and that text saves again to the same bytes
//    (save -> load is exact in every number).
void checkLoad(std::string_view text);

// The step: an accepted scene is built and stepped kSteps times. After every step either
// World::findNonFiniteBody names a body (the runner's exit 4, an error reported: the run stops
// there; with INTERPLAY_FUZZ_STRICT_FINITE set in the environment it is a failure instead), or
// everything the runner's report shows is finite: every body's origin, orientation and
// velocities, and at the end the energies and momenta. To keep each input cheap enough to fuzz (the time per step grows with bodies, substeps
// and iterations, none of which is what is being searched for), scenes of more than kMaxBodies
// bodies are skipped and substeps and iterations are clamped (see scene_checks.cpp).
void checkStep(std::string_view text);

inline constexpr int kSteps = 256;
inline constexpr std::size_t kMaxBodies = 64;

}  // namespace fuzz
