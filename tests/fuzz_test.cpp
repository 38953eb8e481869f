// A bounded, seeded mutation run over every kind of file ltrender reads (issue 15): scenes,
// meshes, images and program files, each mutated from the project's own files. Every case must
// keep cli.md's contract: the reader either accepts the file, and then what comes out is usable
// (finite positions and unit normals, a render without NaN or Inf, pixels a comparison takes),
// or it refuses it with an InputError naming the file on one line. Nothing else may reach
// stderr: no library chatter (libpng, OpenMesh), only our own warnings. A few cases per kind also
// go through the real binary, where the exit code and the one final error line are checked.
//
// The cases are fixed by their seeds (the same mutations on every run and machine); the run is
// sharded so that ctest spreads it over the cores.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <sstream>

#include "core/error.h"
#include "image/image.h"
#include "load/load_scene.h"
#include "mesh/mesh_io.h"
#include "metrics/compare.h"
#include "paths/path.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt {
namespace {

enum class Kind { Scene, Mesh, Image, Program };

const char* name_of(Kind k) {
  switch (k) {
    case Kind::Scene:
      return "scene";
    case Kind::Mesh:
      return "mesh";
    case Kind::Image:
      return "image";
    case Kind::Program:
      return "program";
  }
  return "?";
}

constexpr int kShards = 4;
constexpr int kCasesPerShard = 25;  // 4 kinds x 4 shards x 25 = 400 in-process cases
constexpr int kCliCasesPerShard = 2;

struct Seed {
  std::string name, extension, bytes;
};

// Scene seeds name their meshes relative to the scene's folder; the mutated copy lives in a
// temporary folder, so the names become absolute first.
std::string with_absolute_meshes(const std::string& text, const fs::path& scene_dir) {
  static const std::regex mesh_key(R"re("mesh"\s*:\s*"([^"]+)")re");
  std::string out;
  auto begin = std::sregex_iterator(text.begin(), text.end(), mesh_key);
  std::size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    out += text.substr(last, static_cast<std::size_t>(it->position()) - last);
    out += "\"mesh\": \"" + fs::weakly_canonical(scene_dir / (*it)[1].str()).string() + "\"";
    last = static_cast<std::size_t>(it->position() + it->length());
  }
  return out + text.substr(last);
}

std::vector<Seed> seeds_of(Kind kind, const fs::path& scratch) {
  const fs::path src = test::source_dir();
  std::vector<Seed> seeds;
  auto add_folder = [&](const fs::path& dir, const std::vector<std::string>& extensions) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir)) {
      const auto ext = e.path().extension().string();
      if (std::find(extensions.begin(), extensions.end(), ext) != extensions.end())
        files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      std::string bytes = test::read_file(f);
      if (kind == Kind::Scene) bytes = with_absolute_meshes(bytes, f.parent_path());
      seeds.push_back({f.filename().string(), f.extension().string(), bytes});
    }
  };
  switch (kind) {
    case Kind::Scene:
      add_folder(src / "scenes", {".json"});
      add_folder(src / "scenes" / "hard", {".json"});
      break;
    case Kind::Mesh:
      // Small files only: a mutation of a 600 KB mesh costs as much as fifty small ones.
      add_folder(src / "tests" / "data" / "meshes" / "odd", {".ply", ".obj", ".off", ".stl"});
      add_folder(src / "tests" / "data" / "meshes" / "bad", {".ply", ".obj", ".off", ".stl"});
      add_folder(src / "meshes", {".ply"});
      seeds.erase(std::remove_if(seeds.begin(), seeds.end(),
                                 [](const Seed& s) { return s.bytes.size() > 64 * 1024; }),
                  seeds.end());
      break;
    case Kind::Image: {
      for (const char* g : {"backlit_sphere__glsl.png", "coloured_cubes__gx.png"})
        seeds.push_back({g, ".png", test::read_file(src / "tests" / "goldens" / g)});
      // A float image as the reference writes them.
      Image img;
      img.width = 12;
      img.height = 9;
      img.rgba.resize(12 * 9 * 4);
      for (std::size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = (i % 7) / 6.0f;
      for (const char* ext : {".exr"}) {
        const fs::path p = scratch / (std::string("seed") + ext);
        write_image(p, img);
        seeds.push_back({p.filename().string(), ext, test::read_file(p)});
      }
      break;
    }
    case Kind::Program: {
      add_folder(src / "combiners", {".comb"});
      const fs::path exported = scratch / "seed_gx.c";
      const auto r =
          test::run_ltrender("export gx " + (src / "scenes" / "coloured_cubes.json").string() +
                             " -o " + exported.string());
      EXPECT_EQ(r.exit_code, 0) << r.err;
      seeds.push_back({"seed_gx.c", ".c", test::read_file(exported)});
      break;
    }
  }
  return seeds;
}

// Values that break readers: out of range, non-finite, huge counts, signs, empty.
const std::vector<std::string>& special_tokens() {
  static const std::vector<std::string> t = {
      "nan",    "-inf", "inf",    "1e300", "-1",   "0", "2147483647", "4294967296",
      "1e-320", "",     "3.5e38", "-0",    "0x10", "{", "\"",         "null"};
  return t;
}

// One seeded mutation: byte flips, a cut, a repeated or deleted range, or a number replaced
// by a special token (the mutation that reaches the checks behind the parsers).
std::string mutate(const std::string& in, std::mt19937& rng) {
  std::string s = in;
  if (s.empty()) s = " ";
  auto pick = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  const int rounds = 1 + static_cast<int>(pick(3));
  for (int r = 0; r < rounds; ++r) {
    switch (pick(6)) {
      case 0:  // flip bytes
        for (int k = 0, n = 1 + static_cast<int>(pick(4)); k < n; ++k)
          s[pick(s.size())] ^= static_cast<char>(1u << pick(8));
        break;
      case 1:  // truncate
        s.resize(pick(s.size()));
        break;
      case 2: {  // delete a range
        const std::size_t at = pick(s.size());
        s.erase(at, 1 + pick(std::min<std::size_t>(64, s.size() - at)));
        break;
      }
      case 3: {  // repeat a range
        const std::size_t at = pick(s.size());
        const std::string piece = s.substr(at, 1 + pick(64));
        s.insert(pick(s.size()), piece);
        break;
      }
      case 4:
      case 5: {  // a number becomes a special token
        static const std::regex number(R"([-+]?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?)");
        std::vector<std::pair<std::size_t, std::size_t>> spans;
        for (auto it = std::sregex_iterator(s.begin(), s.end(), number);
             it != std::sregex_iterator() && spans.size() < 4096; ++it)
          spans.emplace_back(it->position(), it->length());
        if (spans.empty()) break;
        const auto [at, len] = spans[pick(spans.size())];
        s.replace(at, len, special_tokens()[pick(special_tokens().size())]);
        break;
      }
    }
    if (s.empty()) s = " ";
  }
  return s;
}

// A scene mutated as JSON, so that the mutation reaches validation rather than the JSON parser:
// one value replaced by a hostile one, a key removed, an unknown key added, or an array element
// repeated (many lights, many objects).
std::string mutate_scene_json(const std::string& text, std::mt19937& rng) {
  using nlohmann::json;
  json doc = json::parse(text);
  std::vector<json::json_pointer> places;
  std::function<void(const json&, const json::json_pointer&)> walk =
      [&](const json& j, const json::json_pointer& at) {
        places.push_back(at);
        if (j.is_object())
          for (auto it = j.begin(); it != j.end(); ++it) walk(*it, at / it.key());
        if (j.is_array())
          for (std::size_t i = 0; i < j.size(); ++i) walk(j[i], at / i);
      };
  walk(doc, json::json_pointer());
  auto pick = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);
  };
  const json hostile[] = {1e300,
                          -1e300,
                          -1,
                          0,
                          2147483647,
                          1e-310,
                          3.5e38,
                          "x",
                          nullptr,
                          json::array(),
                          json::object(),
                          true,
                          json::array({1e38, 1e38, 1e38}),
                          json::array({0, 0, 0}),
                          json::array({1, 2})};
  const json::json_pointer at = places[1 + pick(places.size() - 1)];
  switch (pick(4)) {
    case 0:
      doc[at] = hostile[pick(std::size(hostile))];
      break;
    case 1: {
      // A number stays a number, so the mutation reaches the range checks and the render.
      std::vector<json::json_pointer> numbers;
      for (const auto& p : places)
        if (doc[p].is_number()) numbers.push_back(p);
      if (numbers.empty()) break;
      const json::json_pointer n = numbers[pick(numbers.size())];
      const double x = doc[n].get<double>();
      const double scaled[] = {0.0, -x, x * 1e6, x * 1e-6, 1e300, 1e-310, 3.5e38, x + 0.5};
      doc[n] = scaled[pick(std::size(scaled))];
      break;
    }
    case 2:
      if (doc[at.parent_pointer()].is_object()) {
        doc[at.parent_pointer()].erase(at.back());
      } else {
        doc[at.parent_pointer()].erase(std::stoul(at.back()));
      }
      break;
    case 3: {
      json& parent = doc[at.parent_pointer()];
      if (parent.is_array()) {
        const json copy = parent[0];
        for (std::size_t k = 0, n = 1 + pick(100); k < n; ++k) parent.push_back(copy);
      } else {
        parent["unknown_key"] = 1;
      }
      break;
    }
  }
  return doc.dump();
}

// Descriptor 2 into a file while `fn` runs; returns what was written. The readers' own captures
// (core/stderr_capture.h) nest inside this one: they save and restore whatever fd 2 is.
template <typename Fn>
std::string stderr_of(Fn&& fn) {
  std::fflush(stderr);
  std::FILE* tmp = std::tmpfile();
  const int saved = ::dup(2);
  ::dup2(::fileno(tmp), 2);
  try {
    fn();
  } catch (...) {
    std::fflush(stderr);
    ::dup2(saved, 2);
    ::close(saved);
    std::fclose(tmp);
    throw;
  }
  std::fflush(stderr);
  ::dup2(saved, 2);
  ::close(saved);
  std::rewind(tmp);
  std::string text;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, tmp)) > 0;) text.append(buf, n);
  std::fclose(tmp);
  return text;
}

// Every stderr line a reader may print itself is one of our warnings.
void expect_only_warnings(const std::string& err, const std::string& what) {
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);) {
    EXPECT_EQ(line.rfind("ltrender: warning:", 0), 0u) << what << ": stray stderr line: " << line;
  }
}

// What an accepted file must give: usable data.
void check_accepted(Kind kind, const fs::path& file, const std::string& what) {
  switch (kind) {
    case Kind::Scene: {
      const Scene scene = load_scene(file);
      for (const char* path : {"reference", "combiners"}) {
        const Image img = render_scene(scene, path, "", 16, 12);
        EXPECT_EQ(test::non_finite(img), 0u) << what << " through " << path;
      }
      break;
    }
    case Kind::Mesh: {
      const TriangleMesh m = load_triangle_mesh(file);
      for (std::size_t i = 0; i < m.positions.size(); ++i) {
        ASSERT_TRUE(std::isfinite(m.positions[i].x) && std::isfinite(m.positions[i].y) &&
                    std::isfinite(m.positions[i].z))
            << what << " vertex " << i;
        const double len = glm::length(m.normals[i]);
        ASSERT_TRUE(len == 0.0 || std::fabs(len - 1.0) < 1e-6) << what << " normal " << i;
      }
      for (const auto& t : m.triangles)
        ASSERT_TRUE(t.x < m.positions.size() && t.y < m.positions.size() &&
                    t.z < m.positions.size())
            << what;
      break;
    }
    case Kind::Image: {
      const Image img = read_image(file);
      ASSERT_EQ(img.rgba.size(), static_cast<std::size_t>(img.width) * img.height * 4) << what;
      // The comparison takes whatever was accepted (an EXR may hold NaN: compare counts it).
      (void)compare_images(img, img, TestEncoding::kFloat);
      break;
    }
    case Kind::Program: {
      for (const PathInfo& p : all_paths()) {
        const auto& exts = p.program_extensions;
        if (std::find(exts.begin(), exts.end(), file.extension().string()) == exts.end()) continue;
        (void)budget::to_json(p.budget_file(file.string(), ""));
      }
      break;
    }
  }
}

struct FuzzShard {
  Kind kind;
  int shard;
};

class Fuzz : public ::testing::TestWithParam<FuzzShard> {};

TEST_P(Fuzz, EveryMutationIsAcceptedOrRefusedOnOneLineNamingTheFile) {
  const FuzzShard p = GetParam();
  test::TempDir dir;
  const std::vector<Seed> seeds = seeds_of(p.kind, dir.path());
  ASSERT_FALSE(seeds.empty());
  int accepted = 0, refused = 0;
  for (int c = 0; c < kCasesPerShard + kCliCasesPerShard; ++c) {
    const int index = p.shard * (kCasesPerShard + kCliCasesPerShard) + c;
    std::mt19937 rng(0x1f0a5u + static_cast<unsigned>(index) * 7919u +
                     static_cast<unsigned>(p.kind) * 104729u);
    const Seed& seed = seeds[static_cast<std::size_t>(index) % seeds.size()];
    const fs::path file = dir / ("case" + std::to_string(index) + seed.extension);
    // Half the scenes are mutated as JSON values, half as bytes.
    const std::string bytes = p.kind == Kind::Scene && index % 2 == 0
                                  ? mutate_scene_json(seed.bytes, rng)
                                  : mutate(seed.bytes, rng);
    test::write_file(file, bytes);
    const std::string what = std::string(name_of(p.kind)) + " case " + std::to_string(index) +
                             " (from " + seed.name + ", kept in the test's temp dir on failure)";
    if (c >= kCasesPerShard) {
      // Through the binary: exit 0, 1 (a budget over its profile) or 2, and on 2 one final line.
      std::string args;
      switch (p.kind) {
        case Kind::Scene:
          args = "render " + file.string() + " --path reference --width 16 --height 12 -o " +
                 (dir / "out.exr").string();
          break;
        case Kind::Mesh:
          args = "bake " + file.string() + " --rays 4 -o " + (dir / "baked.ply").string();
          break;
        case Kind::Image:
          args = "compare " + file.string() + " " + file.string();
          break;
        case Kind::Program:
          args = "budget " + file.string();
          break;
      }
      const auto r = test::run_ltrender(args, {60, 0});
      EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1 || r.exit_code == 2)
          << what << ": exit " << r.exit_code << "\n"
          << r.err;
      if (r.exit_code == 2) {
        std::vector<std::string> lines;
        std::istringstream in(r.err);
        for (std::string l; std::getline(in, l);) lines.push_back(l);
        ASSERT_FALSE(lines.empty()) << what;
        EXPECT_EQ(lines.back().rfind("ltrender: error: ", 0), 0u) << what << ": " << r.err;
        EXPECT_NE(lines.back().find(file.filename().string()), std::string::npos)
            << what << ": the error names no file: " << lines.back();
        for (std::size_t i = 0; i + 1 < lines.size(); ++i)
          EXPECT_EQ(lines[i].rfind("ltrender: warning:", 0), 0u) << what << ": " << lines[i];
      }
      continue;
    }
    std::string error;
    const std::string err = stderr_of([&] {
      try {
        check_accepted(p.kind, file, what);
        ++accepted;
      } catch (const InputError& e) {
        ++refused;
        error = e.what();
        if (std::getenv("LT_FUZZ_VERBOSE")) std::printf("refused: %s\n", error.c_str());
      }
    });
    expect_only_warnings(err, what);
    if (!error.empty()) {
      EXPECT_EQ(error.find('\n'), std::string::npos) << what << ": " << error;
      EXPECT_NE(error.find(file.filename().string()), std::string::npos)
          << what << ": the error names no file: " << error;
    }
    if (::testing::Test::HasFailure()) {
      fs::copy_file(file,
                    fs::temp_directory_path() / ("lt_fuzz_failed_" + file.filename().string()),
                    fs::copy_options::overwrite_existing);
      break;
    }
  }
  // Both outcomes occur, or the mutations are not reaching the checks.
  EXPECT_GT(refused, 0) << name_of(p.kind);
  std::printf("%s shard %d: %d accepted, %d refused in process, %d through the binary\n",
              name_of(p.kind), p.shard, accepted, refused, kCliCasesPerShard);
}

std::vector<FuzzShard> all_shards() {
  std::vector<FuzzShard> out;
  for (Kind k : {Kind::Scene, Kind::Mesh, Kind::Image, Kind::Program})
    for (int s = 0; s < kShards; ++s) out.push_back({k, s});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Inputs, Fuzz, ::testing::ValuesIn(all_shards()), [](const auto& info) {
  return std::string(name_of(info.param.kind)) + "_" + std::to_string(info.param.shard);
});

}  // namespace
}  // namespace lt
