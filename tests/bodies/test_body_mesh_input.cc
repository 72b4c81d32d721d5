// Body mesh files that are broken or describe no proper body: each is refused with a message
// that names the file, what is wrong and where (face, edge or vertex indices, or the line).
// And the import options, against transforms worked out by hand.
#include "bodies/body_mesh_error.h"
#include "bodies/mesh_body.h"
#include "bodies/morphing_mesh_body.h"
#include "body_mesh_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace tightfit {
namespace {

using namespace tightfit::testing;

// Loads `path` expecting a BodyMeshError (a std::invalid_argument, which the application turns
// into exit status 2) whose message holds every one of `words`.
void expect_refused(const std::string& path, const std::vector<std::string>& words,
                    const MeshBodyOptions& options = {}) {
  try {
    load_mesh_body(path, options);
    ADD_FAILURE() << path << " was accepted";
  } catch (const BodyMeshError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    for (const std::string& w : words) EXPECT_NE(message.find(w), std::string::npos) << message;
  }
}

const std::string tetrahedron_vertices = "v 1 1 1\nv 1 -1 -1\nv -1 1 -1\nv -1 -1 1\n";

TEST(BodyMeshInput, TheTetrahedronItselfIsAccepted) {
  const std::string path = temporary_path("good.obj");
  write_text(path, tetrahedron_vertices + "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
  const auto body = load_mesh_body(path, {});
  // A regular tetrahedron of edge a = 2 sqrt(2): a^3 / (6 sqrt 2) = 8/3.
  EXPECT_NEAR(enclosed_volume_m3(body->surface().vertices_m, body->surface().triangles), 8.0 / 3.0,
              1e-14);
}

TEST(BodyMeshInput, TruncatedObj) {
  const std::string path = temporary_path("truncated.obj");
  write_text(path, tetrahedron_vertices + "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4");
  expect_refused(path, {"line 8"});
}

TEST(BodyMeshInput, WrongNumbersInObj) {
  const std::string path = temporary_path("letters.obj");
  write_text(path,
             "v 1 1 1\nv 1 -1 x1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
  expect_refused(path, {"line 2", "'x1' is not a finite number"});
  write_text(path, "v 1 1 1\nv 1 -1\nv -1 1 -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
  expect_refused(path, {"line 2", "three coordinates"});
  // Face indices are checked against the file's lines (VTK's reader followed a texture index
  // past the "vt" lines into a null pointer).
  write_text(path, tetrahedron_vertices + "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 9\n");
  expect_refused(path, {"line 8", "face corner '9'", "not one of the 4 'v' lines"});
  write_text(path, tetrahedron_vertices + "f 1 2 3\nf 1 4 2\nf 1/1 3 4\nf 2 4 3\n");
  expect_refused(path, {"line 7", "face corner '1/1'", "not one of the 0 'vt' lines"});
  write_text(path, tetrahedron_vertices + "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 -1\n");
  expect_refused(path, {"line 8", "relative ones are not read"});
}

TEST(BodyMeshInput, TruncatedStlAndPly) {
  struct Broken {
    std::string file, text;
    std::vector<std::string> words;
  };
  const Broken broken[] = {
      {"truncated.stl",
       "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
       "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0",
       {"line 12", "three coordinates"}},
      {"truncated.ply",
       "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
       "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
       "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n",
       {"truncated", "4 vertices and 4 faces"}}};
  for (const Broken& b : broken) {
    write_text(temporary_path(b.file), b.text);
    expect_refused(temporary_path(b.file), b.words);
  }
}

// A face of 5 corners or a polyline: PolygonMesh holds triangles and quads only, refused naming
// the line.
TEST(BodyMeshInput, ObjFacesOtherThanTrianglesAndQuadsNameTheLine) {
  const std::string path = temporary_path("pentagon.obj");
  write_text(path, tetrahedron_vertices + "v 0 0 0\nf 1 2 3 5 4\nf 1 4 2\n");
  expect_refused(path, {"line 6", "face 0 has 5 vertices"});
  write_text(path, tetrahedron_vertices + "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\nl 1 2\n");
  expect_refused(path, {"line 9", "polyline"});
}

// Texture coordinates and normals name lines of their own: the faces still share the file's
// vertices, so the tetrahedron is one closed surface of 4 vertices whatever indices its
// corners give them (VTK's reader gave each corner a vertex of its own, an open surface), with
// its volume a^3 / (6 sqrt 2) = 8/3 for edge a = 2 sqrt(2).
TEST(BodyMeshInput, ObjTextureAndNormalIndicesKeepTheSurfaceWelded) {
  const std::string path = temporary_path("textured.obj");
  write_text(path, tetrahedron_vertices +
                       "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                       "f 1/2/1 2/1/1 3/3/1\nf 1/3 4/1 2/2\nf 1//1 3//1 4//1\nf 2 4 3\n");
  const auto body = load_mesh_body(path, {});
  EXPECT_EQ(body->surface().vertices_m.size(), 4u);
  EXPECT_NEAR(enclosed_volume_m3(body->surface().vertices_m, body->surface().triangles), 8.0 / 3.0,
              1e-14);
}

TEST(BodyMeshInput, MissingFileAndUnknownType) {
  expect_refused(temporary_path("no_such_body.obj"), {"cannot open"});
  const std::string path = temporary_path("body.off");
  write_text(path, "OFF\n");
  expect_refused(path, {"unknown file type", ".off"});
}

TEST(BodyMeshInput, NotClosed) {
  const std::string path = temporary_path("open.obj");
  write_text(path, tetrahedron_vertices + "f 1 2 3\nf 1 4 2\nf 1 3 4\n");
  expect_refused(path, {"not closed", "edge between vertices"});
  // Accepted as an open surface when asked for.
  MeshBodyOptions open;
  open.import.allow_open_surface = true;
  EXPECT_EQ(load_mesh_body(path, open)->surface().triangles.size(), 3u);
}

TEST(BodyMeshInput, NonManifoldEdge) {
  // A fin: a fifth vertex and a face on the edge 1-2, which then joins three faces.
  const std::string path = temporary_path("fin.obj");
  write_text(path, tetrahedron_vertices + "v 3 0 0\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\nf 1 2 5\n");
  expect_refused(path, {"non-manifold", "edge between vertices 0 and 1", "3 faces (0, 1, 4)"});
}

TEST(BodyMeshInput, NonManifoldVertex) {
  // Two corner tetrahedra touching at the origin (vertex 0), the second mirrored through it:
  // every edge joins two faces, but the faces round vertex 0 form two fans.
  const std::string path = temporary_path("bowtie.obj");
  write_text(path,
             "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n"
             "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
             "f 1 5 6\nf 1 7 5\nf 1 6 7\nf 7 6 5\n");
  expect_refused(path, {"non-manifold", "vertex 0", "more than one fan"});
}

TEST(BodyMeshInput, InconsistentOrientation) {
  const std::string path = temporary_path("flipped_face.obj");
  write_text(path, tetrahedron_vertices + "f 1 2 3\nf 1 4 2\nf 1 4 3\nf 2 4 3\n");
  expect_refused(path, {"inconsistent orientation", "face 2 (vertices 0, 3, 2)"});
}

TEST(BodyMeshInput, InwardFacing) {
  const std::string path = temporary_path("inward.obj");
  write_text(path, tetrahedron_vertices + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  expect_refused(path, {"oriented inwards", "-2.66667"});
}

// A coordinate that is not a finite number reaches no distance query. OBJ and ASCII STL spell
// it "nan" or "inf", a binary STL holds the bits. VTK's OBJ reader read "nan" as 0 (the file
// was accepted with a wrong vertex): the OBJ and STL readers refuse it naming the line; a
// binary STL's vertex is refused after reading.
TEST(BodyMeshInput, CoordinatesThatAreNotFiniteInObjAndStl) {
  const std::string obj = temporary_path("nan.obj");
  write_text(obj,
             "v 1 1 1\nv 1 -1 -1\nv -1 nan -1\nv -1 -1 1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
  expect_refused(obj, {"line 3", "'nan' is not a finite number"});
  const std::string stl = temporary_path("inf.stl");
  write_text(stl,
             "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
             "vertex 0 inf 0\nendloop\nendfacet\nendsolid t\n");
  expect_refused(stl, {"line 6", "'inf' is not a finite number"});
  std::string binary(80, ' ');
  const std::uint32_t one = 1;
  binary.append(reinterpret_cast<const char*>(&one), 4);
  const float nan = std::nanf("");
  const float facet[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, nan, 0};
  binary.append(reinterpret_cast<const char*>(facet), sizeof facet);
  binary.append(2, '\0');
  const std::string binary_stl = temporary_path("nan_binary.stl");
  write_text(binary_stl, binary);
  expect_refused(binary_stl, {"not a finite number"});
}

TEST(BodyMeshInput, DegenerateFaces) {
  // A repeated vertex in a quad, then a triangle whose corners lie on one line.
  const std::string path = temporary_path("degenerate.obj");
  write_text(path, tetrahedron_vertices + "f 1 2 3 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
  expect_refused(path, {"face 0 (vertices 0, 2, 2) is degenerate"});
  write_text(path,
             tetrahedron_vertices + "v 1 0 0\n" + "f 1 5 2\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
  expect_refused(path, {"face 0 (vertices 0, 4, 1) is degenerate"});
}

TEST(BodyMeshInput, MorphNeedsOneConnectivity) {
  const std::string a = temporary_path("morph_a.obj"), b = temporary_path("morph_b.obj");
  write_obj(a, revolution_surface({-0.1, 0.1}, {0.05, 0.05}, 8));
  write_obj(b, revolution_surface({-0.1, 0.1}, {0.05, 0.05}, 9));
  MeshBodyOptions options;
  try {
    load_morphing_mesh_body(a, b, options);
    ADD_FAILURE() << "different meshes were accepted as a morph";
  } catch (const BodyMeshError& e) {
    EXPECT_NE(std::string(e.what()).find("one connectivity"), std::string::npos) << e.what();
  }
  auto body = load_morphing_mesh_body(a, a, options);
  EXPECT_THROW(body->set_morph(1.5), std::invalid_argument);
  EXPECT_THROW(body->set_morph(0.5, 0.0), std::invalid_argument);
}

TEST(BodyMeshImport, UnitsUpAxisRotationAndTranslation) {
  // A vertex at (10, 20, 30) cm in a +y-up file: 0.1, 0.2, 0.3 m; +y up turns onto +z by +90
  // degrees about x: (0.1, -0.3, 0.2); then 90 degrees about z: (0.3, 0.1, 0.2); then the
  // translation.
  PolygonMesh file = regular_tetrahedron(1.0);
  file.vertices[0] = Vec3(10, 20, 30);
  MeshImportOptions o;
  o.metres_per_unit = 0.01;
  o.up_axis = "+y";
  o.rotation_deg = Vec3(0, 0, 90);
  o.translation_m = Vec3(1, 2, 3);
  const TriangleSurface s = import_surface(file, o);
  EXPECT_LT((s.vertices_m[0] - Vec3(1.3, 2.1, 3.2)).norm(), 1e-15);
  // Each up axis lands on +z.
  const std::vector<std::pair<std::string, Vec3>> ups = {
      {"+x", Vec3::UnitX()},  {"-x", -Vec3::UnitX()}, {"+y", Vec3::UnitY()},
      {"-y", -Vec3::UnitY()}, {"+z", Vec3::UnitZ()},  {"-z", -Vec3::UnitZ()}};
  for (const auto& [up, direction] : ups) {
    MeshImportOptions u;
    u.up_axis = up;
    EXPECT_LT((import_rotation(u) * direction - Vec3::UnitZ()).norm(), 1e-15) << up;
  }
  o.up_axis = "up";
  EXPECT_THROW(import_surface(file, o), std::invalid_argument);
  o.up_axis = "+z";
  o.metres_per_unit = 0.0;
  EXPECT_THROW(import_surface(file, o), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
