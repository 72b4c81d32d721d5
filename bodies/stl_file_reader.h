// tightfit's reader of STL body files, ASCII or binary, one pass through the file. It reads what
// VTK's vtkSTLReader did: single-precision coordinates (ASCII ones parsed in double precision
// and then rounded to single, as VTK rounded them), the facets' repeated vertices welded where
// their single-precision coordinates are equal (0 and -0 alike), numbered in the order they
// first appear, and a facet that welding collapses (two corners on one vertex) dropped. It
// checks what it reads as it reads it: a binary header announcing more facets than the file
// holds or than memory can take (VTK allocated for the count before reading a facet: found by
// fuzz_body_mesh_stl), an ASCII line out of STL's order or a vertex without three finite
// coordinates, named by its line.
#pragma once

#include "bodies/polygon_mesh.h"

#include <string>

namespace tightfit {

// The STL file's welded vertices and triangles. A file of printable text (tabs, line feeds
// and carriage returns allowed; not a form feed) is ASCII, any other binary: an 80-byte header,
// a facet count and 50 bytes per facet, every whole facet after the header read (many writers
// leave the count wrong) and a remainder shorter than a facet skipped, as VTK did. Throws
// BodyMeshError naming the file: a binary file shorter than its header, or announcing more
// facets than it holds; more facets than memory can hold (binary: the count or the file's
// facets; ASCII: estimated from the file's size); in ASCII naming the line, a keyword out of
// order ("solid", then facets "facet" / "outer loop" / three "vertex" lines / "endloop" /
// "endfacet", then "endsolid"; "color" lines between facets; keywords in any case), a vertex
// line without exactly three numbers or with one that is not finite in single precision, the
// file ending inside a solid.
PolygonMesh read_stl_file(const std::string& path);

}  // namespace tightfit
