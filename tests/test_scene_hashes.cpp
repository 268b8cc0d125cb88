// Determinism against a stored fingerprint, as Box2D's determinism test: every scene file under
// scenes/ is built and stepped, and the state hash (support/state_hash.h) after a fixed number of
// steps is compared with tests/data/determinism_hashes.json. Any change to the engine that moves a
// single bit of any body in any scene fails here, naming the scene; a change meant to alter results
// regenerates the file deliberately (docs/testing.md, "Determinism hashes"):
//
//   INTERPLAY_WRITE_SCENE_HASHES=1 ctest --test-dir build -R test_scene_hashes
//
// The hashes are stored per SIMD kernel set (the contact solver's AVX2 kernels fuse multiply-adds,
// the SSE2 ones do not, so their results differ in the last bits); a build whose kernels have no
// stored hashes skips, saying so.

#include "support/sanitizers.h"
#include "support/state_hash.h"

#include "simcore/io/scene_io.h"
#include "simcore/math/simd.h"

#include <QSaveFile>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace simcore;
using test_support::stateHash;

namespace {

namespace fs = std::filesystem;

const fs::path kSourceDir = INTERPLAY_SOURCE_DIR;
const fs::path kHashFile = kSourceDir / "tests/data/determinism_hashes.json";

// Two checkpoints per scene. 60 steps (1 s at 60 Hz) has the first landings and contacts;
// 240 steps (4 s) adds stacks settling, sleep (0.5 s at rest) and joints swinging through their
// limits. The ASan build runs several times slower, so it checks the first checkpoint only: the
// same code paths, and the comparison of both builds' bits that matters.
constexpr int kShortSteps = 60;
constexpr int kLongSteps = 240;

#if defined(SIMCORE_SIMD_AVX2)
constexpr const char* kKernels = "avx2-fma";
#elif defined(SIMCORE_SIMD_SSE2)
constexpr const char* kKernels = "sse2";
#else
constexpr const char* kKernels = "scalar";
#endif

bool writing() { return qEnvironmentVariableIsSet("INTERPLAY_WRITE_SCENE_HASHES"); }

// Every scene file, as a path relative to the source tree with '/' separators, sorted.
std::vector<std::string> sceneFiles() {
    std::vector<std::string> scenes;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kSourceDir / "scenes"))
        if (entry.is_regular_file() && entry.path().extension() == ".json")
            scenes.push_back(fs::relative(entry.path(), kSourceDir).generic_string());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

std::string hex(std::uint64_t hash) {
    char text[19];
    std::snprintf(text, sizeof text, "0x%016" PRIx64, hash);
    return text;
}

nlohmann::json readHashFile() {
    std::ifstream in(kHashFile);
    if (!in) return nlohmann::json::object();
    return nlohmann::json::parse(in);  // a broken file throws, and the test fails naming the parse error
}

}  // namespace

class TestSceneHashes : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void everySceneHasAStoredHash();
    void sceneMatchesItsStoredHash_data();
    void sceneMatchesItsStoredHash();
    void cleanupTestCase();

private:
    nlohmann::json stored_;      // this build's kernels' table: scene -> steps -> hash
    nlohmann::json computed_ = nlohmann::json::object();
};

void TestSceneHashes::initTestCase() {
    const nlohmann::json file = readHashFile();
    if (file.contains(kKernels)) stored_ = file.at(kKernels);
    if (!writing() && stored_.is_null())
        QSKIP(qPrintable(QString("%1 holds no hashes for this build's %2 kernels; generate them with "
                                 "INTERPLAY_WRITE_SCENE_HASHES=1 (docs/testing.md)")
                             .arg(QString::fromStdString(kHashFile.string()), kKernels)));
}

// A scene added without a hash, or a hash left for a scene that is gone, is a mistake either way.
void TestSceneHashes::everySceneHasAStoredHash() {
    if (writing()) QSKIP("writing the hashes");
    const std::vector<std::string> scenes = sceneFiles();
    QVERIFY2(!scenes.empty(), "no scene files found under scenes/");
    for (const std::string& scene : scenes)
        QVERIFY2(stored_.contains(scene), qPrintable(QString::fromStdString(
                     "no stored hash for " + scene + "; regenerate with INTERPLAY_WRITE_SCENE_HASHES=1")));
    for (const auto& [scene, hashes] : stored_.items())
        QVERIFY2(std::find(scenes.begin(), scenes.end(), scene) != scenes.end(),
                 qPrintable(QString::fromStdString("a hash is stored for " + scene + ", which no longer exists")));
}

void TestSceneHashes::sceneMatchesItsStoredHash_data() {
    QTest::addColumn<QString>("scene");
    for (const std::string& scene : sceneFiles()) QTest::newRow(scene.c_str()) << QString::fromStdString(scene);
}

void TestSceneHashes::sceneMatchesItsStoredHash() {
    QFETCH(QString, scene);
    const std::string path = scene.toStdString();
    const SceneLoadResult loaded = loadSceneFile(kSourceDir / path);
    QVERIFY2(loaded.ok(), qPrintable(scene + " does not load: " +
                                     QString::fromStdString(loaded.diagnostics.empty() ? "" : loaded.diagnostics.front().message)));
    BuiltWorld built = buildWorld(*loaded.scene);
    const std::uint64_t atStart = stateHash(built.world);

    const int lastStep = writing() || !test_support::kSanitized ? kLongSteps : kShortSteps;
    for (int step = 1; step <= lastStep; ++step) {
        built.world.step();
        if (step != kShortSteps && step != kLongSteps) continue;
        const std::string steps = std::to_string(step);
        const std::string got = hex(stateHash(built.world));
        if (writing()) {
            computed_[path][steps] = got;
            continue;
        }
        const std::string expected = stored_.contains(path) && stored_[path].contains(steps)
                                         ? stored_[path][steps].get<std::string>() : "(none)";
        QVERIFY2(got == expected, qPrintable(QString::fromStdString(path + " after " + steps + " steps (" + kKernels +
                                                                    " kernels): expected " + expected + ", got " + got)));
    }
    // A scene whose state never changes would pass whatever the engine did; every scene moves.
    QVERIFY2(stateHash(built.world) != atStart, qPrintable(scene + " did not move: its hash proves nothing"));
}

// In writing mode, this build's table is replaced and the other kernels' tables are kept.
void TestSceneHashes::cleanupTestCase() {
    if (!writing()) return;
    nlohmann::json file = readHashFile();
    file[kKernels] = computed_;
    QSaveFile out(QString::fromStdString(kHashFile.string()));
    QVERIFY2(out.open(QIODevice::WriteOnly), qPrintable(out.errorString()));
    out.write(QByteArray::fromStdString(file.dump(2) + "\n"));
    QVERIFY2(out.commit(), qPrintable(out.errorString()));
    qInfo("wrote %zu scenes' hashes for the %s kernels to %s", computed_.size(), kKernels, kHashFile.string().c_str());
}

QTEST_GUILESS_MAIN(TestSceneHashes)
#include "test_scene_hashes.moc"
