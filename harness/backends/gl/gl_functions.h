#pragma once
// Every GL entry point snell calls, as one table of pointers loaded from the
// context provider in use (OSMesa or EGL), so that the backend code above
// it is the same for both and no GL library is linked. The macros below
// route each glFoo(...) call through the table of the context made current
// last; include this (through gl_api.h) after the GL headers.
//
// A new call: add its name to SNELL_GL_FUNCTIONS and a #define below.

#define SNELL_GL_FUNCTIONS(X)      \
  X(glActiveTexture)               \
  X(glAttachShader)                \
  X(glBeginQuery)                  \
  X(glBeginTransformFeedback)      \
  X(glBindBuffer)                  \
  X(glBindBufferBase)              \
  X(glBindFragDataLocation)        \
  X(glBindFramebuffer)             \
  X(glBindRenderbuffer)            \
  X(glBindTexture)                 \
  X(glBindVertexArray)             \
  X(glBufferData)                  \
  X(glCheckFramebufferStatus)      \
  X(glClearBufferfv)               \
  X(glClearColor)                  \
  X(glClearDepth)                  \
  X(glClientActiveTexture)         \
  X(glColorMask)                   \
  X(glCompileShader)               \
  X(glCreateProgram)               \
  X(glCreateShader)                \
  X(glCullFace)                    \
  X(glDeleteBuffers)               \
  X(glDeleteFramebuffers)          \
  X(glDeleteProgram)               \
  X(glDeleteQueries)               \
  X(glDeleteRenderbuffers)         \
  X(glDeleteShader)                \
  X(glDeleteTextures)              \
  X(glDeleteVertexArrays)          \
  X(glDepthFunc)                   \
  X(glDepthMask)                   \
  X(glDetachShader)                \
  X(glDisable)                     \
  X(glDisableClientState)          \
  X(glDisableVertexAttribArray)    \
  X(glDrawArrays)                  \
  X(glDrawBuffers)                 \
  X(glDrawElements)                \
  X(glEnable)                      \
  X(glEnableClientState)           \
  X(glEnableVertexAttribArray)     \
  X(glEndQuery)                    \
  X(glEndTransformFeedback)        \
  X(glFinish)                      \
  X(glFramebufferRenderbuffer)     \
  X(glFrontFace)                   \
  X(glGenBuffers)                  \
  X(glGenFramebuffers)             \
  X(glGenQueries)                  \
  X(glGenRenderbuffers)            \
  X(glGenTextures)                 \
  X(glGenVertexArrays)             \
  X(glGetActiveAttrib)             \
  X(glGetActiveUniform)            \
  X(glGetAttribLocation)           \
  X(glGetBufferSubData)            \
  X(glGetError)                    \
  X(glGetIntegerv)                 \
  X(glGetProgramInfoLog)           \
  X(glGetProgramInterfaceiv)       \
  X(glGetProgramResourceName)      \
  X(glGetProgramResourceiv)        \
  X(glGetProgramiv)                \
  X(glGetQueryObjectuiv)           \
  X(glGetShaderInfoLog)            \
  X(glGetShaderiv)                 \
  X(glGetString)                   \
  X(glGetTransformFeedbackVarying) \
  X(glGetUniformLocation)          \
  X(glGetUniformfv)                \
  X(glIsEnabled)                   \
  X(glLinkProgram)                 \
  X(glLoadIdentity)                \
  X(glLoadMatrixf)                 \
  X(glMatrixMode)                  \
  X(glMultiTexCoord4f)             \
  X(glNormal3f)                    \
  X(glNormalPointer)               \
  X(glPixelStorei)                 \
  X(glReadBuffer)                  \
  X(glReadPixels)                  \
  X(glRenderbufferStorage)         \
  X(glShaderSource)                \
  X(glTexCoordPointer)             \
  X(glTexImage2D)                  \
  X(glTexParameteri)               \
  X(glTransformFeedbackVaryings)   \
  X(glUniform1fv)                  \
  X(glUniform1i)                   \
  X(glUniform1iv)                  \
  X(glUniform2fv)                  \
  X(glUniform3fv)                  \
  X(glUniform4fv)                  \
  X(glUniformMatrix3fv)            \
  X(glUniformMatrix4fv)            \
  X(glUseProgram)                  \
  X(glVertexAttribPointer)         \
  X(glVertexPointer)               \
  X(glViewport)

namespace snell {

struct GlFunctions {
#define SNELL_GL_MEMBER(name) decltype(&::name) name##_ = nullptr;
  SNELL_GL_FUNCTIONS(SNELL_GL_MEMBER)
#undef SNELL_GL_MEMBER
};

// The table of the current context's provider; set by makeCurrent.
extern const GlFunctions* currentGlFunctions;

// Looks every entry point up with `lookup` (the provider's GetProcAddress).
// Throws SetupError naming the first one missing.
using GlProcLookup = void* (*)(const char* name, void* userData);
GlFunctions loadGlFunctions(GlProcLookup lookup, void* userData, const char* providerName);

}  // namespace snell

#define glActiveTexture (::snell::currentGlFunctions->glActiveTexture_)
#define glAttachShader (::snell::currentGlFunctions->glAttachShader_)
#define glBeginQuery (::snell::currentGlFunctions->glBeginQuery_)
#define glBeginTransformFeedback (::snell::currentGlFunctions->glBeginTransformFeedback_)
#define glBindBuffer (::snell::currentGlFunctions->glBindBuffer_)
#define glBindBufferBase (::snell::currentGlFunctions->glBindBufferBase_)
#define glBindFragDataLocation (::snell::currentGlFunctions->glBindFragDataLocation_)
#define glBindFramebuffer (::snell::currentGlFunctions->glBindFramebuffer_)
#define glBindRenderbuffer (::snell::currentGlFunctions->glBindRenderbuffer_)
#define glBindTexture (::snell::currentGlFunctions->glBindTexture_)
#define glBindVertexArray (::snell::currentGlFunctions->glBindVertexArray_)
#define glBufferData (::snell::currentGlFunctions->glBufferData_)
#define glCheckFramebufferStatus (::snell::currentGlFunctions->glCheckFramebufferStatus_)
#define glClearBufferfv (::snell::currentGlFunctions->glClearBufferfv_)
#define glClearColor (::snell::currentGlFunctions->glClearColor_)
#define glClearDepth (::snell::currentGlFunctions->glClearDepth_)
#define glClientActiveTexture (::snell::currentGlFunctions->glClientActiveTexture_)
#define glColorMask (::snell::currentGlFunctions->glColorMask_)
#define glCompileShader (::snell::currentGlFunctions->glCompileShader_)
#define glCreateProgram (::snell::currentGlFunctions->glCreateProgram_)
#define glCreateShader (::snell::currentGlFunctions->glCreateShader_)
#define glCullFace (::snell::currentGlFunctions->glCullFace_)
#define glDeleteBuffers (::snell::currentGlFunctions->glDeleteBuffers_)
#define glDeleteFramebuffers (::snell::currentGlFunctions->glDeleteFramebuffers_)
#define glDeleteProgram (::snell::currentGlFunctions->glDeleteProgram_)
#define glDeleteQueries (::snell::currentGlFunctions->glDeleteQueries_)
#define glDeleteRenderbuffers (::snell::currentGlFunctions->glDeleteRenderbuffers_)
#define glDeleteShader (::snell::currentGlFunctions->glDeleteShader_)
#define glDeleteTextures (::snell::currentGlFunctions->glDeleteTextures_)
#define glDeleteVertexArrays (::snell::currentGlFunctions->glDeleteVertexArrays_)
#define glDepthFunc (::snell::currentGlFunctions->glDepthFunc_)
#define glDepthMask (::snell::currentGlFunctions->glDepthMask_)
#define glDetachShader (::snell::currentGlFunctions->glDetachShader_)
#define glDisable (::snell::currentGlFunctions->glDisable_)
#define glDisableClientState (::snell::currentGlFunctions->glDisableClientState_)
#define glDisableVertexAttribArray (::snell::currentGlFunctions->glDisableVertexAttribArray_)
#define glDrawArrays (::snell::currentGlFunctions->glDrawArrays_)
#define glDrawBuffers (::snell::currentGlFunctions->glDrawBuffers_)
#define glDrawElements (::snell::currentGlFunctions->glDrawElements_)
#define glEnable (::snell::currentGlFunctions->glEnable_)
#define glEnableClientState (::snell::currentGlFunctions->glEnableClientState_)
#define glEnableVertexAttribArray (::snell::currentGlFunctions->glEnableVertexAttribArray_)
#define glEndQuery (::snell::currentGlFunctions->glEndQuery_)
#define glEndTransformFeedback (::snell::currentGlFunctions->glEndTransformFeedback_)
#define glFinish (::snell::currentGlFunctions->glFinish_)
#define glFramebufferRenderbuffer (::snell::currentGlFunctions->glFramebufferRenderbuffer_)
#define glFrontFace (::snell::currentGlFunctions->glFrontFace_)
#define glGenBuffers (::snell::currentGlFunctions->glGenBuffers_)
#define glGenFramebuffers (::snell::currentGlFunctions->glGenFramebuffers_)
#define glGenQueries (::snell::currentGlFunctions->glGenQueries_)
#define glGenRenderbuffers (::snell::currentGlFunctions->glGenRenderbuffers_)
#define glGenTextures (::snell::currentGlFunctions->glGenTextures_)
#define glGenVertexArrays (::snell::currentGlFunctions->glGenVertexArrays_)
#define glGetActiveAttrib (::snell::currentGlFunctions->glGetActiveAttrib_)
#define glGetActiveUniform (::snell::currentGlFunctions->glGetActiveUniform_)
#define glGetAttribLocation (::snell::currentGlFunctions->glGetAttribLocation_)
#define glGetBufferSubData (::snell::currentGlFunctions->glGetBufferSubData_)
#define glGetError (::snell::currentGlFunctions->glGetError_)
#define glGetIntegerv (::snell::currentGlFunctions->glGetIntegerv_)
#define glGetProgramInfoLog (::snell::currentGlFunctions->glGetProgramInfoLog_)
#define glGetProgramInterfaceiv (::snell::currentGlFunctions->glGetProgramInterfaceiv_)
#define glGetProgramResourceName (::snell::currentGlFunctions->glGetProgramResourceName_)
#define glGetProgramResourceiv (::snell::currentGlFunctions->glGetProgramResourceiv_)
#define glGetProgramiv (::snell::currentGlFunctions->glGetProgramiv_)
#define glGetQueryObjectuiv (::snell::currentGlFunctions->glGetQueryObjectuiv_)
#define glGetShaderInfoLog (::snell::currentGlFunctions->glGetShaderInfoLog_)
#define glGetShaderiv (::snell::currentGlFunctions->glGetShaderiv_)
#define glGetString (::snell::currentGlFunctions->glGetString_)
#define glGetTransformFeedbackVarying (::snell::currentGlFunctions->glGetTransformFeedbackVarying_)
#define glGetUniformLocation (::snell::currentGlFunctions->glGetUniformLocation_)
#define glGetUniformfv (::snell::currentGlFunctions->glGetUniformfv_)
#define glIsEnabled (::snell::currentGlFunctions->glIsEnabled_)
#define glLinkProgram (::snell::currentGlFunctions->glLinkProgram_)
#define glLoadIdentity (::snell::currentGlFunctions->glLoadIdentity_)
#define glLoadMatrixf (::snell::currentGlFunctions->glLoadMatrixf_)
#define glMatrixMode (::snell::currentGlFunctions->glMatrixMode_)
#define glMultiTexCoord4f (::snell::currentGlFunctions->glMultiTexCoord4f_)
#define glNormal3f (::snell::currentGlFunctions->glNormal3f_)
#define glNormalPointer (::snell::currentGlFunctions->glNormalPointer_)
#define glPixelStorei (::snell::currentGlFunctions->glPixelStorei_)
#define glReadBuffer (::snell::currentGlFunctions->glReadBuffer_)
#define glReadPixels (::snell::currentGlFunctions->glReadPixels_)
#define glRenderbufferStorage (::snell::currentGlFunctions->glRenderbufferStorage_)
#define glShaderSource (::snell::currentGlFunctions->glShaderSource_)
#define glTexCoordPointer (::snell::currentGlFunctions->glTexCoordPointer_)
#define glTexImage2D (::snell::currentGlFunctions->glTexImage2D_)
#define glTexParameteri (::snell::currentGlFunctions->glTexParameteri_)
#define glTransformFeedbackVaryings (::snell::currentGlFunctions->glTransformFeedbackVaryings_)
#define glUniform1fv (::snell::currentGlFunctions->glUniform1fv_)
#define glUniform1i (::snell::currentGlFunctions->glUniform1i_)
#define glUniform1iv (::snell::currentGlFunctions->glUniform1iv_)
#define glUniform2fv (::snell::currentGlFunctions->glUniform2fv_)
#define glUniform3fv (::snell::currentGlFunctions->glUniform3fv_)
#define glUniform4fv (::snell::currentGlFunctions->glUniform4fv_)
#define glUniformMatrix3fv (::snell::currentGlFunctions->glUniformMatrix3fv_)
#define glUniformMatrix4fv (::snell::currentGlFunctions->glUniformMatrix4fv_)
#define glUseProgram (::snell::currentGlFunctions->glUseProgram_)
#define glVertexAttribPointer (::snell::currentGlFunctions->glVertexAttribPointer_)
#define glVertexPointer (::snell::currentGlFunctions->glVertexPointer_)
#define glViewport (::snell::currentGlFunctions->glViewport_)
