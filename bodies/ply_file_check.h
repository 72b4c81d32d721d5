// A PLY file read through once, header and data, before VTK's reader sees it. vtkPLYReader
// takes what the file says without checking it: a face naming a vertex past the vertex count
// (read out of bounds: a segfault in vtkAOSDataArrayTemplate::GetTuple, found by
// fuzz_body_mesh_ply), an ASCII line with fewer values than its element has properties (read
// past the line's words), a file ending before its elements, a list count that allocates
// gigabytes, a property before any element.
#pragma once

#include <string>

namespace tightfit {

// Throws BodyMeshError naming the file and the header line, face or vertex at fault: a header
// that is not PLY's (unknown keyword or type, an element or property line short of words, a
// negative or repeated element, no vertex element with scalar x, y, z, no face element with
// a vertex_indices list), more faces than memory can hold, data ending before the elements
// the header announces (a line short of values in ASCII, too few bytes in binary), a face of
// other than 3 or 4 vertices or naming a vertex outside 0 .. vertices - 1, a coordinate that
// is not a finite number.
void check_ply_file(const std::string& path);

}  // namespace tightfit
