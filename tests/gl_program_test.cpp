// gl::GlslProgram owns its GL objects: a program that fails to compile or link releases what it
// made before the error leaves its constructor (issue 24: a failed link leaked both shaders and
// the program, because a throwing constructor runs no destructor).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/program.h"

namespace lt {
namespace {

constexpr const char* kVertex = "void main() { gl_Position = ftransform(); }\n";
constexpr const char* kFragment = "void main() { gl_FragColor = vec4(1.0); }\n";

// The shader and program names alive in this context: a fresh context hands out names from 1
// on (Mesa's name allocator; the GL spec allows any unused name, so the scan is generous).
// The error a program's construction throws ("" when it builds).
std::string build_error(const char* vertex, const char* fragment) {
  try {
    const gl::GlslProgram p(vertex, fragment, "test");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

std::vector<GLuint> live_objects() {
  std::vector<GLuint> out;
  for (GLuint id = 1; id < 256; ++id) {
    if (glIsShader(id) || glIsProgram(id)) out.push_back(id);
  }
  return out;
}

TEST(GlslProgram, ABuiltProgramHoldsItsObjectsUntilItIsDestroyed) {
  gl::Context ctx(4, 4);
  {
    const gl::GlslProgram p(kVertex, kFragment, "good");
    EXPECT_EQ(live_objects().size(), 3u);  // two shaders and the program: the scan sees them
  }
  EXPECT_TRUE(live_objects().empty());
}

TEST(GlslProgram, AFailedCompileOrLinkLeavesNoObjectBehind) {
  gl::Context ctx(4, 4);
  // The fragment shader does not compile: the vertex shader was already made.
  EXPECT_NE(build_error(kVertex, "void main() { syntax error }\n").find("compile error"),
            std::string::npos);
  EXPECT_TRUE(live_objects().empty());
  // Both compile, the link fails (a varying read in the fragment shader that no vertex shader
  // writes is a link error in GLSL 1.10, §4.3.6): both shaders and the program were made.
  EXPECT_NE(build_error(kVertex,
                        "varying vec4 never_written;\n"
                        "void main() { gl_FragColor = never_written; }\n")
                .find("link error"),
            std::string::npos);
  EXPECT_TRUE(live_objects().empty());
}

}  // namespace
}  // namespace lt
