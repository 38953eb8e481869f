// `ltrender meshgen OUTDIR`: writes the procedural meshes of mesh/meshgen.h (the committed
// meshes/ directory is this command's output), or one of them (--sphere, --teapot, --uvsphere).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "cli/commands.h"
#include "core/error.h"
#include "mesh/mesh_io.h"
#include "mesh/meshgen.h"

namespace lt::cli {

namespace {

std::string human_size(std::uintmax_t bytes) {
  char buf[32];
  if (bytes < 1024) {
    std::snprintf(buf, sizeof buf, "%ju B", bytes);
  } else {
    std::snprintf(buf, sizeof buf, "%.1f KiB", static_cast<double>(bytes) / 1024.0);
  }
  return buf;
}

// Creates `dir` if needed; an existing non-directory is an error rather than something to
// replace.
void ensure_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec)) {
    throw InputError(dir.string(), "", "exists and is not a directory");
  }
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string(), "", "cannot create directory: " + ec.message());
}

}  // namespace

Action add_meshgen(CLI::App& app) {
  auto out_dir = std::make_shared<std::string>();
  auto* sub = app.add_subcommand(
      "meshgen", "Write the procedural test meshes (binary PLY with normals) into OUTDIR");
  sub->add_option("OUTDIR", *out_dir, "Output directory (created if missing)")->required();
  auto sphere = std::make_shared<int>(-1);
  sub->add_option("--sphere", *sphere,
                  "Write only sphere_sS.ply, an icosphere of S subdivisions (7: 163842 vertices, "
                  "the bake-rate case of issue 3)")
      ->check(CLI::Range(0, 8));
  auto teapot = std::make_shared<int>(0);
  sub->add_option("--teapot", *teapot,
                  "Write only teapot.ply, the Utah teapot with N x N cells per Bezier patch "
                  "(the set's teapot.ply has " +
                      std::to_string(meshgen::kDefaultTeapotSubdivisions) + ")")
      ->check(CLI::Range(1, 256));
  auto uvsphere = std::make_shared<int>(0);
  sub->add_option("--uvsphere", *uvsphere,
                  "Write only uvsphere.ply, a UV sphere of R latitude rings and 2R segments (the "
                  "set's has 32)")
      ->check(CLI::Range(2, 4096));
  sub->get_option("--sphere")->excludes("--teapot")->excludes("--uvsphere");
  sub->get_option("--teapot")->excludes("--uvsphere");
  return [out_dir, sphere, teapot, uvsphere]() -> int {
    const std::filesystem::path root(*out_dir);
    ensure_directory(root);
    std::uintmax_t total = 0;
    std::vector<meshgen::NamedMesh> set;
    if (*sphere >= 0) {
      set.push_back(
          {"sphere_s" + std::to_string(*sphere) + ".ply", meshgen::icosphere(1.0, *sphere)});
    } else if (*teapot > 0) {
      set.push_back({"teapot.ply", meshgen::teapot(*teapot), true});
    } else if (*uvsphere > 0) {
      set.push_back({"uvsphere.ply", meshgen::uv_sphere(1.0, *uvsphere), true});
    } else {
      set = meshgen::standard_set();
    }
    for (const auto& named : set) {
      const std::filesystem::path path = root / named.path;
      ensure_directory(path.parent_path());
      write_mesh(path, named.mesh, meshgen::write_options(named));
      std::error_code ec;
      const auto size = std::filesystem::file_size(path, ec);
      total += ec ? 0 : size;
      std::printf("wrote %s: %zu vertices, %zu faces, %s\n", path.string().c_str(),
                  named.mesh.n_vertices(), named.mesh.n_faces(), human_size(size).c_str());
    }
    std::printf("meshgen: %s in total\n", human_size(total).c_str());
    return 0;
  };
}

}  // namespace lt::cli
