/*
 * GL/osmesa.h — the OSMesa off-screen rendering API
 *
 * softgl: a software OpenGL 1.5 implementation with Mesa's OSMesa API.
 *
 * GENERATED FILE, DO NOT EDIT. Produced by cbindgen from the files in src/ffi with
 *   cargo run --example gen_headers
 * (tests/headers.rs fails when this file is stale).
 */

#ifndef OSMESA_H
#define OSMESA_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Constants: src/ffi/osmesa.rs */
#define OSMESA_COLOR_INDEX                       GL_COLOR_INDEX
#define OSMESA_RGBA                              GL_RGBA
#define OSMESA_BGRA                              0x1
#define OSMESA_ARGB                              0x2
#define OSMESA_RGB                               GL_RGB
#define OSMESA_BGR                               0x4
#define OSMESA_RGB_565                           0x5
#define OSMESA_ROW_LENGTH                        0x10
#define OSMESA_Y_UP                              0x11
#define OSMESA_WIDTH                             0x20
#define OSMESA_HEIGHT                            0x21
#define OSMESA_FORMAT                            0x22
#define OSMESA_TYPE                              0x23
#define OSMESA_MAX_WIDTH                         0x24
#define OSMESA_MAX_HEIGHT                        0x25
#define OSMESA_DEPTH_BITS                        0x30
#define OSMESA_STENCIL_BITS                      0x31
#define OSMESA_ACCUM_BITS                        0x32
#define OSMESA_PROFILE                           0x33
#define OSMESA_CORE_PROFILE                      0x34
#define OSMESA_COMPAT_PROFILE                    0x35
#define OSMESA_CONTEXT_MAJOR_VERSION             0x36
#define OSMESA_CONTEXT_MINOR_VERSION             0x37
#define OSMESA_MAJOR_VERSION                     11
#define OSMESA_MINOR_VERSION                     2
#define OSMESA_PATCH_VERSION                     0

/* Types: src/ffi/osmesa.rs */
struct osmesa_context;
typedef struct osmesa_context *OSMesaContext;
typedef void (*OSMESAproc)();

/* Functions: src/ffi/osmesa.rs */
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContext(GLenum format, OSMesaContext sharelist);
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextExt(GLenum format, GLint depthBits, GLint stencilBits, GLint accumBits, OSMesaContext sharelist);
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextAttribs(const int *attribList, OSMesaContext sharelist);
GLAPI void GLAPIENTRY OSMesaDestroyContext(OSMesaContext ctx);
GLAPI GLboolean GLAPIENTRY OSMesaMakeCurrent(OSMesaContext ctx, void *buffer, GLenum type, GLsizei width, GLsizei height);
GLAPI OSMesaContext GLAPIENTRY OSMesaGetCurrentContext(void);
GLAPI void GLAPIENTRY OSMesaPixelStore(GLint pname, GLint value);
GLAPI void GLAPIENTRY OSMesaGetIntegerv(GLint pname, GLint *value);
GLAPI GLboolean GLAPIENTRY OSMesaGetDepthBuffer(OSMesaContext c, GLint *width, GLint *height, GLint *bytesPerValue, void **buffer);
GLAPI GLboolean GLAPIENTRY OSMesaGetColorBuffer(OSMesaContext c, GLint *width, GLint *height, GLint *format, void **buffer);
GLAPI void GLAPIENTRY OSMesaColorClamp(GLboolean enable);
GLAPI void GLAPIENTRY OSMesaPostprocess(OSMesaContext osmesa, const char *filter, unsigned int enable_value);
GLAPI OSMESAproc GLAPIENTRY OSMesaGetProcAddress(const char *funcName);

#ifdef __cplusplus
}
#endif

#endif /* OSMESA_H */
