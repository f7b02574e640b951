// The parallel OBJ reader: chunking must not change what is read, forward and relative references, line ends,
// malformed statements, and the number syntax.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <map>

#include "scene/loaders/obj/obj_geometry_reader.h"
#include "scene/loaders/obj/obj_loader.h"
#include "scene/loaders/obj/obj_numbers.h"
#include "scene/scene_test_files.h"

namespace candela {
namespace {

// Materials by name, numbered in order of first use; "missing" is in no library. Records every question.
class FakeLibraries : public ObjMaterialResolver {
 public:
  void loadLibraries(size_t line, std::string_view names) override {
    log.push_back("mtllib@" + std::to_string(line) + ":" + std::string(names));
  }
  uint32_t find(size_t line, std::string_view name) override {
    log.push_back("usemtl@" + std::to_string(line) + ":" + std::string(name));
    if (name == "missing") return kObjNoMaterial;
    return ids.try_emplace(std::string(name), uint32_t(ids.size())).first->second;
  }
  std::map<std::string, uint32_t> ids;
  std::vector<std::string> log;
};

struct ReadResult {
  ObjGeometry geometry;
  std::vector<std::string> warnings, calls;
};

ReadResult read(const std::string& text, ObjReadOptions options) {
  FakeLibraries libraries;
  LoadWarnings warnings;
  auto source = objTextInMemory(text, options.windowBytes);
  ReadResult r{readObjGeometry("test.obj", *source, libraries, warnings, options), warnings.messages, libraries.log};
  return r;
}

template <class T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Something of every statement the reader handles, with CRLF and lone CR line ends, relative and forward
// references, polygons, material and smoothing changes, and problems that are only warnings.
std::string varietyText() {
  std::string t = "mtllib a.mtl b\\ c.mtl\r\n# comment\nv 0 0 0\nv 1 0 0\r\nv 1 1 0\rv 0 1 0\n";
  t += "vt 0 0\nvt 1 0\nvt 1 1 0.5\nvn 0 0 1\n  vw 0 1 0.5\n";
  t += "usemtl red\ns 1\nf 1/1/1 2/2/1 3/3/1\nf -4/-3/-1 -3/-2/-1 -2/-1/-1 -1/-1/-1\n";
  t += "o thing\ng group one\nusemtl missing\nf 1 2 3 4 # a quad\ns off\n";
  for (int i = 0; i < 40; ++i) {
    float a = float(i) * 0.1f;
    t += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " " + std::to_string(a) + "\n";
    if (i % 3 == 2) t += "f -3 -2 -1\n";
    if (i % 7 == 6) t += "usemtl " + std::string(i % 2 ? "green" : "red") + "\ns " + std::to_string(i) + "\n";
  }
  t += "f 1 2 3 50\nf 2 3\nl 1 2\nf 45 46 47 48 49\nf 1/9/1 2/1/1 3/1/1\nf 49 50 51\n";
  t += "v 5 5 5\nv 6 5 5\nv 5 6 5\nvn 1 0 0\n";  // positions 45..51 come after the faces that use them
  t += "v 6 6 5\nv 7 6 5\nv 7 7 7\nv 8 8 8";     // no line end at the end
  return t;
}

TEST(ObjGeometryReader, ChunkingDoesNotChangeTheResult) {
  const std::string text = varietyText();
  ReadResult whole = read(text, {});
  ASSERT_GT(whole.geometry.triangleCount(), 10u);
  for (size_t window : {size_t(1), size_t(9), size_t(64), size_t(1000)})
    for (size_t chunk : {size_t(1), size_t(2), size_t(5), size_t(17), size_t(100)}) {
      SCOPED_TRACE("window " + std::to_string(window) + ", chunk " + std::to_string(chunk));
      ReadResult r = read(text, {window, chunk});
      const ObjGeometry &a = whole.geometry, &b = r.geometry;
      EXPECT_TRUE(sameBytes(a.positions, b.positions));
      EXPECT_TRUE(sameBytes(a.normals, b.normals));
      EXPECT_TRUE(sameBytes(a.uvs, b.uvs));
      EXPECT_EQ(a.cornerPositions, b.cornerPositions);
      EXPECT_EQ(a.cornerUvs, b.cornerUvs);
      EXPECT_EQ(a.cornerNormals, b.cornerNormals);
      EXPECT_EQ(a.smoothingGroups, b.smoothingGroups);
      EXPECT_EQ(a.materials, b.materials);
      EXPECT_EQ(whole.warnings, r.warnings);
      EXPECT_EQ(whole.calls, r.calls);
    }
}

TEST(ObjGeometryReader, ReadsWhatTheStatementsSay) {
  ReadResult r = read(varietyText(), {});
  const ObjGeometry& g = r.geometry;
  EXPECT_EQ(g.positions.size(), 51u);
  EXPECT_EQ(g.uvs.size(), 3u);
  EXPECT_EQ(g.normals.size(), 2u);
  // Relative references: the quad "-4 -3 -2 -1" after four positions is positions 0..3 (cut along 1-3, as
  // its diagonals are equally long), uv 1 2 2 2, normal 0.
  EXPECT_EQ(std::vector<uint32_t>(g.cornerPositions.begin() + 3, g.cornerPositions.begin() + 9),
            (std::vector<uint32_t>{0, 1, 3, 1, 2, 3}));
  EXPECT_EQ(g.cornerUvs[4], 1);
  EXPECT_EQ(g.cornerNormals[4], 0);
  // Materials and smoothing groups follow the statements; "missing" is no material.
  EXPECT_EQ(g.materials[0], 0u);
  EXPECT_EQ(g.smoothingGroups[0], 1u);
  EXPECT_EQ(g.materials[3], kObjNoMaterial);
  EXPECT_EQ(g.smoothingGroups[3], 1u);
  EXPECT_EQ(g.smoothingGroups.back(), 34u);
  EXPECT_EQ(r.calls.front(), "mtllib@1:a.mtl b\\ c.mtl");
  EXPECT_EQ(r.calls[1], "usemtl@12:red");
  // Forward references to positions defined at the end resolve; the texture coordinate 9 of three is dropped.
  const uint32_t last = g.cornerPositions[g.cornerPositions.size() - 1];
  EXPECT_EQ(last, 50u);
  const std::vector<std::string> expected = {
      "test.obj:11: 'vw' (skin weight) statements are ignored",
      "test.obj:85: a face with fewer than 3 corners is left out",
      "test.obj:88: texture coordinate reference 9 but 3 texture coordinates are defined before it; 1 references "
      "to missing normals or texture coordinates are ignored",
      "test.obj: line and point elements are not rendered"};
  EXPECT_EQ(r.warnings, expected);
}

Scene loadText(const std::string& text, LoadWarnings& warnings, ObjReadOptions options = {}) {
  return loadObjText("test.obj", text, warnings, options);
}

std::string errorOf(const std::string& text, ObjReadOptions options = {}) {
  LoadWarnings warnings;
  try {
    loadText(text, warnings, options);
  } catch (const LoadError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a LoadError for:\n" << text;
  return {};
}

TEST(ObjLoader, ForwardReferencesAreCheckedAgainstTheWholeFile) {
  LoadWarnings warnings;
  EXPECT_EQ(loadText("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", warnings).triangleCount(), 1u);
  // Found to be out of range only at the end, the error still names the face's line, with small chunks too.
  const std::string beyond = "v 0 0 0\nv 1 0 0\nf 1 2 4\nv 0 1 0\n# end\n";
  for (size_t chunk : {size_t(1) << 20, size_t(3)})
    EXPECT_EQ(errorOf(beyond, {64, chunk}), "test.obj:3: vertex reference 4 but 2 vertices are defined before it");
}

TEST(ObjLoader, LoneCarriageReturnsEndLines) {
  LoadWarnings warnings;
  Scene s = loadText("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r", warnings);
  EXPECT_EQ(s.triangleCount(), 1u);
  EXPECT_EQ(errorOf("v 0 0 0\r\nv 1 0 0\rv x 0 0\nf 1 2 3\n"), "test.obj:3: a coordinate is not a number");
}

TEST(ObjLoader, MalformedReferencesAreErrors) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n";
  EXPECT_EQ(errorOf(tri + "f 1 2x 3\n"), "test.obj:5: vertex reference '2x' is not a number");
  EXPECT_EQ(errorOf(tri + "f 1/0 2 3\n"), "test.obj:5: texture coordinate reference 0 (OBJ counts from 1)");
  EXPECT_EQ(errorOf(tri + "f /1 2 3\n"), "test.obj:5: element with an empty vertex reference");
  EXPECT_EQ(errorOf(tri + "f 1 2 3.0\n"), "test.obj:5: vertex reference '3.0' is not a number");
  EXPECT_EQ(errorOf(tri + "l 1 0\nf 1 2 3\n"), "test.obj:5: vertex reference 0 (OBJ counts from 1)");
  LoadWarnings warnings;
  EXPECT_EQ(loadText(tri + "f 1/1 2//1 3 # trailing comment\n", warnings).triangleCount(), 1u);
}

TEST(ObjLoader, CoordinatesMustBeWholeNumbers) {
  const std::string faces = "f 1 2 3\n";
  for (const char* bad : {"v 0 0 1-2\n", "v 0 0 1e\n", "v 0 inf 0\n", "v 0 0 0x1p3\n", "v 0 0 0 red\n", "vt 0 0#\n"})
    EXPECT_EQ(errorOf(std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\n") + bad + faces),
              "test.obj:4: a coordinate is not a number")
        << bad;
  EXPECT_EQ(errorOf("v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n"), "test.obj:2: non-finite vertex position");
  EXPECT_EQ(errorOf("vt 0 -1e39\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "test.obj:1: non-finite texture coordinate");
  // Vertex colours and w after the coordinates are read past; a comment ends the statement.
  LoadWarnings warnings;
  Scene s = loadText("v 0 0 0 1 0.5 0\nv 1 0 0 1\nv 0 1 # no z\nf 1 2 3\n", warnings);
  EXPECT_EQ(s.meshes[0].positions.size(), 3u);
}

TEST(ObjNumbers, FloatSyntax) {
  float v = 0;
  for (const char* good : {"1", "-1.5", ".5", "-.5", "+2", "1e-3", "1E+05", "1.", "007"})
    EXPECT_TRUE(parseObjFloat(good, v)) << good;
  EXPECT_TRUE(parseObjFloat("-1.5e1", v));
  EXPECT_EQ(v, -15.0f);
  for (const char* bad : {"", "-", "nan", "-nan", "inf", "+inf", "1e", "1-2", "0x1p3", "--1", "+-1", "1.2.3", "e5"})
    EXPECT_FALSE(parseObjFloat(bad, v)) << bad;
  ASSERT_TRUE(parseObjFloat("-1e39", v));
  EXPECT_TRUE(std::isinf(v) && v < 0);
  ASSERT_TRUE(parseObjFloat("1e-50", v));
  EXPECT_EQ(v, 0.0f);
}

TEST(ObjNumbers, IntegerSyntax) {
  int64_t v = 0;
  ASSERT_TRUE(parseObjInteger("+12", v));
  EXPECT_EQ(v, 12);
  ASSERT_TRUE(parseObjInteger("-3", v));
  EXPECT_EQ(v, -3);
  for (const char* bad : {"", "-", "+", "1.5", "2x", " 1"}) EXPECT_FALSE(parseObjInteger(bad, v)) << bad;
  ASSERT_TRUE(parseObjInteger("123456789012345678901234567890", v));
  EXPECT_EQ(v, int64_t(1) << 62);
}

TEST(ObjLoader, ReadsEveryLibraryOfAnMtllibStatementAndRecordsTheInputFiles) {
  test::TempFolder dir;
  dir.write("a.mtl", "newmtl red\nKd 1 0 0\n");
  dir.write("b c.mtl", "newmtl blue\nKd 0 0 1\nmap_Kd blue.png\n");
  const std::string obj =
      dir.write("m.obj",
                "mtllib a.mtl b\\ c.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\nusemtl blue\nf 1 2 3\n");
  LoadWarnings warnings;
  Scene s = loadObj(obj, warnings);
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.meshes[0].triangleMaterials, (std::vector<uint32_t>{0, 1}));
  EXPECT_FLOAT_EQ(s.materials[1].baseColor.z, 1.0f);
  const std::vector<std::string> files = {obj, dir.file("a.mtl"), dir.file("b c.mtl"), dir.file("blue.png")};
  EXPECT_EQ(s.inputFiles, files);
}

}  // namespace
}  // namespace candela
