#include "io/vtu_share.h"

#include <filesystem>
#include <stdexcept>
#include <vector>

namespace tightfit {

TriangleBlock triangle_block(std::size_t n_triangles, int piece, int n_pieces) {
  if (n_pieces < 1 || piece < 0 || piece >= n_pieces)
    throw std::invalid_argument("VTU output: piece " + std::to_string(piece) + " of " +
                                std::to_string(n_pieces) + " does not exist");
  const auto boundary = [&](int p) {
    return n_triangles * static_cast<std::size_t>(p) / static_cast<std::size_t>(n_pieces);
  };
  return {boundary(piece), boundary(piece + 1)};
}

std::string write_vtu_share(const SurfaceVtu& surface, const std::string& directory,
                            const std::string& stem, int writer, int n_writers) {
  const auto path = [&](const std::string& name) {
    return (std::filesystem::path(directory) / name).string();
  };
  if (n_writers == 1) {
    surface.write(path(stem + ".vtu"));
    return stem + ".vtu";
  }
  const auto piece_name = [&](int p) { return stem + "_" + std::to_string(p) + ".vtu"; };
  const TriangleBlock block = triangle_block(surface.n_triangles(), writer, n_writers);
  surface.piece(block.first, block.end).write(path(piece_name(writer)));
  if (writer == 0) {
    std::vector<std::string> pieces;
    for (int p = 0; p < n_writers; ++p) pieces.push_back(piece_name(p));
    surface.write_pvtu_header(path(stem + ".pvtu"), pieces);
  }
  return stem + ".pvtu";
}

}  // namespace tightfit
