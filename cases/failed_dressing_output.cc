#include "cases/failed_dressing_output.h"

#include "io/vtu_writer.h"

#include <filesystem>
#include <stdexcept>

namespace tightfit {

std::string write_failed_dressing(const std::string& directory, const DressingSnapshot& state) {
  namespace fs = std::filesystem;
  try {
    fs::create_directories(directory);
    SurfaceVtu panels(state.positions_m, state.triangles);
    panels.add_point_scalar("seam gap", state.seam_gap_m);
    panels.add_point_scalar(
        "seam partner", std::vector<double>(state.seam_partner.begin(), state.seam_partner.end()));
    panels.add_point_scalar("distance to body", state.body_distance_m);
    panels.add_field_scalar("frame", state.frame);
    panels.add_field_scalar("body scale", state.body_scale);
    const std::string garment_file = (fs::path(directory) / "dressing_failed.vtu").string();
    panels.write(garment_file);
    const std::string body_file = (fs::path(directory) / "dressing_failed_body.vtu").string();
    SurfaceVtu(state.body.vertices_m, state.body.triangles).write(body_file);
    return "the state it stopped in is in " + garment_file + " and " + body_file;
  } catch (const std::exception& error) {
    return std::string("the state it stopped in could not be written: ") + error.what();
  }
}

void write_failed_dressing_to(const OutputSettings& output, DressingSettings& settings) {
  if (!output.write_files || output.rank != 0) return;
  const std::string directory = output.directory;
  settings.on_failure = [directory](const DressingSnapshot& state) {
    return write_failed_dressing(directory, state);
  };
}

}  // namespace tightfit
