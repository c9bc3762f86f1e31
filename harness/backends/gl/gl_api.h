#pragma once
// The one place the GL headers come in. The prototypes are declared only
// so that gl_functions.h can take each entry point's type; every call goes
// through the table the context provider loaded (no GL library is linked).
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>

#include "backends/gl/gl_functions.h"
