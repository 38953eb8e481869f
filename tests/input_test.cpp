// The input layer (core/fs.h): every file ltrender reads (scene, mesh, image, program file) must
// be a regular file within its kind's size cap. Anything else is cli.md's one error line naming
// the file, exit 2 and no output: never a hang (a FIFO), never runaway memory (/dev/zero). The
// runs are bounded (test::RunLimits), so a regression fails here instead of hanging the suite.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>

#include "core/error.h"
#include "core/fs.h"
#include "image/image.h"
#include "load/load_scene.h"
#include "mesh/mesh_io.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt {
namespace {

namespace fs = std::filesystem;

// Long enough for a loaded machine, short enough that a hang fails the test; 4 GB of address
// space stops a read of /dev/zero long before it hurts the machine.
const test::RunLimits kBounded{60, 4096};

std::string scene_with_mesh(const std::string& mesh) {
  return R"({
  "image": {"width": 16, "height": 12},
  "camera": {"eye": [0, 0, 4], "target": [0, 0, 0]},
  "materials": {"m": {"albedo": [0.8, 0.8, 0.8],
                      "translucency": {"power": 4, "thickness": 0.5}}},
  "lights": [{"type": "directional", "direction": [0, 0, 1]}],
  "objects": [{"mesh": ")" +
         mesh + R"(", "material": "m"}]
})";
}

// cli.md's contract for a refused input: exit 2 (124 would be timeout(1): it hung), exactly one
// stderr line, starting with the prefix and naming `file`, saying `what`.
void expect_refused(const test::RunResult& r, const std::string& file, const std::string& what) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("ltrender: error: " + file + ":", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

class InputFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    test::write_file(dir_ / "quad.obj", test::quad_obj());
    test::write_file(dir_ / "good.json", scene_with_mesh("quad.obj"));
    for (const char* name : {"fifo.json", "fifo.ply", "fifo.c", "fifo.png"}) {
      ASSERT_EQ(::mkfifo((dir_ / name).c_str(), 0600), 0) << name;
    }
    for (const char* name : {"zero.json", "zero.ply", "zero.png"}) {
      fs::create_symlink("/dev/zero", dir_ / name);
    }
    write_image(dir_ / "a.png", Image(4, 4));
  }
  std::string p(const std::string& name) const { return (dir_ / name).string(); }

  test::TempDir dir_;
};

TEST_F(InputFiles, FifoSceneIsRefusedByEveryCommand) {
  const std::string fifo = p("fifo.json");
  const std::string fifo_what = "is a FIFO (named pipe), not a regular file";
  expect_refused(test::run_ltrender("info " + fifo, kBounded), fifo, fifo_what);
  expect_refused(test::run_ltrender("render " + fifo + " --path glsl -o " + p("out.png"), kBounded),
                 fifo, fifo_what);
  expect_refused(test::run_ltrender("budget " + fifo, kBounded), fifo, fifo_what);
  expect_refused(test::run_ltrender("bench " + fifo + " -o " + p("bench"), kBounded), fifo,
                 fifo_what);
  expect_refused(test::run_ltrender("export gx " + fifo + " -o " + p("out.c"), kBounded), fifo,
                 fifo_what);
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
  EXPECT_FALSE(fs::exists(dir_ / "bench"));
  EXPECT_FALSE(fs::exists(dir_ / "out.c"));
}

TEST_F(InputFiles, FifoMeshIsRefusedByBake) {
  expect_refused(test::run_ltrender("bake " + p("fifo.ply") + " -o " + p("out.ply"), kBounded),
                 p("fifo.ply"), "is a FIFO (named pipe), not a regular file");
  EXPECT_FALSE(fs::exists(dir_ / "out.ply"));
}

TEST_F(InputFiles, SymlinkToDevZeroIsRefusedBeforeAnyRead) {
  const std::string what =
      "is a character device, not a regular file (a symbolic link to /dev/zero)";
  expect_refused(test::run_ltrender("info " + p("zero.json"), kBounded), p("zero.json"), what);
  expect_refused(test::run_ltrender("bake " + p("zero.ply") + " -o " + p("out.ply"), kBounded),
                 p("zero.ply"), what);
  EXPECT_FALSE(fs::exists(dir_ / "out.ply"));
}

TEST_F(InputFiles, AMeshThatIsNoFileNamesTheScenesKey) {
  for (const char* mesh : {"fifo.ply", "zero.ply"}) {
    test::write_file(dir_ / "s.json", scene_with_mesh(mesh));
    const auto r =
        test::run_ltrender("render " + p("s.json") + " --path glsl -o " + p("out.png"), kBounded);
    expect_refused(r, p("s.json") + ":objects[0].mesh", "not a regular file");
    EXPECT_NE(r.err.find(p(mesh)), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.png"));
  }
}

TEST_F(InputFiles, FifoProgramFileIsRefused) {
  const std::string what = "is a FIFO (named pipe), not a regular file";
  expect_refused(test::run_ltrender("budget " + p("fifo.c"), kBounded), p("fifo.c"), what);
  expect_refused(test::run_ltrender("render " + p("good.json") + " --path gx --program " +
                                        p("fifo.c") + " -o " + p("out.png"),
                                    kBounded),
                 p("fifo.c"), what);
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

// OpenImageIO probes every format it knows once the PNG reader fails: on a FIFO or /dev/zero
// that never ends, so the check must come before it, for TEST and REF alike.
TEST_F(InputFiles, CompareRefusesAFifoOrADeviceAsTestOrReference) {
  const std::string heatmap = " --heatmap " + p("heat.png");
  expect_refused(
      test::run_ltrender("compare " + p("fifo.png") + " " + p("a.png") + heatmap, kBounded),
      p("fifo.png"), "is a FIFO (named pipe), not a regular file");
  expect_refused(
      test::run_ltrender("compare " + p("a.png") + " " + p("fifo.png") + heatmap, kBounded),
      p("fifo.png"), "is a FIFO (named pipe), not a regular file");
  expect_refused(
      test::run_ltrender("compare " + p("a.png") + " " + p("zero.png") + heatmap, kBounded),
      p("zero.png"), "is a character device, not a regular file");
  expect_refused(test::run_ltrender("compare /dev/zero " + p("a.png") + heatmap, kBounded),
                 "/dev/zero", "is a character device, not a regular file");
  EXPECT_FALSE(fs::exists(dir_ / "heat.png"));
}

TEST_F(InputFiles, ADirectoryIsNotAFile) {
  fs::create_directory(dir_ / "dir.json");
  expect_refused(test::run_ltrender("info " + p("dir.json"), kBounded), p("dir.json"),
                 "is a directory, not a scene file");
  fs::create_directory(dir_ / "dir.png");
  expect_refused(test::run_ltrender("compare " + p("dir.png") + " " + p("a.png"), kBounded),
                 p("dir.png"), "is a directory, not an image file");
}

// Sparse files: one byte over each cap costs no disk, and the cap is checked before reading.
TEST_F(InputFiles, EachKindHasASizeCap) {
  auto sparse = [&](const std::string& name, InputKind kind) {
    test::write_file(dir_ / name, "");
    fs::resize_file(dir_ / name, input_size_cap(kind) + 1);
    return p(name);
  };
  const std::string scene = sparse("big.json", InputKind::Scene);
  expect_refused(test::run_ltrender("info " + scene, kBounded), scene,
                 "is 16.0 MiB, over the 16 MiB limit for scene files");
  const std::string mesh = sparse("big.ply", InputKind::Mesh);
  expect_refused(test::run_ltrender("bake " + mesh + " -o " + p("out.ply"), kBounded), mesh,
                 "is 256.0 MiB, over the 256 MiB limit for mesh files");
  const std::string image = sparse("big.png", InputKind::Image);
  expect_refused(test::run_ltrender("compare " + image + " " + p("a.png"), kBounded), image,
                 "is 512.0 MiB, over the 512 MiB limit for image files");
  const std::string program = sparse("big.c", InputKind::Program);
  expect_refused(test::run_ltrender("budget " + program, kBounded), program,
                 "is 16.0 MiB, over the 16 MiB limit for program files");
  EXPECT_FALSE(fs::exists(dir_ / "out.ply"));
}

TEST(ReadInputFile, ReadsARegularFileWhole) {
  test::TempDir dir;
  std::string bytes(200000, 'x');
  bytes[12345] = '\0';  // binary content survives
  test::write_file(dir / "f.ply", bytes);
  EXPECT_EQ(read_input_file(dir / "f.ply", InputKind::Mesh), bytes);
  EXPECT_THROW(read_input_file(dir / "missing.ply", InputKind::Mesh), InputError);
  // The system calls would stop at the NUL and read f.ply instead.
  try {
    read_input_file(dir.path().string() + "/f.ply" + std::string(1, '\0') + "x", InputKind::Mesh);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.what_only(), "path contains a NUL byte");
  }
}

// ---------------------------------------------------------------------------------------------
// Within the caps a file can still be too large for the memory left: the error names the file
// (not "std::bad_alloc" alone). Run in a child whose address space is capped just above what it
// maps already.

std::string error_with_memory_left(std::size_t headroom, const std::function<void()>& work) {
  int fds[2];
  if (::pipe(fds) != 0) return "pipe failed";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    std::string msg = "(no error)";
    long pages = 0;
    if (FILE* f = std::fopen("/proc/self/statm", "r")) {
      if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
      std::fclose(f);
    }
    const rlim_t limit = static_cast<rlim_t>(pages) * ::sysconf(_SC_PAGESIZE) + headroom;
    const rlimit as{limit, limit};
    ::setrlimit(RLIMIT_AS, &as);
    try {
      work();
    } catch (const InputError& e) {
      msg = e.what();
    } catch (const std::exception& e) {
      msg = std::string("not an InputError: ") + e.what();
    }
    if (::write(fds[1], msg.data(), msg.size()) < 0) ::_exit(2);
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) out.append(buf, n);
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return out;
}

TEST(OutOfMemory, ABigMeshNamesItself) {
  if (test::kSanitizedBuild) GTEST_SKIP() << "AddressSanitizer exits on exhaustion, never throws";
  test::TempDir dir;
  // A million vertices of binary PLY: 16 MB of file, well over 64 MB once it is a mesh.
  const int n = 999999;
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(n) +
                    "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                    std::to_string(n / 3) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < n; ++i) {
    const float xyz[3] = {static_cast<float>(i % 1000), static_cast<float>(i / 1000), 0.0f};
    ply.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  }
  for (int f = 0; f < n / 3; ++f) {
    const unsigned char count = 3;
    const int idx[3] = {3 * f, 3 * f + 1, 3 * f + 2};
    ply.append(reinterpret_cast<const char*>(&count), 1);
    ply.append(reinterpret_cast<const char*>(idx), sizeof idx);
  }
  test::write_file(dir / "big.ply", ply);
  const std::string msg =
      error_with_memory_left(std::size_t{64} << 20, [&] { read_mesh(dir / "big.ply"); });
  EXPECT_EQ(msg.rfind((dir / "big.ply").string() + ": out of memory", 0), 0u) << msg;
}

TEST(OutOfMemory, ABigSceneNamesItself) {
  if (test::kSanitizedBuild) GTEST_SKIP() << "AddressSanitizer exits on exhaustion, never throws";
  test::TempDir dir;
  test::write_file(dir / "quad.obj", test::quad_obj());
  // A 12 MB string under an unknown key, inside the scene cap: the parser copies it before the
  // key is refused, and 20 MB of headroom cannot hold the file and the copy. (A string, not an
  // array: nlohmann::json allocates while it destroys a partly parsed array, and a bad_alloc
  // there ends the process whatever we catch.)
  std::string scene = scene_with_mesh("quad.obj");
  scene.insert(scene.find('{') + 1, "\"padding\": \"" + std::string(12 << 20, 'x') + "\",");
  test::write_file(dir / "s.json", scene);
  const std::string msg =
      error_with_memory_left(std::size_t{20} << 20, [&] { load_scene(dir / "s.json"); });
  EXPECT_EQ(msg.rfind((dir / "s.json").string() + ": out of memory", 0), 0u) << msg;
}

}  // namespace
}  // namespace lt

namespace lt {
namespace {

// Library messages with newlines (OpenImageIO's "PNG read error: ...\nPNG library error") become
// one line where the error is made, so every consumer sees cli.md's one line.
TEST(InputErrorText, LinesAreJoinedWhereTheErrorIsMade) {
  const InputError e("f.png", "",
                     "cannot decode image: PNG read error: CRC error\nPNG library error\n");
  EXPECT_EQ(e.what_only(), "cannot decode image: PNG read error: CRC error; PNG library error");
  EXPECT_EQ(std::string(e.what()),
            "f.png: cannot decode image: PNG read error: CRC error; PNG library error");
}

// A message quoting kilobytes (an unknown key 5000 characters long) is cut to a bounded line.
TEST(InputErrorText, TheCliLineHasABoundedLength) {
  test::TempDir dir;
  const std::string key(5000, 'k');
  std::ifstream in(test::source_dir() / "scenes" / "backlit_sphere.json");
  std::string scene((std::istreambuf_iterator<char>(in)), {});
  scene.replace(scene.find("../meshes/"), 10, (test::source_dir() / "meshes").string() + "/");
  scene.insert(1, "\"" + key + "\": 1,");
  test::write_file(dir / "s.json", scene);
  const auto r = test::run_ltrender("info " + (dir / "s.json").string());
  EXPECT_EQ(r.exit_code, 2);
  ASSERT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("ltrender: error: ", 0), 0u);
  EXPECT_LT(r.err.size(), 1100u);
  EXPECT_NE(r.err.find("more characters)"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace lt
