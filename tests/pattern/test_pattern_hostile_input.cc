// Pattern files that must not hurt: outlines the mesher cannot honour are refused with a
// message naming the panel, and every input kept from fuzzing (fuzz_findings/) is refused as
// a PatternError, never a crash, a hang or another exception.
#include "fuzz/pattern_fuzz_steps.h"
#include "pattern/pattern_file.h"
#include "pattern/pattern_garment.h"
#include "tests/pattern/pattern_files.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

namespace tightfit::pattern {
namespace {

// The message of the PatternError `path` is refused with; a failure when it is accepted.
std::string refusal(const std::string& path, double edge_length_m) {
  try {
    PatternMeshOptions options;
    options.edge_length_m = edge_length_m;
    pattern_garment(read_pattern_file(path), options);
  } catch (const PatternError& error) {
    return error.what();
  }
  ADD_FAILURE() << path << " was accepted";
  return "";
}

TEST_F(PatternFiles, OutlineThatCrossesItselfIsRefusedNamingThePanel) {
  // A bow tie: the edges from (0,0) to (1,1) and from (1,0) to (0,1) cross at (0.5, 0.5).
  const std::string path = write("bow_tie.json", R"({
    "pattern": {"panels": {"tie": {
      "vertices": [[0, 0], [1, 1], [1, 0], [0, 1]],
      "edges": [{"endpoints": [0, 1]}, {"endpoints": [1, 2]}, {"endpoints": [2, 3]},
                {"endpoints": [3, 0]}]}},
      "stitches": []},
    "properties": {"units_in_meter": 1}})");
  const std::string message = refusal(path, 0.1);
  EXPECT_NE(message.find("panel 'tie': the outline crosses itself"), std::string::npos) << message;
}

TEST_F(PatternFiles, SpikeSharperThanADegreeIsRefusedNamingThePanelAndTheCorner) {
  // 100 mm wide and 11.1 m tall, the top corner a spike of 0.26 degrees (its sides run from
  // (100, 11100) down to (100, 0) and towards (50, 130)): the angle bound would refine towards
  // its tip without end: each meshing round added about 200 outline points, 16 rounds and
  // 38 s under the sanitizers before the mesher refused corners under a degree. Its sides'
  // tangents meet at atan(50 / 10970) = 0.261 degrees, its sampled chords at 0.264 (SVG's y
  // runs down: the tip is at y = -11.1 m).
  const std::string path = write("spike.svg", R"(<svg width="200mm">
    <g id="fs-stack-test.spike-part-test.spike">
      <path class="fabric" id="p" d="M 0,0 l 100,0 V 11100 Q 50,130 0,100 C 0,66 0,33 0,1 z"/>
    </g></svg>)");
  const std::string message = refusal(path, 0.555);
  EXPECT_NE(message.find("panel 'spike': the outline turns back at (0.1, -11.1) m in a corner of "
                         "0.264 degrees"),
            std::string::npos)
      << message;
}

TEST_F(PatternFiles, NeckFarNarrowerThanTheEdgeLengthIsRefusedNamingThePanel) {
  // Two 100 mm squares joined by a neck 1 m long and 0.1 mm wide, meshed at 5 cm: the angle
  // bound makes triangles as small as the neck is wide along all of it (some 10^4 vertices).
  // The budget, 10 x (2 A / (sqrt(3) h^2) + L / h + outline points) + 1000, is about 1700.
  const std::string path = write("neck.svg", R"(<svg width="200mm">
    <g id="fs-stack-test.neck-part-test.neck">
      <path class="fabric" id="p"
            d="M 0,0 H 100 V 50 H 1100 V 0 H 1200 V 100 H 1100 V 50.1 H 100 V 100 H 0 z"/>
    </g></svg>)");
  const std::string message = refusal(path, 0.05);
  EXPECT_NE(message.find("panel 'neck': meshing at edge length 0.050000 m took more than"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("far narrower than the edge length"), std::string::npos) << message;
}

// Every input kept from fuzzing goes through the fuzz targets' steps and is refused.
TEST(PatternHostileInput, FuzzFindingsAreRefused) {
  int n = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(TIGHTFIT_PATTERN_FUZZ_FINDINGS_DIR)) {
    const std::string name = entry.path().filename().string();
    if (name == "README.md") continue;
    try {
      fuzz::read_check_mesh_and_sew(entry.path().string());
      ADD_FAILURE() << name << " was accepted";
    } catch (const PatternError& error) {
      EXPECT_GT(std::string(error.what()).size(), 20u) << name << ": " << error.what();
    }
    ++n;
  }
  EXPECT_GT(n, 0) << "no fuzz findings in " << TIGHTFIT_PATTERN_FUZZ_FINDINGS_DIR;
  std::printf("%d fuzz findings refused\n", n);
}

}  // namespace
}  // namespace tightfit::pattern
