// A path is one way of rendering a scene: the reference (the ground truth), flat (the timing
// baseline) and the ports (glsl, arbfp, combiners, half, gx). Each lives in its own folder under
// paths/ behind this interface: its PathInfo says what the path is, takes and refuses, parses its
// variants, counts its budget, builds a Path, which renders one scene, and (`ltrender export`)
// writes its programs in its export_formats for a target that is not ltrender: the command
// parses the options into an ExportRequest, the path refuses what its format does not take
// (export_variant) and returns the file (export_scene). Adding a path touches its folder and
// registry.cpp; the commands name none.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>  // std::function, std::reference_wrapper
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "budget/report.h"
#include "gl/context.h"
#include "gl/scene_geometry.h"
#include "image/image.h"
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
// geometry (matrices loaded) and the options (the variant goes to PathInfo::create).
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

struct ErrorStats;  // metrics/compare.h

// `ltrender export PATH SCENE --format F -o FILE`: one format a path writes its programs in.
struct ExportFormat {
  std::string name;       // as given to --format: "c"
  std::string extension;  // of the file it writes: ".c"
  std::string summary;    // one line, for --help
};

// What `export` was given besides the path and the output; the path refuses (export_variant)
// the options its format does not take before the scene is read.
struct ExportRequest {
  std::size_t format = 0;     // index into the path's export_formats
  std::string scene_file;     // as given: for messages and the file's comments
  std::string variant;        // as given; "" = the default
  std::string program_file;   // --program: drawn instead of the generated programs
  int width = 0, height = 0;  // --width, --height; 0: the scene's
  int frames = 1;             // --frames N: the first N frames of the camera path
  std::string light_range;    // --light-range D; "": not given
};

// What the command hands export_scene once the scene is read.
struct ExportInput {
  const Scene& scene;
  std::string variant;        // as export_variant returned it
  std::vector<Scene> frames;  // --frames N > 1: the scene on frames 0..N-1 of the camera path
  // The covered error of the path's variant against the reference at the scene's size (the
  // evaluate step, render/evaluate.h, which is above paths/), measured when called.
  std::function<ErrorStats()> error;
};

// What a path is to the bench and the goldens: the ground truth every error is against, the
// timing baseline every ratio is against, or a port being judged.
enum class PathRole { GroundTruth, Baseline, Port };

// What a path is, takes and refuses, and what builds it: one class per path (its folder's
// *_path.cpp), one instance in the registry. The description is data its constructor sets; the
// behaviour is the virtual functions below. A path with variant axes derives TypedPathInfo (its
// variant parsed once into a typed value), one with only listed names ListedPathInfo; one with a
// single variant and nothing to type is a SingleVariantInfo.
class PathInfo {
 public:
  virtual ~PathInfo() = default;

  std::string name;
  std::string summary;
  std::vector<VariantInfo> variants;  // the first is the default; bench runs each of them
  PathRole role = PathRole::Port;
  // Whether the path takes PathOptions::program_file, PathOptions::profile.
  bool takes_program_file = false;
  bool takes_profile = false;
  // The profiles budget() takes, its default first (`budget --profile` gives each named profile
  // to the path that has it); empty: the path counts nothing and has no budget().
  std::vector<std::string> budget_profiles;
  // `ltrender budget FILE`: a program file of this path's kind, recognised by its extension or,
  // failing that, by its text (reads_program_text); see budget_file().
  std::vector<std::string> program_extensions;
  // Whether fifo_log() is there (paths that model a console).
  bool writes_fifo_log = false;
  // `ltrender export NAME`: what the path's exports are for ("libogc C for the Wii / GameCube")
  // and their formats, the default first; none: the path exports nothing.
  std::string export_target;
  std::vector<ExportFormat> export_formats;

  // Builds the path for one scene; `variant` as resolve_variant returned it.
  virtual std::unique_ptr<Path> create(const PathContext& ctx,
                                       const std::string& variant) const = 0;
  // The canonical name of `variant`, throwing InputError("--variant", ...) naming the valid
  // values. Default: one of the listed names, as given.
  virtual std::string parse_variant(const std::string& variant) const;
  // Why `variant` cannot be exact for this scene (empty when it can): `render` refuses it with
  // this message, bench and the tests skip it and say why.
  virtual std::string refusal(const Scene& scene, const std::string& variant) const;
  // `ltrender budget SCENE --path NAME`: counts what the path builds for the scene (under a
  // variant, "" = the default) against one of budget_profiles (empty: the default) into the one
  // budget report (budget/report.h), which the command prints. The path owns its counter
  // and profiles; the command names no path.
  virtual budget::Report budget(const Scene& scene, const std::string& variant,
                                const std::string& profile) const;
  // `ltrender budget FILE`: a program file of this path's kind, counted against a profile by
  // the budget (src/budget/ reads and counts every program language; the path only names it).
  virtual budget::Report budget_file(const std::string& file, const std::string& profile) const;
  // Whether `text` (a file's, whose extension no path claims) is a program of this path's kind.
  // Default: no (a path whose files are known by their text asks the budget's reader).
  virtual bool reads_program_text(const std::string& text) const;
  // `export --format dff` and `render --via dolphin`: one frame as a Dolphin FIFO log (the bytes
  // of a .dff file) encoded from exactly the state the path's emulator runs, for an
  // implementation that is not ltrender's to play.
  virtual std::vector<std::uint8_t> fifo_log(const Scene& scene, const std::string& variant,
                                             const PathOptions& options, int width,
                                             int height) const;
  // `ltrender export`, before the scene is read: refuses (InputError) what `request` gives that
  // its format does not take and returns the variant to export, resolved. Default: the variant
  // alone, every other option refused.
  virtual std::string export_variant(const ExportRequest& request) const;
  // The bytes of the exported file, which the command writes.
  virtual std::string export_scene(const ExportRequest& request, const ExportInput& input) const;
};

// A path whose variant is a typed value V: the string is parsed once at each entry point and
// the path's own functions take V. parse throws InputError("--variant", text, ...) naming the
// valid values; name_of gives the canonical spelling.
template <class V>
class TypedPathInfo : public PathInfo {
 public:
  virtual V parse(const std::string& variant) const = 0;
  virtual std::string name_of(const V& variant) const = 0;
  virtual std::unique_ptr<Path> build(const PathContext& ctx, const V& variant) const = 0;
  virtual std::string refuse(const Scene&, const V&) const { return ""; }

  std::unique_ptr<Path> create(const PathContext& ctx, const std::string& variant) const final {
    return build(ctx, parse(variant));
  }
  std::string parse_variant(const std::string& variant) const final {
    return name_of(parse(variant));
  }
  std::string refusal(const Scene& scene, const std::string& variant) const final {
    return refuse(scene, parse(variant));
  }
};

// One listed variant and its typed value.
template <class V>
struct ListedVariant {
  VariantInfo info;
  V value;
};

// Throws InputError("--variant", requested, "path PATH has no such variant (valid: ...)").
[[noreturn]] void throw_unknown_variant(const std::string& path,
                                        const std::vector<VariantInfo>& variants,
                                        const std::string& requested);

// The value of the listed variant named `text`; throws as throw_unknown_variant otherwise.
template <class V>
const V& find_listed(const std::string& path, const std::vector<ListedVariant<V>>& listed,
                     const std::string& text) {
  for (const ListedVariant<V>& l : listed) {
    if (l.info.name == text) return l.value;
  }
  std::vector<VariantInfo> infos;
  for (const ListedVariant<V>& l : listed) infos.push_back(l.info);
  throw_unknown_variant(path, infos, text);
}

// A path whose variants are the listed names alone, each naming a value of V.
template <class V>
class ListedPathInfo : public TypedPathInfo<V> {
 public:
  ListedPathInfo(std::string path_name, std::string path_summary,
                 std::vector<ListedVariant<V>> listed)
      : listed_(std::move(listed)) {
    this->name = std::move(path_name);
    this->summary = std::move(path_summary);
    for (const ListedVariant<V>& l : listed_) this->variants.push_back(l.info);
  }
  V parse(const std::string& variant) const override {
    return find_listed(this->name, listed_, variant);
  }
  std::string name_of(const V& variant) const override {
    for (const ListedVariant<V>& l : listed_) {
      if (l.value == variant) return l.info.name;
    }
    return this->variants.front().name;  // unreachable: every value is listed
  }

 private:
  std::vector<ListedVariant<V>> listed_;
};

// A path with one variant and nothing to type (flat, the reference): P built from the context.
template <class P>
class SingleVariantInfo final : public PathInfo {
 public:
  SingleVariantInfo(std::string path_name, std::string path_summary, VariantInfo variant,
                    PathRole path_role) {
    name = std::move(path_name);
    summary = std::move(path_summary);
    variants = {std::move(variant)};
    role = path_role;
  }
  std::unique_ptr<Path> create(const PathContext& ctx, const std::string&) const override {
    return std::make_unique<P>(ctx);
  }
};

// Every path, in the order the report lists them.
// (A range of `const PathInfo&`: `for (const PathInfo& p : all_paths())`.)
const std::vector<std::reference_wrapper<const PathInfo>>& all_paths();
// Throws InputError(file_for_errors, "--path", ...) listing the valid names.
const PathInfo& find_path(const std::string& name);
// The one path of a role that has exactly one (GroundTruth, Baseline).
const PathInfo& path_with_role(PathRole role);
// The path `ltrender budget SCENE` counts without --path: the first in report order that has a
// budget (arbfp, the SM2-class programs a shader budget is usually about).
const PathInfo& default_budget_path();
// The variant to use: `requested` if the path has it, its default if empty; throws InputError
// listing the valid variants otherwise.
std::string resolve_variant(const PathInfo& path, const std::string& requested);

}  // namespace lt
