// Body mesh files made to hurt: headers that announce more than the file holds or the machine
// can store, and the inputs fuzzing found (tests/bodies/fuzz_findings/, from scripts/fuzz.sh).
// Each must end in a BodyMeshError naming the file (exit status 2), never a crash, a sanitizer
// report or an allocation the size of the announced count.
#include "bodies/body_mesh_error.h"
#include "bodies/mesh_body.h"
#include "body_mesh_files.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tightfit {
namespace {

using namespace tightfit::testing;

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// A binary STL: 80-byte header, facet count, then 50 bytes per facet (one facet here).
std::string binary_stl(const std::string& header, std::uint32_t announced_facets) {
  std::string bytes = header;
  bytes.resize(80, ' ');
  for (int k = 0; k < 4; ++k)
    bytes.push_back(static_cast<char>((announced_facets >> (8 * k)) & 0xff));
  const float facet[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  bytes.append(reinterpret_cast<const char*>(facet), sizeof facet);
  bytes.append(2, '\0');
  return bytes;
}

// VTK's reader allocates for the header's count before reading a facet: 4e9 facets (about
// 600 GB of points) from a 134-byte file. Refused as truncated, whether or not the header
// starts with "solid" as many exporters write it.
TEST(BodyMeshHostileInput, BinaryStlAnnouncingMoreFacetsThanItHolds) {
  for (const std::string header : {"binary exported by hand", "solid but binary all the same"}) {
    const std::string path = temporary_path("bogus_count.stl");
    write_bytes(path, binary_stl(header, 4000000000u));
    const std::string message = mesh_refusal(path);
    EXPECT_NE(message.find("truncated binary STL"), std::string::npos) << header << ": " << message;
    EXPECT_NE(message.find("4000000000 facets"), std::string::npos) << message;
  }
}

// A header that announces a billion faces is refused before anything is read, with the
// memory it would need.
TEST(BodyMeshHostileInput, PlyAnnouncingABillionFaces) {
  const std::string path = temporary_path("billion.ply");
  write_text(path,
             "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
             "property float y\nproperty float z\nelement face 1000000000\n"
             "property list uchar int vertex_indices\nend_header\n");
  const std::string message = mesh_refusal(path);
  EXPECT_NE(message.find("would need about"), std::string::npos) << message;
  EXPECT_NE(message.find("1e+09 faces announced"), std::string::npos) << message;
}

TEST(BodyMeshHostileInput, PlyWithANegativeCount) {
  const std::string path = temporary_path("negative.ply");
  write_text(path,
             "ply\nformat ascii 1.0\nelement vertex -3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
             "end_header\n3 0 1 2\n");
  EXPECT_NE(mesh_refusal(path).find("line 3: a negative element count"), std::string::npos)
      << mesh_refusal(path);
}

// Every input kept from fuzzing is refused with a message naming the file.
TEST(BodyMeshHostileInput, FuzzFindingsAreRefused) {
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(TIGHTFIT_BODY_FUZZ_FINDINGS_DIR)) {
    const std::string name = entry.path().filename().string();
    if (name == "README.md") continue;
    // The file name keeps the reader's extension; copied so that messages name a scratch path.
    const std::string path = temporary_path("finding_" + name);
    std::filesystem::copy_file(entry.path(), path,
                               std::filesystem::copy_options::overwrite_existing);
    const std::string message = mesh_refusal(path);
    EXPECT_NE(message.find(path), std::string::npos)
        << name << " was accepted or crashed: " << message;
    std::printf("%s: %s\n", name.c_str(), message.c_str());
    ++n;
  }
  std::printf("%d fuzz findings refused\n", n);
}

}  // namespace
}  // namespace tightfit
