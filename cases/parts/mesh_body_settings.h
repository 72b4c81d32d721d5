// The Body/Mesh subsection, shared by Body/Kind = mesh and Body/Kind = morph (whose base shape
// it gives): the file and how it is brought into tightfit's frame (docs/bodies.md).
#pragma once

#include "bodies/mesh_body.h"
#include "cases/parameter_tree.h"

#include <string>

namespace tightfit {

struct MeshBodySettings {
  std::string file;
  MeshBodyOptions options;
};

// Declares the entries of the current subsection (Body/Mesh).
void declare_mesh_body_settings(ParameterTree& prm);
// Reads them; throws std::invalid_argument for an empty file name.
MeshBodySettings parse_mesh_body_settings(ParameterTree& prm);

}  // namespace tightfit
