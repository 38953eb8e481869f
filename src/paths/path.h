// A path is one way of rendering a scene: the reference (the ground truth), flat (the timing
// baseline) and the ports (glsl, arbfp, combiners, half, gx). Each lives in its own folder under
// paths/ behind this interface: a PathInfo says what the path is, takes and refuses, and a Path
// renders one scene. Adding a path touches its folder and registry.cpp; the commands name none.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/scene_geometry.h"
#include "image/image.h"
#include "paths/budget/report.h"
#include "paths/frame_stats.h"
#include "scene/scene.h"

namespace lt {

// What the user gave beyond the scene and the variant (validated by the path that takes it).
struct PathOptions {
  std::string program_file;  // gx: a program file that replaces the generated programs
  // arbfp: a profile (ps_2_0 ...) the programs must fit; over it, lights go into more passes.
  std::string profile;
};

// What a path renders with: the scene, a current context at the output size, the uploaded
// geometry (matrices loaded), and the variant string the user picked (already validated).
struct PathContext {
  const Scene& scene;
  gl::Context& gl;
  gl::SceneGeometry& geometry;
  int width, height;
  PathOptions options = {};
};

// One built stage or program, for `ltrender info` and the budget checker.
struct BuiltStage {
  std::string name;    // e.g. "material marble: fragment program"
  std::string kind;    // "glsl-vertex", "glsl-fragment", "arb-vertex", "arb-fragment", "cpu", ...
  std::string source;  // the generated program text, if any
};

// What a path executes for one material, counted from its built programs (not timed): the bench
// multiplies it by the material's covered pixels and drawn vertices into the work axis, the cost
// figure that is the same on every machine (issue 11). Each path counts in its hardware's own
// operation: fragment ALU + TEX instructions, combiner stages, TEV stages, XF lights, CPU light
// evaluations. Summed over the passes the material is drawn in.
struct MaterialWork {
  double per_pixel = 0;   // operations a covered pixel of the material costs
  double per_vertex = 0;  // operations a vertex of the material costs
};

struct WorkModel {
  std::string pixel_operation, vertex_operation;  // what one operation is, for the report
  std::vector<MaterialWork> by_material;          // scene.materials order; empty: not counted
  std::string not_counted;                        // why, when by_material is empty
};

class Path {
 public:
  virtual ~Path() = default;
  // Renders one frame. Bench brackets it with glFinish; a CPU path finishes its work inside.
  virtual void frame() = 0;
  // The image of the last frame: linear float RGBA, top row first, alpha = coverage.
  virtual Image result() = 0;
  // What was built for this scene (programs, stages, textures).
  virtual std::vector<BuiltStage> stages() const = 0;
  // True when the output is float (the reference); false for 8-bit framebuffer paths.
  virtual bool float_output() const { return false; }
  // One line of what the built programs cost, for the bench table ("fragment 24 ALU + 2 TEX",
  // "3 stages, 1 unit, 2 passes"); empty where there is nothing to count.
  virtual std::string cost() const { return ""; }
  // Figures of the last frame a path can report (e.g. the reference's CPU shading time).
  virtual FrameStats frame_stats() const { return {}; }
  // The operations each material costs (see MaterialWork).
  virtual WorkModel work() const { return {{}, {}, {}, "this path counts no operations"}; }
};

// Which runs a variant is in: a full bench runs every variant; the quick one (./run.sh, bench
// --variants story) runs each path's default and its Story variants, those whose comparison
// with the default the docs tell (the LUT's width, texgen, the XF lobe, ...).
enum class VariantRun { Full, Story };

struct VariantInfo {
  std::string name;     // as given to --variant, e.g. "pow=exact"
  std::string summary;  // one line: what it trades
  VariantRun run = VariantRun::Full;
};

// What a path is to the bench and the goldens: the ground truth every error is against, the
// timing baseline every ratio is against, or a port being judged.
enum class PathRole { GroundTruth, Baseline, Port };

struct PathInfo {
  std::string name;
  std::string summary;
  std::vector<VariantInfo> variants;  // the first is the default; bench runs each of them
  std::function<std::unique_ptr<Path>(const PathContext&, const std::string& variant)> create;
  // A path whose variants are a grammar (gx: any LUT width) parses them here and returns the
  // canonical name, throwing InputError naming the valid values; without it only the listed
  // names are accepted.
  std::function<std::string(const std::string& variant)> parse_variant = {};
  // Why `variant` cannot be exact for this scene (empty when it can): `render` refuses it with
  // this message, bench and the tests skip it and say why.
  std::function<std::string(const Scene& scene, const std::string& variant)> refusal = {};
  // Whether the path takes PathOptions::program_file, PathOptions::profile.
  bool takes_program_file = false;
  bool takes_profile = false;
  PathRole role = PathRole::Port;
  // `ltrender budget SCENE --path NAME`: counts what the path builds for the scene (under a
  // variant, "" = the default) against one of its profiles (empty: the path's default) into the
  // one budget report (paths/budget/report.h), which the command prints. The path owns its
  // counter and profiles; the command names no path.
  std::function<budget::Report(const Scene& scene, const std::string& variant,
                               const std::string& profile)>
      budget = {};
  // The profiles the path's budget takes, its default first: `budget --profile` gives each
  // named profile to the path that has it.
  std::vector<std::string> budget_profiles = {};
  // `ltrender budget FILE`: a program file of this path's kind, recognised by its extension or,
  // failing that, by the first characters of its text (after white space).
  std::vector<std::string> program_extensions = {};
  std::vector<std::string> program_headers = {};
  std::function<budget::Report(const std::string& file, const std::string& profile)> budget_file =
      {};
  // `export --format dff` and `render --via dolphin`: one frame as a Dolphin FIFO log (the bytes
  // of a .dff file) encoded from exactly the state the path's emulator runs, for an
  // implementation that is not ltrender's to play. Empty for paths that model no console.
  std::function<std::vector<std::uint8_t>(const Scene& scene, const std::string& variant,
                                          const PathOptions& options, int width, int height)>
      fifo_log = {};
};

// Every path, in the order the report lists them.
const std::vector<PathInfo>& all_paths();
// Throws InputError(file_for_errors, "--path", ...) listing the valid names.
const PathInfo& find_path(const std::string& name);
// The one path of a role that has exactly one (GroundTruth, Baseline).
const PathInfo& path_with_role(PathRole role);
// The variant to use: `requested` if the path has it, its default if empty; throws InputError
// listing the valid variants otherwise.
std::string resolve_variant(const PathInfo& path, const std::string& requested);

}  // namespace lt
