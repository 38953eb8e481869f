// Which renderer made a golden (docs/regress.md "Goldens per renderer"): developer machines and CI
// images carry different Mesa builds and drivers (llvmpipe, softpipe), which may differ by an
// LSB. A case keeps a shared golden and, per renderer, an approved override in a folder named by
// the renderer's key; it passes against either (Skia Gold's and Chromium's several approved
// images a test, Blender's reference_override_dir).
#pragma once

#include <string>

namespace lt {

// The key of the GL renderer this process draws with, from what `--version` reports (the GL
// renderer's first word and the Mesa version): "llvmpipe-mesa-22.3.6", "softpipe-mesa-22.3.6".
std::string renderer_golden_key();

// The key from GL_RENDERER and GL_VERSION as OpenGL reports them.
std::string golden_key_from(const std::string& gl_renderer, const std::string& gl_version);

}  // namespace lt
