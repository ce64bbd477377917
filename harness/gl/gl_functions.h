// The GL entry points the plugins use, loaded once from an OsmesaContext (never linked:
// see osmesa_context.h). One table for every GL user, so a function is named once.
#pragma once
#include <GL/glcorearb.h>

#include "harness/gl/osmesa_context.h"

namespace vob::gl {

#define VOB_GL_FUNCTIONS(X)                                                       \
  X(PFNGLGETERRORPROC, glGetError)                                                \
  X(PFNGLGETSTRINGPROC, glGetString)                                              \
  X(PFNGLCREATESHADERPROC, glCreateShader)                                        \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                                        \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                                      \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                          \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                                \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                                        \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                                      \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                                        \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                          \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                        \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                              \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                                      \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                                            \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                            \
  X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                                \
  X(PFNGLPROGRAMUNIFORM1IPROC, glProgramUniform1i)                                \
  X(PFNGLPROGRAMUNIFORMMATRIX4DVPROC, glProgramUniformMatrix4dv)                  \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                                  \
  X(PFNGLCREATEVERTEXARRAYSPROC, glCreateVertexArrays)                            \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                            \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                                  \
  X(PFNGLVERTEXATTRIBPOINTERPROC, glVertexAttribPointer)                          \
  X(PFNGLVERTEXATTRIBIPOINTERPROC, glVertexAttribIPointer)                        \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, glEnableVertexAttribArray)                  \
  X(PFNGLVERTEXARRAYVERTEXBUFFERPROC, glVertexArrayVertexBuffer)                  \
  X(PFNGLVERTEXARRAYELEMENTBUFFERPROC, glVertexArrayElementBuffer)                \
  X(PFNGLVERTEXARRAYATTRIBLFORMATPROC, glVertexArrayAttribLFormat)                \
  X(PFNGLVERTEXARRAYATTRIBIFORMATPROC, glVertexArrayAttribIFormat)                \
  X(PFNGLVERTEXARRAYATTRIBBINDINGPROC, glVertexArrayAttribBinding)                \
  X(PFNGLENABLEVERTEXARRAYATTRIBPROC, glEnableVertexArrayAttrib)                  \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                                            \
  X(PFNGLCREATEBUFFERSPROC, glCreateBuffers)                                      \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                                      \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                                            \
  X(PFNGLBUFFERDATAPROC, glBufferData)                                            \
  X(PFNGLNAMEDBUFFERDATAPROC, glNamedBufferData)                                  \
  X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)                                    \
  X(PFNGLCREATETEXTURESPROC, glCreateTextures)                                    \
  X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                                    \
  X(PFNGLTEXTURESTORAGE2DPROC, glTextureStorage2D)                                \
  X(PFNGLTEXTURESTORAGE3DPROC, glTextureStorage3D)                                \
  X(PFNGLCLEARTEXIMAGEPROC, glClearTexImage)                                      \
  X(PFNGLBINDIMAGETEXTUREPROC, glBindImageTexture)                                \
  X(PFNGLGETTEXTUREIMAGEPROC, glGetTextureImage)                                  \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                                  \
  X(PFNGLCREATEFRAMEBUFFERSPROC, glCreateFramebuffers)                            \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                            \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                                  \
  X(PFNGLNAMEDFRAMEBUFFERPARAMETERIPROC, glNamedFramebufferParameteri)            \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)                    \
  X(PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC, glCheckNamedFramebufferStatus)          \
  X(PFNGLGENRENDERBUFFERSPROC, glGenRenderbuffers)                                \
  X(PFNGLDELETERENDERBUFFERSPROC, glDeleteRenderbuffers)                          \
  X(PFNGLBINDRENDERBUFFERPROC, glBindRenderbuffer)                                \
  X(PFNGLRENDERBUFFERSTORAGEPROC, glRenderbufferStorage)                          \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, glFramebufferRenderbuffer)                  \
  X(PFNGLDRAWBUFFERSPROC, glDrawBuffers)                                          \
  X(PFNGLREADBUFFERPROC, glReadBuffer)                                            \
  X(PFNGLVIEWPORTPROC, glViewport)                                                \
  X(PFNGLENABLEPROC, glEnable)                                                    \
  X(PFNGLDISABLEPROC, glDisable)                                                  \
  X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                              \
  X(PFNGLDEPTHMASKPROC, glDepthMask)                                              \
  X(PFNGLSTENCILFUNCPROC, glStencilFunc)                                          \
  X(PFNGLSTENCILOPPROC, glStencilOp)                                              \
  X(PFNGLSTENCILMASKPROC, glStencilMask)                                          \
  X(PFNGLCLEARBUFFERUIVPROC, glClearBufferuiv)                                    \
  X(PFNGLCLEARBUFFERFIPROC, glClearBufferfi)                                      \
  X(PFNGLDRAWELEMENTSPROC, glDrawElements)                                        \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                            \
  X(PFNGLMEMORYBARRIERPROC, glMemoryBarrier)                                      \
  X(PFNGLFINISHPROC, glFinish)                                                    \
  X(PFNGLREADPIXELSPROC, glReadPixels)                                            \
  X(PFNGLPIXELSTOREIPROC, glPixelStorei)

struct Functions {
#define VOB_GL_MEMBER(type, name) type name = nullptr;
  VOB_GL_FUNCTIONS(VOB_GL_MEMBER)
#undef VOB_GL_MEMBER
  // Loads every entry point; std::runtime_error naming the first one OSMesa lacks.
  explicit Functions(const OsmesaContext& ctx);
  // std::runtime_error("GL error 0x... in WHAT") when glGetError reports one.
  void check(const char* what) const;
};

}  // namespace vob::gl
