// `ltrender bake MESH -o OUT.ply`: local thickness (inverted-normal AO) into vertex colours;
// `ltrender bake MESH --texture WxH -o MAP.png|.exr`: the same into a thickness map in UV space.
// The baking itself is lt::bake (src/bake/thickness_baker.h, src/bake/uv_baker.h); this file
// maps options, prints warnings, the progress bar and the rate, and writes the result.
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "bake/thickness_baker.h"
#include "bake/uv_baker.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/file_name.h"
#include "core/fs.h"
#include "core/stopwatch.h"
#include "image/image.h"
#include "mesh/mesh_io.h"

namespace lt::cli {

namespace {

struct BakeOptions {
  std::string mesh;
  std::string out;
  int rays = 256;
  std::optional<double> max_distance;
  std::optional<double> max_distance_relative;
  double min = 0.0;
  double max = 1.0;
  std::string tint = "1,1,1";
  std::uint64_t seed = 0;
  std::string distribution = "cosine";
  std::string estimator = "occlusion";
  std::string sampler = "stratified";
  int smooth = 0;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  bool float_colors = false;
  std::string texture;  // "WxH": bake a map in UV space instead of vertex colours
  int margin = 2;
};

struct TextureSize {
  int width = 0, height = 0;
};

// "WxH", each in [1, 16384] and the product within the image cap.
TextureSize parse_texture_size(const std::string& text) {
  TextureSize size;
  const auto x = text.find_first_of("xX");
  auto number = [&](const std::string& part, int& out) {
    if (part.empty() || part.size() > 5 ||
        !std::all_of(part.begin(), part.end(), [](unsigned char c) { return std::isdigit(c); })) {
      return false;
    }
    out = std::stoi(part);
    return out >= 1 && out <= 16384;
  };
  if (x == std::string::npos || !number(text.substr(0, x), size.width) ||
      !number(text.substr(x + 1), size.height)) {
    throw InputError(
        "--texture", "",
        "expected WxH with W and H in [1, 16384] (e.g. 1024x1024), got '" + text + "'");
  }
  if (static_cast<long long>(size.width) * size.height > kMaxImagePixels) {
    throw InputError("--texture", "",
                     text + " has more than " + std::to_string(kMaxImagePixels) + " texels");
  }
  return size;
}

// "R,G,B" with three numbers (validated against [0, 1] by bake::validate).
glm::dvec3 parse_tint(const std::string& text) {
  glm::dvec3 rgb(0.0);
  std::istringstream in(text);
  std::string part;
  int n = 0;
  while (std::getline(in, part, ',')) {
    if (n == 3)
      throw InputError("--tint", "", "expected R,G,B (three numbers), got '" + text + "'");
    try {
      std::size_t used = 0;
      rgb[n] = std::stod(part, &used);
      while (used < part.size() && std::isspace(static_cast<unsigned char>(part[used]))) ++used;
      if (used != part.size()) throw std::invalid_argument(part);
    } catch (const std::exception&) {
      throw InputError("--tint", "", "'" + part + "' is not a number (expected R,G,B)");
    }
    ++n;
  }
  if (n != 3) throw InputError("--tint", "", "expected R,G,B (three numbers), got '" + text + "'");
  return rgb;
}

// The value of an option that names one of two choices: `value_a` for `a`, `value_b` for `b`.
template <class T>
T one_of(const std::string& text, const char* option, const char* a, T value_a, const char* b,
         T value_b) {
  if (text == a) return value_a;
  if (text == b) return value_b;
  throw InputError(option, "", std::string("must be ") + a + " or " + b + ", got '" + text + "'");
}

bake::BakeSettings settings_from(const BakeOptions& o) {
  bake::BakeSettings s;
  s.rays = o.rays;
  if (o.max_distance && o.max_distance_relative) {
    throw InputError("--max-distance", "", "give either --max-distance or --max-distance-relative");
  }
  s.max_distance = o.max_distance;
  if (o.max_distance_relative) s.max_distance_relative = *o.max_distance_relative;
  s.distribution = one_of(o.distribution, "--distribution", "cosine", bake::Distribution::Cosine,
                          "uniform", bake::Distribution::Uniform);
  s.estimator = one_of(o.estimator, "--estimator", "occlusion", bake::Estimator::Occlusion,
                       "distance", bake::Estimator::Distance);
  s.sampler = one_of(o.sampler, "--sampler", "stratified", bake::Sampler::Stratified, "random",
                     bake::Sampler::Random);
  s.seed = o.seed;
  s.threads = o.threads;
  bake::validate(s);
  return s;
}

// A one-line bar redrawn in place; only when stderr is a terminal, so logs and pipes stay clean.
class ProgressBar {
 public:
  ProgressBar() : enabled_(::isatty(STDERR_FILENO) == 1) {}

  void update(std::size_t done, std::size_t total) {
    if (!enabled_ || total == 0) return;
    const int percent = static_cast<int>(100 * done / total);
    if (percent == last_percent_) return;  // redraw at most 101 times
    last_percent_ = percent;
    constexpr int kWidth = 40;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\rbake [%s%s] %3d%%",
                 std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(kWidth - filled), ' ').c_str(), percent);
    std::fflush(stderr);
  }

  void finish() {
    if (enabled_ && last_percent_ >= 0) std::fprintf(stderr, "\r\033[K");  // erase the bar
  }

 private:
  bool enabled_;
  int last_percent_ = -1;
};

void warn(const std::string& file, const std::string& what) {
  std::fprintf(stderr, "ltrender: warning: %s: %s\n", file.c_str(), what.c_str());
}

void warn_about_edges(const std::string& mesh, const bake::EdgeReport& edges) {
  if (edges.boundary_edges > 0 || edges.non_manifold_edges > 0) {
    warn(mesh, "not a closed manifold: " + std::to_string(edges.boundary_edges) +
                   " boundary edges, " + std::to_string(edges.non_manifold_edges) +
                   " non-manifold edges; rays leaving through an opening count as unoccluded "
                   "(thick)");
  }
}

double mrays_per_second(std::uint64_t rays, double seconds) {
  return seconds > 0.0 ? static_cast<double>(rays) / seconds / 1e6 : 0.0;
}

int run_vertex_bake(const BakeOptions& o, const bake::BakeSettings& settings,
                    const bake::ColorMap& map) {
  if (lower_extension(o.out) != ".ply") {
    throw InputError(o.out, "", "bake writes PLY (vertex colours): the output must end in .ply");
  }
  ensure_not_an_input(o.out, {o.mesh});

  LoadedMesh loaded = read_mesh(o.mesh);
  for (const auto* list : {&loaded.notes, &loaded.warnings})
    for (const auto& w : *list) warn(o.mesh, w);

  ProgressBar bar;
  const auto start = SteadyClock::now();
  const bake::MeshBakeReport report =
      bake::bake_mesh(loaded.mesh, settings, map, o.smooth,
                      [&bar](std::size_t done, std::size_t total) { bar.update(done, total); });
  const double seconds = seconds_since(start);
  bar.finish();

  warn_about_edges(o.mesh, report.edges);
  if (report.result.vertices_without_normal > 0) {
    warn(o.mesh, std::to_string(report.result.vertices_without_normal) +
                     " vertices have no normal and no non-degenerate face: baked as unoccluded "
                     "(translucency = --min)");
  }

  // Keep what the file had (binary or ASCII, normals, UVs, ...) and add the colours. Alpha is
  // dropped: the thickness is rgb. 8-bit colours unless --float-colors (OpenMesh rounds to
  // nearest).
  OpenMesh::IO::Options options = loaded.read_options;
  options += OpenMesh::IO::Options::VertexColor;
  options -= OpenMesh::IO::Options::ColorAlpha;
  if (o.float_colors) {
    options += OpenMesh::IO::Options::ColorFloat;
  } else {
    options -= OpenMesh::IO::Options::ColorFloat;
  }
  // Everything else the input had (a PLY's quality, ...) goes through unchanged.
  write_mesh(o.out, loaded.mesh, options, loaded.extra_vertex_properties);

  const auto& r = report.result;
  std::printf(
      "ltrender: bake: %zu vertices, %llu rays (%d per vertex, D = %g), %.3f s (rays %.3f s), "
      "%.2f Mrays/s, %d threads -> %s\n",
      r.occlusion.size(), static_cast<unsigned long long>(r.rays_traced), settings.rays,
      r.max_distance, seconds, r.trace_seconds, mrays_per_second(r.rays_traced, r.trace_seconds),
      r.threads, o.out.c_str());
  return 0;
}

int run_texture_bake(const BakeOptions& o, const bake::BakeSettings& settings,
                     const bake::ColorMap& map) {
  const TextureSize size = parse_texture_size(o.texture);
  if (o.margin < 0 || o.margin > 4096) throw InputError("--margin", "", "must be in [0, 4096]");
  if (o.smooth != 0) {
    throw InputError("--smooth", "", "smooths vertex colours; a --texture bake has no vertices");
  }
  if (o.float_colors) {
    throw InputError("--float-colors", "",
                     "is for vertex colours; write the map as .exr for float texels");
  }
  check_output_extension(o.out);
  ensure_not_an_input(o.out, {o.mesh});

  const LoadedMesh loaded = read_mesh(o.mesh);
  for (const auto* list : {&loaded.notes, &loaded.warnings})
    for (const auto& w : *list) warn(o.mesh, w);
  const TriangleMesh mesh = to_triangle_mesh(loaded);
  if (mesh.uvs.empty()) {
    throw InputError(o.mesh, "",
                     "has no texture coordinates (UVs): --texture bakes in UV space (bake without "
                     "--texture for vertex colours)");
  }

  ProgressBar bar;
  const auto start = SteadyClock::now();
  const bake::UvBakeResult r = bake::bake_uv(
      mesh.positions, mesh.normals, mesh.uvs, mesh.triangles, settings, size.width, size.height,
      o.margin, [&bar](std::size_t done, std::size_t total) { bar.update(done, total); });
  const double seconds = seconds_since(start);
  bar.finish();

  warn_about_edges(o.mesh, bake::count_problem_edges(mesh.positions, mesh.triangles));
  if (r.overlapping > 0) {
    warn(o.mesh, std::to_string(r.overlapping) +
                     " texels are covered by two or more triangles (overlapping UVs): each "
                     "keeps the thickness of the first triangle");
  }
  if (r.texels_without_normal > 0) {
    warn(o.mesh, std::to_string(r.texels_without_normal) +
                     " texels lie on triangles without normal or area: baked as unoccluded "
                     "(translucency = --min)");
  }
  write_image(o.out, bake::thickness_image(r, map));

  std::printf(
      "ltrender: bake: %dx%d texels, %zu covered + %zu margin, %llu rays (%d per texel, D = %g), "
      "%.3f s (rays %.3f s), %.2f Mrays/s, %d threads -> %s\n",
      r.width, r.height, r.covered, r.margin, static_cast<unsigned long long>(r.rays_traced),
      settings.rays, r.max_distance, seconds, r.trace_seconds,
      mrays_per_second(r.rays_traced, r.trace_seconds), r.threads, o.out.c_str());
  return 0;
}

int run_bake(const BakeOptions& o) {
  // Every option first, so a typo fails before a long bake.
  const bake::BakeSettings settings = settings_from(o);
  bake::ColorMap map;
  map.min = o.min;
  map.max = o.max;
  map.tint = parse_tint(o.tint);
  bake::validate(map);
  if (o.smooth < 0 || o.smooth > 100000) throw InputError("--smooth", "", "must be in [0, 100000]");
  return o.texture.empty() ? run_vertex_bake(o, settings, map) : run_texture_bake(o, settings, map);
}

}  // namespace

Action add_bake(CLI::App& app) {
  auto* sub = app.add_subcommand(
      "bake",
      "Bake local thickness (ambient occlusion with flipped normals) into per-vertex colours: "
      "translucency = lerp(--min, --max, occlusion) * --tint, thin parts bright");
  auto o = std::make_shared<BakeOptions>();
  sub->add_option("MESH", o->mesh, "Input mesh (PLY, OFF, OBJ, STL, OM)")->required();
  sub->add_option("-o,--output", o->out,
                  "Output PLY with vertex colours (or, with --texture, a PNG or EXR map)")
      ->required();
  sub->add_option("--rays", o->rays, "Rays per vertex")->capture_default_str();
  sub->add_option("--max-distance", o->max_distance, "Max ray distance in scene units");
  sub->add_option("--max-distance-relative", o->max_distance_relative,
                  "Max ray distance as a fraction of the bounding-box diagonal (default 0.25)");
  sub->add_option("--min", o->min, "Translucency where no ray hits (thick; addendum: 0.5)")
      ->capture_default_str();
  sub->add_option("--max", o->max, "Translucency where every ray hits (thin)")
      ->capture_default_str();
  sub->add_option("--tint", o->tint, "Colour multiplied in, R,G,B in [0,1] (e.g. 1,0.2,0.1)")
      ->capture_default_str();
  sub->add_option("--seed", o->seed, "Random seed; same seed, same output on any thread count")
      ->capture_default_str();
  sub->add_option("--distribution", o->distribution, "cosine or uniform")->capture_default_str();
  sub->add_option("--estimator", o->estimator,
                  "occlusion (fraction of rays hitting) or distance (1 - mean hit distance / D)")
      ->capture_default_str();
  sub->add_option("--sampler", o->sampler,
                  "stratified (rotated Hammersley per vertex) or random (independent rays)")
      ->capture_default_str();
  sub->add_option("--smooth", o->smooth, "Neighbour-averaging iterations after baking")
      ->capture_default_str();
  sub->add_option("--threads", o->threads, "Worker threads (0: all cores)")->capture_default_str();
  sub->add_flag("--float-colors", o->float_colors, "Write float colours instead of 8-bit");
  sub->add_option("--texture", o->texture,
                  "WxH: bake a thickness map in UV space (v = 0 at the bottom row) into -o "
                  "MAP.png (8-bit, linear) or MAP.exr (float); the mesh needs UVs");
  sub->add_option("--margin", o->margin,
                  "With --texture: texels the map is grown by across seams (Blender's bake "
                  "margin)")
      ->capture_default_str();
  return [o]() -> int { return run_bake(*o); };
}

}  // namespace lt::cli
