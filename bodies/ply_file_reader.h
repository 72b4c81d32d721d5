// tightfit's reader of PLY body files, one pass through header and data. It reads what VTK's
// reader did (vertices x, y, z as single precision, faces from vertex_indices, in the file's
// order) and refuses what VTK's reader took on trust, found by fuzz_body_mesh_ply: a face
// naming a vertex past the vertex count (an out-of-bounds read in VTK), an ASCII line with
// fewer values than its element has properties, a file ending before its elements, a list
// count that allocates gigabytes, a property before any element. Headers VTK's reader could
// not read stay refused, so a file reads here if and only if it read there.
#pragma once

#include "bodies/polygon_mesh.h"

#include <string>

namespace tightfit {

// The PLY file's vertices and faces. Throws BodyMeshError naming the file and the header
// line, face or vertex at fault: a header that is not PLY's (unknown keyword or type, an
// element or property line short of words, a negative or repeated element, no vertex element
// with scalar x, y, z, no face element with a vertex_indices list), more faces than memory can
// hold, data ending before the elements the header announces (a line short of values in
// ASCII, too few bytes in binary), a face of other than 3 or 4 vertices or naming a vertex
// outside 0 .. vertices - 1, a coordinate that is not a finite number.
PolygonMesh read_ply_file(const std::string& path);

}  // namespace tightfit
