// One place that includes GL: OSMesa's libOSMesa exports every entry point we use, so with
// GL_GLEXT_PROTOTYPES (set by CMake) we call them directly, no loader needed.
#pragma once

#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
