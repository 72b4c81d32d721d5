// STL body files read by tightfit's own reader (bodies/stl_file_reader.h), ASCII and binary:
// the facets' corners welded into the vertices of a connected surface as VTK's reader welded
// them, and every malformed ASCII line refused naming its line.
#include "bodies/body_mesh_error.h"
#include "bodies/polygon_mesh.h"
#include "body_mesh_files.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace tightfit {
namespace {

using namespace tightfit::testing;

struct Facet {
  float corners[3][3];
};

// A binary STL of `facets`, its header announcing `announced` facets, `tail` bytes after them.
void write_binary_stl(const std::string& path, const std::vector<Facet>& facets,
                      std::uint32_t announced, const std::string& tail = "") {
  std::string bytes(80, ' ');
  for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<char>((announced >> (8 * k)) & 0xff));
  for (const Facet& f : facets) {
    const float normal[3] = {0, 0, 1};
    bytes.append(reinterpret_cast<const char*>(normal), sizeof normal);
    bytes.append(reinterpret_cast<const char*>(f.corners), sizeof f.corners);
    bytes.append(2, '\0');
  }
  bytes += tail;
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

// The tetrahedron (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1), outward faces, as STL facets.
std::vector<Facet> tetrahedron_facets() {
  const float v[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  const int faces[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  std::vector<Facet> facets(4);
  for (int f = 0; f < 4; ++f)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) facets[f].corners[c][k] = v[faces[f][c]][k];
  return facets;
}

std::string ascii_stl(const std::vector<Facet>& facets) {
  std::string text = "solid t\n";
  for (const Facet& f : facets) {
    text += "facet normal 0 0 1\nouter loop\n";
    for (const auto& c : f.corners)
      text += "vertex " + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " +
              std::to_string(c[2]) + "\n";
    text += "endloop\nendfacet\n";
  }
  return text + "endsolid t\n";
}

// The 12 corners of the tetrahedron's 4 facets are its 4 vertices, numbered as they first
// appear, and the faces name them in the facets' order: the same from ASCII and binary.
TEST(StlFileReader, CornersAreWeldedIntoTheTetrahedronsFourVertices) {
  const std::string ascii = temporary_path("tetrahedron_ascii.stl");
  const std::string binary = temporary_path("tetrahedron_binary.stl");
  write_text(ascii, ascii_stl(tetrahedron_facets()));
  write_binary_stl(binary, tetrahedron_facets(), 4);
  const std::vector<std::vector<int>> faces = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  for (const std::string& path : {ascii, binary}) {
    const PolygonMesh mesh = read_polygon_mesh(path);
    ASSERT_EQ(mesh.vertices.size(), 4u) << path;
    EXPECT_EQ(mesh.vertices[3], Vec3(-1, -1, 1)) << path;
    EXPECT_EQ(mesh.faces, faces) << path;
  }
}

// Many writers leave the binary count wrong: every whole facet after the header is read (a
// count of 0 here), and a remainder shorter than a facet is skipped. A count above what the
// file holds stays refused (BodyMeshHostileInput).
TEST(StlFileReader, BinaryFacetsAreReadToTheEndWhateverTheCount) {
  const std::string path = temporary_path("count_zero.stl");
  write_binary_stl(path, tetrahedron_facets(), 0, std::string(10, 'x'));
  const PolygonMesh mesh = read_polygon_mesh(path);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.faces.size(), 4u);
}

// 0 and -0 are one coordinate; a facet two of whose corners weld onto one vertex has no area
// and is dropped (its corners still number vertices). Here a fifth facet from (0,0,0) to
// (-0,0,-0) and (1,0,0): 4 + 2 vertices, 4 faces.
TEST(StlFileReader, SignedZerosWeldAndCollapsedFacetsAreDropped) {
  std::vector<Facet> facets = tetrahedron_facets();
  facets.push_back(Facet{{{0, 0, 0}, {-0.0f, 0, -0.0f}, {1, 0, 0}}});
  const std::string path = temporary_path("collapsed.stl");
  write_binary_stl(path, facets, 5);
  const PolygonMesh mesh = read_polygon_mesh(path);
  EXPECT_EQ(mesh.vertices.size(), 6u);
  EXPECT_EQ(mesh.faces.size(), 4u);
}

// An ASCII coordinate is read in double precision, then rounded to single (as VTK's reader
// did, so that a file reads to the same vertices): 1 + 2^-24 + 2^-60 rounds to the double
// 1 + 2^-24, halfway between the floats 1 and 1 + 2^-23, and then to even, 1. Read directly
// in single precision it would be 1 + 2^-23.
TEST(StlFileReader, AsciiCoordinatesRoundThroughDoublePrecision) {
  const std::string x = "1.00000005960464477625798673798840354720596224069595336914062";
  const std::string path = temporary_path("double_rounding.stl");
  write_text(path, "solid t\nfacet normal 0 0 1\nouter loop\nvertex " + x +
                       " 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid t\n");
  const PolygonMesh mesh = read_polygon_mesh(path);
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.vertices[0].x(), 1.0);
}

// Keywords in any case, blank lines, tabs, carriage returns, "color" lines between facets and
// two solids read as one surface.
TEST(StlFileReader, AsciiAsExportersWriteIt) {
  const std::string path = temporary_path("exported.stl");
  std::string text = ascii_stl(tetrahedron_facets());
  text.insert(text.find("facet normal", text.find("endfacet")), "endsolid t\r\n\r\nSOLID u\r\n");
  text.insert(text.find('\n') + 1, "color 1 0 0\n\t\n");
  text.replace(text.find("vertex"), 6, "VERTEX\t");
  write_text(path, text);
  const PolygonMesh mesh = read_polygon_mesh(path);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.faces.size(), 4u);
}

// Each malformed ASCII file is refused naming the line at fault (counted from 1, blank lines
// too) and what is wrong there.
TEST(StlFileReader, MalformedAsciiIsRefusedNamingTheLine) {
  const std::string good_facet =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
      "endfacet\n";
  struct Broken {
    std::string text;
    std::vector<std::string> words;
  };
  const Broken broken[] = {
      {"hello\n" + good_facet, {"line 1", "expected 'solid', found 'hello'"}},
      {"solid t\n\n" + good_facet + "junk\n", {"line 10", "found 'junk'"}},
      {"solid t\nfacet normal 0 0 1\nloop\n", {"line 3", "expected 'outer loop'"}},
      {"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
       "vertex 1 1 0\n",
       {"line 7", "expected 'endloop', found 'vertex'"}},
      {"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n",
       {"line 4", "three coordinates, this one 2"}},
      {"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0 7\n",
       {"line 4", "three coordinates, this one 4"}},
      {"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 x1 0\n",
       {"line 4", "'x1' is not a number"}},
      {"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 nan\n",
       {"line 4", "'nan' is not a finite number"}},
      {"solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 1e39\n",
       {"line 4", "beyond single precision"}},
      {"solid t\n" + good_facet, {"line 8", "ends before 'endsolid'"}},
      {"solid t\n\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n",
       {"line 5", "ends inside the facet begun on line 3"}},
  };
  for (const Broken& b : broken) {
    const std::string path = temporary_path("broken_ascii.stl");
    write_text(path, b.text);
    const std::string message = mesh_refusal(path);
    EXPECT_NE(message.find(path), std::string::npos) << b.text << "\n" << message;
    for (const std::string& w : b.words)
      EXPECT_NE(message.find(w), std::string::npos) << b.text << "\n" << message;
  }
}

}  // namespace
}  // namespace tightfit
