// A surface written by several processes (MPI ranks) that each hold all of it.
//
// With one writer the surface is a plain .vtu. With n writers each writes one piece (a
// contiguous block of the triangles, with the points they use) and the first writer also
// writes the .pvtu header that makes the pieces one dataset in ParaView. No communication is
// needed: every writer knows every piece's name. MPI stays out of io/: the caller says which
// writer it is.
#pragma once

#include "io/vtu_writer.h"

#include <cstddef>
#include <string>

namespace tightfit {

struct TriangleBlock {
  std::size_t first = 0;
  std::size_t end = 0;  // one past the last
};

// The `piece`-th of `n_pieces` contiguous blocks that together cover [0, n_triangles), their
// sizes differing by at most one (std::invalid_argument unless 0 <= piece < n_pieces).
TriangleBlock triangle_block(std::size_t n_triangles, int piece, int n_pieces);

// Writes writer `writer`'s share (of `n_writers`) of `surface` into `directory`; `stem` is the
// file name without extension:
//   one writer:  <stem>.vtu;
//   n writers:   <stem>_<writer>.vtu, then on writer 0 <stem>.pvtu naming all n pieces.
// Returns the name (relative to `directory`) a .pvd collection lists: <stem>.vtu or
// <stem>.pvtu. Writer 0 returns once its own files are written; the other writers' pieces may
// land a moment later, so the .pvtu is complete once every writer has returned.
std::string write_vtu_share(const SurfaceVtu& surface, const std::string& directory,
                            const std::string& stem, int writer, int n_writers);

}  // namespace tightfit
