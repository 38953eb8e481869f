// advise's vertex storage (issue 46): for a console path (gx), each material's pick tried with the
// storages a port ships (kStorages), each rendered and compared as the search measures a
// candidate, and costed in the console's bytes a frame (report/console_bytes.h: the path's
// budget of the scene under that variant, FIFO bytes as bench's console chart plots them). The
// storage advised for a material is the one of fewest FIFO bytes whose error on the material stays
// within the budget. A second step after the pick rather than a third axis of the grid: the
// storage changes bytes and the mesh's values, not the TEV program the pick was chosen for, and
// it keeps the search's renders at (picks x storages), not (grid x storages).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "metrics/compare.h"
#include "paths/path.h"
#include "report/console_bytes.h"
#include "scene/scene.h"

namespace lt::advise {

// The storages tried, the first the F32 direct stream (the path's default). Each is appended to
// the pick's variant (docs/advise.md): positions and texture coordinates s16 with the fractional
// bits the mesh's bounds allow, normals s8, colours RGB565; then the same indexed, stripped, in
// display lists.
inline constexpr const char* kStorages[] = {"", "vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto",
                                            "vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto:draw=list"};

struct StorageOption {
  std::string storage;  // a kStorages entry ("" F32 direct)
  std::string variant;  // the pick's variant with it
  std::string failed;   // why it was not measured (the mesh does not fit it); empty when it was
  ConsoleBytes bytes;   // the frame's, from the path's budget
  ErrorStats error;     // the material's, rendered
  std::size_t non_finite = 0;
};

struct StorageAdvice {
  std::vector<StorageOption> options;  // kStorages' order
  std::optional<std::size_t> pick;     // fewest FIFO bytes within the budget
};

struct Advice;

// Fills each material's `storage` (MaterialAdvice) that has a pick, when the path is a console's
// (writes a FIFO log); renders each distinct (pick, storage) once in a session of its own.
void add_storage_advice(Advice& a, const Scene& scene, const PathInfo& path,
                        const PathOptions& options, const std::string& profile);

}  // namespace lt::advise
