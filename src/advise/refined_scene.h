// What `advise -o DIR` writes of a mesh refinement (docs/advise.md, "Mesh density"): each refined
// object's mesh, and a scene that draws them, so that the refined result can be rendered,
// compared and benched like any scene.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "advise/advise.h"

namespace lt::advise {

struct RefinedFiles {
  std::vector<std::string> written;  // file names in the directory
  std::string not_written;           // why no scene was written (empty when one was)
};

// For every material whose refinement holds the budget, writes into `staging` each of its
// objects' refined meshes as MATERIAL_objectN.ply (N: the object's index in the scene; world
// space, as the scene holds them: write_triangle_mesh) and, once, `refined.json`: the scene
// file with those objects' "mesh" replaced by the written files and their "transform" dropped,
// and every other file the scene names (meshes, glTF files, maps, ramps) given relative to
// `final_dir`, where the staging directory ends up. A glTF scene file, or a refined object that
// a glTF file brought, has no "mesh" key to replace: the meshes are written and the scene is
// not (`not_written` says why).
RefinedFiles write_refined_scene(const Advice& a, const std::filesystem::path& staging,
                                 const std::filesystem::path& final_dir);

}  // namespace lt::advise
