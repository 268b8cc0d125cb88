#include "simcore/collision/contact_manifold.h"

#include <algorithm>
#include <cmath>

namespace simcore {

// One deep point, the farthest from it, the one making the largest triangle, then the one adding
// the most area to it; areas are signed, measured in the contact plane.
//
// The choice must not flicker from step to step, or the warm start is lost and the support polygon
// jumps: a cap of 8 rim points rocking on another chose a different 4 of them whenever the deepest
// changed by a micrometre, and a stack of 10 cylinders never came to rest. So the deep point changes
// only for one deeper by a margin (kChoiceMargin), and where the geometry ties (a regular polygon's
// vertices) the earliest candidate wins, whose order follows the features. The others are the best
// by their measure, not merely close to it: taking the first within 5 % made a quad of a 32-sided
// face's vertices whose centre sat 5 cm off the face's (gaps of 6, 8, 8 and 10 sides), and a stack
// of 30 such wheels toppled, each joint tilted towards its quad's centre.
void reduceToManifold(const ContactCandidate* candidates, int count, const Vec3& normal, ContactManifold& out) {
    out.normal = normal;
    out.pointCount = 0;
    const auto keep = [&](int i) {
        const ContactCandidate& c = candidates[i];
        out.points[out.pointCount++] = {c.pointA, c.pointB, c.separation, c.featureId};
    };
    if (count <= kMaxManifoldPoints) {
        for (int i = 0; i < count; ++i) keep(i);
        return;
    }
    constexpr float kChoiceMargin = 0.2f * kLinearSlop;  // m
    constexpr float kTieRatio = 1.001f;  // scores this close to the best tie: rounding must not choose
    const auto at = [&](int i) { return candidates[i].pointA; };
    struct Choice {
        int index;    // the earliest candidate tying with the best score
        float score;  // the best score
    };
    const auto best = [&](auto&& score) {
        Choice choice{0, 0.0f};
        for (int i = 0; i < count; ++i) choice.score = std::max(choice.score, score(i));
        while (kTieRatio * score(choice.index) < choice.score) ++choice.index;
        return choice;
    };

    int first = 0;
    for (int i = 1; i < count; ++i)
        if (candidates[i].separation < candidates[first].separation - kChoiceMargin) first = i;
    const int second = best([&](int i) { return lengthSquared(at(i) - at(first)); }).index;
    keep(first);
    if (lengthSquared(at(second) - at(first)) <= 1e-12f) return;  // all candidates coincide
    keep(second);

    const auto triangleArea = [&](int i) {  // signed, twice the area
        return glm::dot(glm::cross(at(second) - at(first), at(i) - at(first)), normal);
    };
    const int third = best([&](int i) { return std::abs(triangleArea(i)); }).index;
    if (std::abs(triangleArea(third)) <= 1e-9f) return;  // collinear
    keep(third);

    // The fourth point lies outside one triangle edge; the area it adds is how negative its signed
    // area against that edge is (with the triangle oriented counter-clockwise about the normal).
    const float orientation = triangleArea(third) > 0.0f ? 1.0f : -1.0f;
    const int corners[3] = {first, second, third};
    const Choice fourth = best([&](int i) {
        float added = 0.0f;
        for (int e = 0; e < 3; ++e) {
            const Vec3 p = at(corners[e]);
            const Vec3 q = at(corners[(e + 1) % 3]);
            added = std::max(added, -orientation * glm::dot(glm::cross(q - p, at(i) - p), normal));
        }
        return added;
    });
    if (fourth.score > 1e-9f) keep(fourth.index);
}

}  // namespace simcore
