// Start-up (issue 11): the binary maps no image library until a command uses one. OpenImageIO
// alone maps ~250 libraries (0.29 s, 130 MB before main on a 2-core machine); commands such as
// `budget FILE` and `info` use no image and must not pay that. Where the image module is found
// (core/run_time_files.h: the build directory, or an installed prefix's lib/ltrender/) is
// tested on real installs in tests/install/.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "core/build_paths.h"
#include "test_util.h"

namespace lt {
namespace {

// What the dynamic loader maps for `binary` before main(): ld.so lists instead of running when
// LD_TRACE_LOADED_OBJECTS is set (this is what ldd does). `env` sets it for the binary alone.
std::string loaded_libraries(const std::string& binary) {
  const std::string cmd = "env LD_TRACE_LOADED_OBJECTS=1 " + binary;
  std::string out;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return out;
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  ::pclose(p);
  return out;
}

TEST(Startup, TheBinaryMapsNoImageLibrary) {
  const std::string libs = loaded_libraries(lt::build_paths::ltrender_binary().string());
  // The trace itself worked: the GL library the binary does link is in it.
  ASSERT_NE(libs.find("libOSMesa"), std::string::npos) << libs;
  EXPECT_EQ(libs.find("libOpenImageIO"), std::string::npos) << libs;
  EXPECT_EQ(libs.find("libopencv"), std::string::npos) << libs;
  EXPECT_EQ(libs.find("libltrender_imageio"), std::string::npos) << libs;
}

// gtest builds every parameter list in every test process, and ctest starts one process per
// test: a list made by loading scenes (a map's image opens the image module, ~0.3 s) was paid
// ~1,700 times and was half the suite's CPU time (issue 28). Listing the tests must load none.
// LD_DEBUG=files makes ld.so print each library it opens, dlopen's included, to stderr.
TEST(Startup, ListingTheTestsLoadsNoImage) {
  const std::string cmd = "LD_DEBUG=files /proc/" + std::to_string(::getpid()) +
                          "/exe --gtest_list_tests 2>&1 >/dev/null";
  std::string out;
  FILE* p = ::popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  ::pclose(p);
  // The trace itself worked: the GL library the binary links is opened at start.
  ASSERT_NE(out.find("libOSMesa"), std::string::npos) << out.substr(0, 2000);
  EXPECT_EQ(out.find("libltrender_imageio"), std::string::npos)
      << "a parameter list loads a scene or an image; build it from file names (bounds_test.cpp)";
}

}  // namespace
}  // namespace lt
