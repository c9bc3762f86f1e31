#pragma once
// The one place the GL and OSMesa headers come in. GL_GLEXT_PROTOTYPES (set
// by the target) makes glext.h declare the GL 3.x/4.x entry points that
// libOSMesa exports directly, so no loader is needed.
#include <GL/osmesa.h>  // includes GL/gl.h, which includes GL/glext.h
