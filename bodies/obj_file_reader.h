// tightfit's reader of OBJ body files, one pass through the file. It reads the vertices ("v",
// single precision, as VTK's reader did) and the faces ("f", each corner's vertex index) in
// the file's order, and checks each line as it reads it: VTK's reader, found by
// fuzz_body_mesh_obj, took "v 1 x 0" or "v 0 0" without a word, "nan" and "inf" for 0, and
// followed a face's texture and normal indices past the file's "vt" and "vn" lines into a null
// pointer.
#pragma once

#include "bodies/polygon_mesh.h"

#include <string>

namespace tightfit {

// The OBJ file's vertices and faces. Texture coordinates and normals are not read, only checked
// to name lines the file has, so a vertex keeps one index whatever its texture coordinates (VTK's
// reader gave every face corner a vertex of its own as soon as the file had "vt" or "vn" lines,
// which left no two faces sharing an edge). Throws BodyMeshError naming the file and the line:
// a vertex without three finite coordinates, a face corner naming no line the file has (indices
// count from 1; relative ones are not read) or ending with '/', a face of other than 3 or 4
// corners, a polyline ("l": a surface of polygons only), more faces than memory can hold
// (estimated from the file's size).
PolygonMesh read_obj_file(const std::string& path);

}  // namespace tightfit
