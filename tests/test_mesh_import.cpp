// Geometry import (simcore_import): OBJ, ASCII and binary STL, glTF with an embedded buffer and
// GLB, each written by the test, give the expected triangle counts, bounds and fronts; scale and
// up axis are applied; missing, unsupported, empty, oversized, truncated and garbage files give a
// message naming the file; hull points of a part. Scenes that reference mesh files: relative
// paths resolved from the scene's folder, round trips that keep the reference (also after saving
// to another folder), missing, hostile and limit-breaking files refused with the path as written
// and as resolved, and a loader without the importer saying so. assimp is mapped into the process
// only by the first import, not by loading a scene without mesh files.

#include "simcore/io/mesh_import.h"
#include "simcore/io/scene_io.h"
#include "simcore/shapes/convex_hull.h"

#include <QtTest>

#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace simcore;

namespace {

// A box of half extents (1, 2, 3) as six quads, outward counter-clockwise.
const char* kBoxObj = R"(# box
v -1 -2 -3
v  1 -2 -3
v  1  2 -3
v -1  2 -3
v -1 -2  3
v  1 -2  3
v  1  2  3
v -1  2  3
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 4 8 7 3
f 1 5 8 4
f 2 3 7 6
)";

// Two facets: the unit square in the xz plane, facing +y.
const char* kSquareStl = R"(solid square
facet normal 0 1 0
 outer loop
  vertex 0 0 0
  vertex 0 0 1
  vertex 1 0 1
 endloop
endfacet
facet normal 0 1 0
 outer loop
  vertex 0 0 0
  vertex 1 0 1
  vertex 1 0 0
 endloop
endfacet
endsolid square
)";

// A tetrahedron as binary STL: 80-byte header, count, 50 bytes per facet.
std::string tetrahedronBinaryStl(std::uint32_t declaredFacets = 4) {
    const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    std::string out(80, ' ');
    out.append(reinterpret_cast<const char*>(&declaredFacets), 4);
    for (const auto& f : faces) {
        const float normal[3] = {0, 0, 0};
        out.append(reinterpret_cast<const char*>(normal), 12);
        for (int k : f) out.append(reinterpret_cast<const char*>(v[k]), 12);
        out.append(2, '\0');
    }
    return out;
}

// A glTF buffer: a quad in the xz plane facing +y (positions, then uint16 indices).
QByteArray quadBuffer() {
    const float positions[4][3] = {{0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2}};
    const std::uint16_t indices[6] = {0, 2, 1, 0, 3, 2};
    QByteArray bytes(reinterpret_cast<const char*>(positions), sizeof positions);
    bytes.append(reinterpret_cast<const char*>(indices), sizeof indices);
    return bytes;
}

QByteArray quadGltfJson(const QString& bufferUri, int bufferLength) {
    QString json = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0, "translation": [0, 1, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "buffers": [{%1"byteLength": %2}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [2, 0, 2]},
                {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
    return json.arg(bufferUri.isEmpty() ? QString() : QString("\"uri\": \"%1\", ").arg(bufferUri)).arg(bufferLength).toUtf8();
}

QByteArray quadGlb() {
    QByteArray json = quadGltfJson({}, 60);
    while (json.size() % 4) json.append(' ');
    QByteArray bin = quadBuffer();
    while (bin.size() % 4) bin.append('\0');
    auto u32 = [](std::uint32_t v) { return QByteArray(reinterpret_cast<const char*>(&v), 4); };
    QByteArray out = "glTF" + u32(2) + u32(12 + 8 + json.size() + 8 + bin.size());
    out += u32(json.size()) + "JSON" + json;
    out += u32(bin.size()) + QByteArray("BIN\0", 4) + bin;
    return out;
}

Aabb boundsOf(const ImportedMesh& mesh) {
    Aabb box;
    for (const auto& t : mesh.triangles)
        for (std::uint32_t v : t) box.grow(mesh.vertices[v]);
    return box;
}

// Whether a library whose file name contains `name` is mapped into this process.
bool isMapped(const char* name) {
    QFile maps("/proc/self/maps");
    if (!maps.open(QIODevice::ReadOnly)) qFatal("cannot read /proc/self/maps");
    return maps.readAll().contains(name);
}

bool near(const Vec3& a, const Vec3& b) { return glm::length(a - b) < 1e-5f; }

Vec3 normalOf(const ImportedMesh& mesh, std::size_t t) {
    const auto& i = mesh.triangles[t];
    return glm::normalize(glm::cross(mesh.vertices[i[1]] - mesh.vertices[i[0]], mesh.vertices[i[2]] - mesh.vertices[i[0]]));
}

}  // namespace

class TestMeshImport : public QObject {
    Q_OBJECT
private slots:
    void init() { QVERIFY(dir.isValid()); }
    void assimpIsMappedByTheFirstImport();  // first: no other test has imported yet
    void objBox();
    void objScaleAndUpAxis();
    void mirroringScaleKeepsFrontsOutside();
    void stlAscii();
    void stlBinary();
    void gltfEmbedded();
    void glb();
    void degenerateTrianglesAreDropped();
    void badFilesNameTheFile_data();
    void badFilesNameTheFile();
    void limitsAreApplied();
    void fromMemoryChecksFormat();
    void hullPointsOfAPart();
    void triangleMeshFromFile();
    void shippedFiles();
    void sceneMeshFileResolvesFromTheSceneFolder();
    void sceneMeshFileRoundTripKeepsTheReference();
    void sceneMeshFileSavedElsewhereIsRewritten();
    void sceneMeshFileErrorsNameThePath_data();
    void sceneMeshFileErrorsNameThePath();
    void sceneMeshFileLimitsApplyToTheLoader();

private:
    // A scene of one static body whose mesh is `shape` (a JSON object), written to `name`.
    QString writeScene(const QString& name, const QByteArray& shape) {
        return write(name, R"({"format": "interplay.scene", "version": 1, "bodies": [
            {"name": "terrain", "motion": "static", "shape": )" + shape + "}]}");
    }
    static SceneReadOptions withImporter() {
        SceneReadOptions options;
        options.loadMeshFile = importMeshFile;
        return options;
    }
    QString write(const QString& name, const QByteArray& bytes) {
        const QString path = dir.filePath(name);
        QFile file(path);
        if (!file.open(QIODevice::WriteOnly)) qFatal("cannot write %s", qPrintable(path));
        file.write(bytes);
        return path;
    }
    QTemporaryDir dir;
};

void TestMeshImport::assimpIsMappedByTheFirstImport() {
    QVERIFY(!isMapped("libassimp"));
    // A scene without mesh files, loaded with the importer at hand, does not open it.
    const QString scene = write("plain.json", R"({"format": "interplay.scene", "version": 1, "bodies": [
        {"name": "ball", "shape": {"type": "sphere", "radius": 0.5}}]})");
    QVERIFY(loadSceneFile(scene.toStdString(), withImporter()).ok());
    QVERIFY(!isMapped("libassimp"));
    // Refusals made before parsing (a missing file, an unsupported format) do not open it either.
    QVERIFY(!importMesh(dir.filePath("absent.obj").toStdString()).ok());
    QVERIFY(!importMeshFromMemory("x", 1, "ply", "bytes").ok());
    QVERIFY(!isMapped("libassimp"));
    const ImportedMesh box = importMesh(write("box.obj", kBoxObj).toStdString());
    QVERIFY2(box.ok(), box.error.c_str());
    QVERIFY(isMapped("libsimcore_assimp"));
    QVERIFY(isMapped("libassimp"));
}

void TestMeshImport::objBox() {
    const auto mesh = importMesh(write("box.obj", kBoxObj).toStdString());
    QVERIFY2(mesh.ok(), mesh.error.c_str());
    QCOMPARE(mesh.triangles.size(), std::size_t(12));
    QCOMPARE(mesh.vertices.size(), std::size_t(8));  // identical vertices joined
    const Aabb box = boundsOf(mesh);
    QVERIFY(near(box.min, {-1, -2, -3}) && near(box.max, {1, 2, 3}));
    // Every front faces out of the box.
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& i = mesh.triangles[t];
        const Vec3 centre = (mesh.vertices[i[0]] + mesh.vertices[i[1]] + mesh.vertices[i[2]]) / 3.0f;
        QVERIFY(glm::dot(normalOf(mesh, t), centre) > 0.0f);
    }
}

void TestMeshImport::objScaleAndUpAxis() {
    const std::string path = write("box.obj", kBoxObj).toStdString();
    MeshImportOptions zUp;
    zUp.upAxis = UpAxis::Z;
    zUp.scale = {2.0f, 1.0f, 0.5f};
    // File z (3) becomes y, file y (2) becomes -z; then x doubles and z halves.
    const Aabb turned = boundsOf(importMesh(path, zUp));
    QVERIFY(near(turned.min, {-2, -3, -1}) && near(turned.max, {2, 3, 1}));
    MeshImportOptions xUp;
    xUp.upAxis = UpAxis::X;
    const Aabb xTurned = boundsOf(importMesh(path, xUp));
    QVERIFY(near(xTurned.min, {-2, -1, -3}) && near(xTurned.max, {2, 1, 3}));
}

void TestMeshImport::mirroringScaleKeepsFrontsOutside() {
    MeshImportOptions mirror;
    mirror.scale = {-1.0f, 1.0f, 1.0f};
    const auto mesh = importMesh(write("box.obj", kBoxObj).toStdString(), mirror);
    QVERIFY(mesh.ok());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& i = mesh.triangles[t];
        const Vec3 centre = (mesh.vertices[i[0]] + mesh.vertices[i[1]] + mesh.vertices[i[2]]) / 3.0f;
        QVERIFY(glm::dot(normalOf(mesh, t), centre) > 0.0f);
    }
}

void TestMeshImport::stlAscii() {
    const auto mesh = importMesh(write("square.STL", kSquareStl).toStdString());
    QVERIFY2(mesh.ok(), mesh.error.c_str());
    QCOMPARE(mesh.triangles.size(), std::size_t(2));
    const Aabb box = boundsOf(mesh);
    QVERIFY(near(box.min, {0, 0, 0}) && near(box.max, {1, 0, 1}));
    for (std::size_t t = 0; t < 2; ++t) QVERIFY(near(normalOf(mesh, t), {0, 1, 0}));
    // The welded mesh has its diagonal as an inactive seam.
    const auto built = TriangleMesh::build(mesh.vertices, mesh.triangles);
    QVERIFY(built.mesh);
    int inactive = 0;
    for (std::uint32_t t = 0; t < 2; ++t)
        for (int e = 0; e < 3; ++e) inactive += !isEdgeActive(built.mesh->triangle(t).flags, e);
    QCOMPARE(inactive, 2);
}

void TestMeshImport::stlBinary() {
    const std::string bytes = tetrahedronBinaryStl();
    const auto mesh = importMesh(write("tetra.stl", QByteArray(bytes.data(), int(bytes.size()))).toStdString());
    QVERIFY2(mesh.ok(), mesh.error.c_str());
    QCOMPARE(mesh.triangles.size(), std::size_t(4));
    const Aabb box = boundsOf(mesh);
    QVERIFY(near(box.min, {0, 0, 0}) && near(box.max, {1, 1, 1}));
}

void TestMeshImport::gltfEmbedded() {
    const QString uri = "data:application/octet-stream;base64," + QString::fromLatin1(quadBuffer().toBase64());
    const auto mesh = importMesh(write("quad.gltf", quadGltfJson(uri, 60)).toStdString());
    QVERIFY2(mesh.ok(), mesh.error.c_str());
    QCOMPARE(mesh.triangles.size(), std::size_t(2));
    const Aabb box = boundsOf(mesh);
    QVERIFY(near(box.min, {0, 1, 0}) && near(box.max, {2, 1, 2}));  // the node's translation applied
    for (std::size_t t = 0; t < 2; ++t) QVERIFY(near(normalOf(mesh, t), {0, 1, 0}));
}

void TestMeshImport::glb() {
    const auto mesh = importMesh(write("quad.glb", quadGlb()).toStdString());
    QVERIFY2(mesh.ok(), mesh.error.c_str());
    QCOMPARE(mesh.triangles.size(), std::size_t(2));
    const Aabb box = boundsOf(mesh);
    QVERIFY(near(box.min, {0, 1, 0}) && near(box.max, {2, 1, 2}));
}

void TestMeshImport::degenerateTrianglesAreDropped() {
    const auto mesh = importMesh(write("sliver.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\n").toStdString());
    QVERIFY2(mesh.ok(), mesh.error.c_str());
    QCOMPARE(mesh.triangles.size(), std::size_t(1));
    QCOMPARE(mesh.droppedTriangles, std::size_t(1));
    const auto none = importMesh(write("line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n").toStdString());
    QVERIFY(!none.ok());
    QVERIFY2(QString::fromStdString(none.error).contains("line.obj: has only degenerate triangles"), none.error.c_str());
}

void TestMeshImport::badFilesNameTheFile_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<QByteArray>("bytes");  // empty name: the file is not written
    QTest::addColumn<QString>("expected");
    const std::string stl = tetrahedronBinaryStl();
    QTest::newRow("missing") << "missing.obj" << QByteArray() << "missing.obj: no such file";
    QTest::newRow("unsupported") << "part.fbx" << QByteArray("x") << "part.fbx: unsupported format \".fbx\"";
    QTest::newRow("empty") << "empty.stl" << QByteArray("") << "empty.stl: is empty";
    QTest::newRow("binary stl truncated") << "cut.stl" << QByteArray(stl.data(), 84 + 60) << "cut.stl: cannot be read as stl";
    QTest::newRow("binary stl lying count") << "lie.stl" << QByteArray(tetrahedronBinaryStl(1000000).data(), int(stl.size()))
                                            << "lie.stl: cannot be read as stl";
    static constexpr char kGlbGarbage[] = "glTF\x02\0\0\0\xff\xff\xff\x7f garbage";  // a header claiming 2 GiB
    QTest::newRow("glb garbage") << "junk.glb" << QByteArray(kGlbGarbage, sizeof kGlbGarbage - 1)
                                 << "junk.glb: is a binary glTF whose header says 2147483647 bytes, but it has 20";
    QTest::newRow("glb truncated") << "cut.glb" << quadGlb().left(100) << "cut.glb: is a binary glTF whose header says 656 bytes, but it has 100";
    QTest::newRow("gltf not json") << "junk.gltf" << QByteArray("{ this is not json") << "junk.gltf: cannot be read as gltf";
    QTest::newRow("gltf missing buffer") << "nobuf.gltf" << quadGltfJson("absent.bin", 60) << "nobuf.gltf: cannot be read as gltf";
    // A PLY file in disguise: assimp would hand it to its PLY reader; only the named formats' readers run.
    QTest::newRow("ply named glb") << "disguised.glb"
                                   << QByteArray("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                                 "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                                 "end_header\n0 0 0\n1 0 0\n0 0 1\n3 0 1 2\n")
                                   << "disguised.glb: cannot be read as glb";
    QTest::newRow("obj garbage") << "junk.obj" << QByteArray("\x01\x02\x03 nothing here\n", 18) << "junk.obj: cannot be read as obj";
    QTest::newRow("obj bad index") << "index.obj" << QByteArray("v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 9\n") << "index.obj:";
}

void TestMeshImport::badFilesNameTheFile() {
    QFETCH(QString, name);
    QFETCH(QByteArray, bytes);
    QFETCH(QString, expected);
    const QString path = name == "missing.obj" ? dir.filePath(name) : write(name, bytes);
    const auto mesh = importMesh(path.toStdString());
    QVERIFY(!mesh.ok());
    qInfo("%s", mesh.error.c_str());
    QVERIFY2(QString::fromStdString(mesh.error).contains(expected), mesh.error.c_str());
    QVERIFY2(QString::fromStdString(mesh.error).startsWith(dir.filePath(name)), mesh.error.c_str());
}

void TestMeshImport::limitsAreApplied() {
    const std::string path = write("box.obj", kBoxObj).toStdString();
    MeshImportOptions few;
    few.maxTriangles = 5;
    const auto tooMany = importMesh(path, few);
    QVERIFY2(QString::fromStdString(tooMany.error).contains("has 12 triangles; at most 5"), tooMany.error.c_str());
    MeshImportOptions small;
    small.maxFileBytes = 16;
    const auto tooBig = importMesh(path, small);
    QVERIFY2(QString::fromStdString(tooBig.error).contains("bytes; at most 16 are read"), tooBig.error.c_str());
    MeshImportOptions flat;
    flat.scale = {1.0f, 0.0f, 1.0f};
    QVERIFY2(QString::fromStdString(importMesh(path, flat).error).contains("scale must be finite and non-zero"),
             importMesh(path, flat).error.c_str());
    MeshImportOptions huge;
    huge.scale = Vec3(1e6f);
    QVERIFY2(QString::fromStdString(importMesh(path, huge).error).contains("beyond 1000000 m once scaled"),
             importMesh(path, huge).error.c_str());
}

void TestMeshImport::fromMemoryChecksFormat() {
    const auto mesh = importMeshFromMemory(kBoxObj, std::strlen(kBoxObj), "OBJ", "inline box");
    QVERIFY2(mesh.ok(), mesh.error.c_str());
    QCOMPARE(mesh.triangles.size(), std::size_t(12));
    const QByteArray glbBytes = quadGlb();
    QCOMPARE(importMeshFromMemory(glbBytes.data(), std::size_t(glbBytes.size()), "glb", "inline").triangles.size(), std::size_t(2));
    const auto wrong = importMeshFromMemory(kBoxObj, std::strlen(kBoxObj), "3ds", "inline box");
    QVERIFY2(wrong.error == "inline box: unsupported format \"3ds\" (use obj, stl, gltf or glb)", wrong.error.c_str());
}

void TestMeshImport::hullPointsOfAPart() {
    const auto mesh = importMesh(write("box.obj", kBoxObj).toStdString());
    const HullPoints points = hullPoints(mesh);
    QVERIFY2(points.error.empty(), points.error.c_str());
    QCOMPARE(points.points.size(), std::size_t(8));
    const auto hull = ConvexHull::build(points.points);
    QVERIFY(hull.hull);
    QCOMPARE(hull.hull->faces().size(), std::size_t(6));
    const auto flat = importMesh(write("square.stl", kSquareStl).toStdString());
    QVERIFY(!hullPoints(flat).error.empty());
}

void TestMeshImport::triangleMeshFromFile() {
    const auto built = importTriangleMesh(write("box.obj", kBoxObj).toStdString());
    QVERIFY2(built.mesh, built.error.c_str());
    QCOMPARE(built.mesh->triangleCount(), std::size_t(12));
    // A closed box: every edge has a neighbour, and the 90-degree creases are active, the face
    // diagonals not.
    int active = 0;
    for (std::uint32_t t = 0; t < 12; ++t)
        for (int e = 0; e < 3; ++e) {
            QVERIFY(built.mesh->neighbour(t, e) != TriangleMesh::kNoNeighbour);
            active += isEdgeActive(built.mesh->triangle(t).flags, e);
        }
    QCOMPARE(active, 24);  // 12 box edges, seen from both sides
    const auto missing = importTriangleMesh(dir.filePath("nothere.stl").toStdString());
    QVERIFY(!missing.mesh && QString::fromStdString(missing.error).endsWith("nothere.stl: no such file"));
}

void TestMeshImport::shippedFiles() {
    // tests/data/meshes/: the fuzzer's seeds, valid and hostile.
    const QDir meshes(QStringLiteral(INTERPLAY_SOURCE_DIR "/tests/data/meshes"));
    const std::pair<const char*, std::size_t> valid[] = {
        {"box.obj", 12}, {"square.stl", 2}, {"tetrahedron_binary.stl", 4}, {"quad_embedded.gltf", 2}, {"quad.glb", 2}};
    for (const auto& [name, triangles] : valid) {
        const auto mesh = importMesh(meshes.filePath(name).toStdString());
        QVERIFY2(mesh.ok(), mesh.error.c_str());
        QCOMPARE(mesh.triangles.size(), triangles);
    }
    const QDir hostile(meshes.filePath("hostile"));
    const QStringList files = hostile.entryList(QDir::Files);
    QCOMPARE(files.size(), 7);
    for (const QString& name : files) {
        const auto mesh = importMesh(hostile.filePath(name).toStdString());
        QVERIFY2(!mesh.ok() && QString::fromStdString(mesh.error).startsWith(hostile.filePath(name) + ": "),
                 qPrintable(name + ": " + QString::fromStdString(mesh.error)));
    }
    // A GLB whose JSON chunk claims 4 GB is refused before assimp allocates it (the fuzzer's
    // out-of-memory), and the message says which length lies.
    const auto lying = importMesh(hostile.filePath("lying_chunk_length.glb").toStdString());
    QVERIFY2(QString::fromStdString(lying.error).endsWith("chunk at byte 12 says 4294966764 bytes, but 608 follow"),
             lying.error.c_str());
}

void TestMeshImport::sceneMeshFileResolvesFromTheSceneFolder() {
    QVERIFY(QDir(dir.path()).mkpath("scenes/parts"));
    write("scenes/parts/box.obj", kBoxObj);
    const QString scene = writeScene("scenes/a.json", R"({"type": "mesh", "file": "parts/box.obj", "scale": [2, 1, 1]})");
    const SceneLoadResult loaded = loadSceneFile(scene.toStdString(), withImporter());
    QVERIFY2(loaded.ok(), loaded.diagnostics.empty() ? "" : loaded.diagnostics.front().toString().c_str());
    const SceneBody& body = loaded.scene->bodies.front();
    QVERIFY(body.meshFile && body.body.shape.mesh);
    QCOMPARE(body.meshFile->file, std::string("parts/box.obj"));
    QCOMPARE(QString::fromStdString(body.meshFile->resolvedPath.string()),
             QDir::cleanPath(QDir(dir.path()).absoluteFilePath("scenes/parts/box.obj")));
    QCOMPARE(body.body.shape.mesh->triangleCount(), std::size_t(12));
    // The scale reached the importer: x doubled from the file's [-1, 1].
    QVERIFY(near(body.body.shape.mesh->bounds().max, {2, 2, 3}));

    // "../": the folder above the scene's; the working directory plays no part.
    write("box.obj", kBoxObj);
    const QString up = writeScene("scenes/b.json", R"({"type": "mesh", "file": "../box.obj"})");
    QVERIFY(loadSceneFile(up.toStdString(), withImporter()).ok());
}

void TestMeshImport::sceneMeshFileRoundTripKeepsTheReference() {
    write("box.obj", kBoxObj);
    const QString path = writeScene("a.json", R"({"type": "mesh", "file": "box.obj", "scale": [1, -2, 0.5], "upAxis": "z"})");
    const SceneLoadResult loaded = loadSceneFile(path.toStdString(), withImporter());
    QVERIFY(loaded.ok());
    const std::string text = serializeScene(*loaded.scene);
    QVERIFY2(text.find("\"vertices\"") == std::string::npos, text.c_str());  // a reference stays one
    QVERIFY(text.find("\"file\": \"box.obj\"") != std::string::npos);

    QVERIFY(!saveSceneFile(*loaded.scene, dir.filePath("b.json").toStdString()));
    const SceneLoadResult again = loadSceneFile(dir.filePath("b.json").toStdString(), withImporter());
    QVERIFY(again.ok());
    const SceneBody& a = loaded.scene->bodies.front();
    const SceneBody& b = again.scene->bodies.front();
    QVERIFY(b.meshFile && *b.meshFile == *a.meshFile);
    QVERIFY(b.body.shape.mesh->vertices() == a.body.shape.mesh->vertices());
    QVERIFY(b.body.shape.mesh->triangleIndices() == a.body.shape.mesh->triangleIndices());
    QCOMPARE(serializeScene(*again.scene), text);
    // The editor checks every edit with checkScene: it must pass without reading the file again.
    QVERIFY(QFile::remove(dir.filePath("box.obj")));
    QVERIFY(checkScene(*again.scene).empty());
}

void TestMeshImport::sceneMeshFileSavedElsewhereIsRewritten() {
    QVERIFY(QDir(dir.path()).mkpath("scenes/meshes"));
    QVERIFY(QDir(dir.path()).mkpath("elsewhere/deeper"));
    write("scenes/meshes/box.obj", kBoxObj);
    const QString path = writeScene("scenes/a.json", R"({"type": "mesh", "file": "meshes/box.obj"})");
    const SceneLoadResult loaded = loadSceneFile(path.toStdString(), withImporter());
    QVERIFY(loaded.ok());
    // Save As into another folder: the path is rewritten relative to it, and still names the file.
    const QString moved = dir.filePath("elsewhere/deeper/b.json");
    QVERIFY(!saveSceneFile(*loaded.scene, moved.toStdString()));
    QFile file(moved);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.readAll().contains(R"("file": "../../scenes/meshes/box.obj")"));
    const SceneLoadResult again = loadSceneFile(moved.toStdString(), withImporter());
    QVERIFY(again.ok());
    QCOMPARE(again.scene->bodies.front().meshFile->resolvedPath, loaded.scene->bodies.front().meshFile->resolvedPath);
    // An absolute reference stays absolute.
    MeshFileReference absolute = *loaded.scene->bodies.front().meshFile;
    absolute.file = absolute.resolvedPath.string();
    QCOMPARE(meshFileText(absolute, dir.filePath("elsewhere").toStdString()), absolute.file);
}

void TestMeshImport::sceneMeshFileErrorsNameThePath_data() {
    QTest::addColumn<QByteArray>("shape");
    QTest::addColumn<QString>("expected");  // in the error, besides the file as written and resolved
    QTest::newRow("missing") << QByteArray(R"({"type": "mesh", "file": "nowhere/terrain.obj"})") << "no such file";
    QTest::newRow("hostile") << QByteArray(R"({"type": "mesh", "file": ")" INTERPLAY_SOURCE_DIR
                                           R"(/tests/data/meshes/hostile/truncated.glb"})")
                             << "truncated.glb: is a binary glTF whose header says 628 bytes, but it has 100";
    QTest::newRow("not a mesh") << QByteArray(R"({"type": "mesh", "file": "a.json"})") << "unsupported format";
    QTest::newRow("both") << QByteArray(R"({"type": "mesh", "file": "box.obj", "triangles": []})") << "not both";
    QTest::newRow("zero scale") << QByteArray(R"({"type": "mesh", "file": "box.obj", "scale": [1, 0, 1]})")
                                << "every scale factor";
    QTest::newRow("up axis") << QByteArray(R"({"type": "mesh", "file": "box.obj", "upAxis": "w"})") << "expected y, z or x";
}

void TestMeshImport::sceneMeshFileErrorsNameThePath() {
    QFETCH(QByteArray, shape);
    QFETCH(QString, expected);
    write("box.obj", kBoxObj);
    const QString path = writeScene("a.json", shape);
    const SceneLoadResult loaded = loadSceneFile(path.toStdString(), withImporter());
    QVERIFY(!loaded.ok());
    const std::string message = loaded.diagnostics.front().toString();
    QVERIFY2(QString::fromStdString(message).contains(expected), message.c_str());
    QVERIFY2(message.find("/bodies/0/shape/") != std::string::npos, message.c_str());
    if (QString(QTest::currentDataTag()) == "missing") {
        QVERIFY2(message.find("\"nowhere/terrain.obj\"") != std::string::npos, message.c_str());
        QVERIFY2(message.find(dir.filePath("nowhere/terrain.obj").toStdString()) != std::string::npos, message.c_str());
    }
}

void TestMeshImport::sceneMeshFileLimitsApplyToTheLoader() {
    const QString path = writeScene("a.json", R"({"type": "mesh", "file": "any.obj"})");
    // Without the importer (the engine alone, the fuzzers) the error says so and names the file.
    const SceneLoadResult bare = loadSceneFile(path.toStdString());
    QVERIFY(!bare.ok());
    QVERIFY2(bare.diagnostics.front().message.find("without the mesh importer") != std::string::npos &&
                 bare.diagnostics.front().message.find("\"any.obj\"") != std::string::npos,
             bare.diagnostics.front().toString().c_str());
    // Whatever a loader gives goes through the inline mesh's checks.
    SceneReadOptions options;
    MeshFileData given;
    options.loadMeshFile = [&](const MeshFileRequest&) { return given; };
    given.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};  // a zero-area triangle
    given.triangles = {{0, 1, 2}};
    SceneLoadResult loaded = loadSceneFile(path.toStdString(), options);
    QVERIFY(!loaded.ok());
    QVERIFY2(loaded.diagnostics.front().message.find("cannot build the mesh of \"any.obj\"") != std::string::npos,
             loaded.diagnostics.front().toString().c_str());
    given.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 0, 2e6f}};  // beyond the coordinate range
    QVERIFY(!loadSceneFile(path.toStdString(), options).ok());
    given.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    given.triangles = {{0, 1, 3}};  // an index out of range
    QVERIFY(!loadSceneFile(path.toStdString(), options).ok());
    given.triangles = {{0, 2, 1}};
    QVERIFY(loadSceneFile(path.toStdString(), options).ok());
}

QTEST_APPLESS_MAIN(TestMeshImport)
#include "test_mesh_import.moc"
