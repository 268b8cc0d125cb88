#pragma once
// Runs the headless runner (INTERPLAY_RUN_PATH) on a scene and reads the bodies of its report back
// as BodyStates, so a runner's final state hashes like a World's (state_hash.h).

#include "run_program.h"
#include "state_hash.h"

#include <QString>
#include <QStringList>

#include <nlohmann/json.hpp>

#include <optional>

namespace test_support {

// The bodies of a report, in its order; each float as printed (the report prints exact doubles).
inline std::vector<BodyState> bodyStates(const nlohmann::json& report) {
    const auto vec = [](const nlohmann::json& a) {
        return simcore::Vec3(a.at(0).get<float>(), a.at(1).get<float>(), a.at(2).get<float>());
    };
    std::vector<BodyState> states;
    for (const nlohmann::json& body : report.at("bodies")) {
        const nlohmann::json& q = body.at("orientation");  // [w, x, y, z]
        states.push_back({vec(body.at("position")),
                          simcore::Quat(q.at(0).get<float>(), q.at(1).get<float>(), q.at(2).get<float>(),
                                        q.at(3).get<float>()),
                          vec(body.at("linearVelocity")), vec(body.at("angularVelocity")),
                          body.at("awake").get<bool>()});
    }
    return states;
}

// `interplay-run SCENE --steps N`: the final body states, or nothing with the reason in *error.
inline std::optional<std::vector<BodyState>> runnerBodyStates(const QString& scenePath, int steps, QString* error) {
    const ProgramRun run = runProgram(QStringLiteral(INTERPLAY_RUN_PATH), {scenePath, QStringLiteral("--steps"), QString::number(steps)},
                                      120'000);
    if (!run.finished || run.exitCode != 0) {
        *error = QStringLiteral("interplay-run %1 failed (exit %2): %3")
                     .arg(scenePath)
                     .arg(run.exitCode)
                     .arg(QString::fromLocal8Bit(run.err));
        return std::nullopt;
    }
    return bodyStates(nlohmann::json::parse(run.out.toStdString()));
}

}  // namespace test_support
