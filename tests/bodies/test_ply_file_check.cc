// PLY files whose data VTK's reader would follow out of bounds: faces naming vertices that do
// not exist (past the count, negative), lists of the wrong length, ASCII lines short of values,
// coordinates that are not numbers, headers VTK misreads. Each is refused by tightfit's PLY
// reader (bodies/ply_file_reader.cc) as it reads, naming the file and the face, vertex or line
// (exit status 2); the same tetrahedron written correctly is read.
#include "bodies/body_mesh_error.h"
#include "bodies/mesh_body.h"
#include "body_mesh_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace tightfit {
namespace {

using namespace tightfit::testing;

void expect_refusal_names(const std::string& path, const std::vector<std::string>& words) {
  const std::string message = mesh_refusal(path);
  EXPECT_NE(message.find("'" + path + "'"), std::string::npos) << message;
  for (const std::string& w : words) EXPECT_NE(message.find(w), std::string::npos) << message;
}

const std::string header_start =
    "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 4\nproperty list uchar int vertex_indices\nend_header\n";

// The regular tetrahedron (outward faces), its faces as given, as a binary little-endian PLY.
std::string binary_tetrahedron(const std::vector<std::vector<std::int32_t>>& faces,
                               float y_of_vertex_2 = -1) {
  std::string bytes = "ply\nformat binary_little_endian 1.0\n" + header_start;
  const float xyz[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, y_of_vertex_2, -1}, {-1, -1, 1}};
  bytes.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  for (const auto& face : faces) {
    bytes.push_back(static_cast<char>(face.size()));
    for (const std::int32_t v : face) bytes.append(reinterpret_cast<const char*>(&v), 4);
  }
  return bytes;
}

std::string ascii_tetrahedron(const std::string& vertices, const std::string& faces) {
  return "ply\nformat ascii 1.0\n" + header_start + vertices + faces;
}

const std::vector<std::vector<std::int32_t>> outward = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
const std::string ascii_vertices = "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n";
const std::string ascii_faces = "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n";

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The well-formed files first: the check refuses nothing VTK reads correctly.
TEST(PlyFileCheck, WellFormedTetrahedronIsRead) {
  const std::string binary = temporary_path("tetrahedron_binary.ply");
  write_bytes(binary, binary_tetrahedron(outward));
  EXPECT_EQ(load_mesh_body(binary, {})->surface().triangles.size(), 4u);
  const std::string ascii = temporary_path("tetrahedron_ascii.ply");
  write_text(ascii, ascii_tetrahedron(ascii_vertices, ascii_faces));
  EXPECT_EQ(load_mesh_body(ascii, {})->surface().triangles.size(), 4u);
}

// A binary face naming vertex 4 of 4 (the fuzz finding's kind) or vertex -1.
TEST(PlyFileCheck, BinaryFaceIndexOutOfRangeIsRefusedNamingTheFace) {
  const std::string path = temporary_path("binary_bad_index.ply");
  write_bytes(path, binary_tetrahedron({{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 4, 2}}));
  expect_refusal_names(path, {"face 3", "names vertex 4 (counted from 0) of 4"});
  write_bytes(path, binary_tetrahedron({{0, 1, 2}, {0, -1, 1}, {0, 2, 3}, {1, 3, 2}}));
  expect_refusal_names(path, {"face 1", "names vertex -1"});
}

TEST(PlyFileCheck, AsciiFaceIndexOutOfRangeIsRefusedNamingTheLine) {
  const std::string path = temporary_path("ascii_bad_index.ply");
  // Header 9 lines, 4 vertex lines: face 2 is line 16.
  write_text(path, ascii_tetrahedron(ascii_vertices, "3 0 1 2\n3 0 3 1\n3 0 2 7\n3 1 3 2\n"));
  expect_refusal_names(path, {"line 16", "face 2", "names vertex 7"});
  write_text(path, ascii_tetrahedron(ascii_vertices, "3 0 1 2\n3 0 3 1\n3 0 -2 3\n3 1 3 2\n"));
  expect_refusal_names(path, {"line 16", "names vertex -2"});
  write_text(path, ascii_tetrahedron(ascii_vertices, "3 0 1 2\n3 0 3 1\n3 0 2.5 3\n3 1 3 2\n"));
  expect_refusal_names(path, {"line 16", "names vertex 2.5"});
}

// A list count VTK would allocate for (255 indices, then read past the file) or a face the
// mesh cannot hold.
TEST(PlyFileCheck, FaceOfOtherThanThreeOrFourVerticesIsRefused) {
  const std::string path = temporary_path("long_list.ply");
  std::string bytes = binary_tetrahedron(outward);
  bytes[bytes.size() - 13] = static_cast<char>(255);  // the last face's count
  write_bytes(path, bytes);
  expect_refusal_names(path, {"face 3", "has 255 vertices"});
  write_text(path, ascii_tetrahedron(ascii_vertices, "3 0 1 2\n2 0 3\n3 0 2 3\n3 1 3 2\n"));
  expect_refusal_names(path, {"line 15", "face 1", "has 2 vertices"});
}

// VTK reads an ASCII element from its one line without counting the words.
TEST(PlyFileCheck, AsciiLineShortOfValuesIsRefused) {
  const std::string path = temporary_path("short_line.ply");
  write_text(path, ascii_tetrahedron("1 1 1\n1 -1\n-1 1 -1\n-1 -1 1\n", ascii_faces));
  expect_refusal_names(path, {"line 11", "vertex 1", "fewer values"});
  write_text(path, ascii_tetrahedron(ascii_vertices, "3 0 1 2\n3 0 3 1\n\n3 0 2 3\n3 1 3 2\n"));
  expect_refusal_names(path, {"line 16", "face 2", "fewer values"});
  write_text(path, ascii_tetrahedron(ascii_vertices, "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3\n"));
  expect_refusal_names(path, {"line 17", "face 3", "fewer values"});
  write_text(path, ascii_tetrahedron("1 1 1\n1 -1 one\n-1 1 -1\n-1 -1 1\n", ascii_faces));
  expect_refusal_names(path, {"line 11", "vertex 1"});
  // Three values for a stream, two words for VTK, which splits at spaces and tabs only.
  write_text(path, ascii_tetrahedron("1 1 1\n1 -1\v-1\n-1 1 -1\n-1 -1 1\n", ascii_faces));
  expect_refusal_names(path, {"line 11", "vertex 1"});
}

TEST(PlyFileCheck, CoordinateThatIsNotFiniteIsRefusedNamingTheVertex) {
  const std::string path = temporary_path("nan_vertex.ply");
  write_bytes(path, binary_tetrahedron(outward, std::numeric_limits<float>::quiet_NaN()));
  expect_refusal_names(path, {"vertex 2", "coordinate y is not a finite number"});
  write_text(path, ascii_tetrahedron("1 1 1\n1 -1 -1\n-1 inf -1\n-1 -1 1\n", ascii_faces));
  expect_refusal_names(path, {"line 12", "vertex 2", "coordinate y"});
}

TEST(PlyFileCheck, BinaryDataEndingInsideAFaceIsRefusedAsTruncated) {
  const std::string path = temporary_path("truncated_binary.ply");
  const std::string bytes = binary_tetrahedron(outward);
  write_bytes(path, bytes.substr(0, bytes.size() - 3));
  expect_refusal_names(path, {"truncated", "4 vertices and 4 faces", "ends in face 3"});
}

// Header lines VTK takes on trust: a property with no element to belong to, a second vertex
// element, coordinates or indices of the wrong kind, no vertices at all, an element VTK does
// not step over before the faces.
TEST(PlyFileCheck, HeadersVtkWouldMisreadAreRefused) {
  struct Case {
    std::string header;
    std::vector<std::string> words;
  };
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const std::string faces = "element face 1\nproperty list uchar int vertex_indices\n";
  const Case cases[] = {
      {"property float x\nelement vertex 3\n" + xyz + faces, {"line 3", "before any element"}},
      {"element vertex 3\n" + xyz + "element vertex 3\n" + xyz + faces,
       {"line 7", "a second element 'vertex'"}},
      {"element vertex 3\nproperty float x\nproperty float y\n" + faces, {"no property 'z'"}},
      {"element vertex 3\n" + xyz + "element face 1\nproperty uchar vertex_indices\n",
       {"'vertex_indices' is a number"}},
      {"element vertex 3\nproperty list uchar float x\nproperty float y\nproperty float z\n" +
           faces,
       {"'x' is a list"}},
      {faces, {"no vertex element"}},
      {"element vertex 3\n" + xyz + "element edge 1\nproperty int vertex1\n" + faces,
       {"'edge' comes before"}},
      {"element vertex 3\n" + xyz + "element face 1\nproperty list float int vertex_indices\n",
       {"line 8", "an integer count"}},
      // An element with no properties, whose unset property list VTK frees (found by
      // fuzz_body_mesh_ply), and a second "ply" and "format" line.
      {"element vertex 3\n" + xyz + "element empty 2\n" + faces,
       {"the element 'empty' has no properties"}},
      {"element vertex 3\n" + xyz + "ply\nformat ascii 1.0\n" + faces,
       {"line 7", "a second 'ply' line"}},
      {"element vertex 3\n" + xyz + "format ascii 1.0\n" + faces,
       {"line 7", "a second 'format' line"}},
      // A vertical tab VTK keeps in the name "z" (found by fuzz_body_mesh_ply).
      {"element vertex 3\nproperty float x\nproperty float y\nproperty float z\v\n" + faces,
       {"line 6", "control character"}},
  };
  const std::string path = temporary_path("bad_header.ply");
  for (const Case& c : cases) {
    write_text(path,
               "ply\nformat ascii 1.0\n" + c.header + "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    expect_refusal_names(path, c.words);
  }
}

}  // namespace
}  // namespace tightfit
