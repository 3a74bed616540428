/* The GL 2.0 shader entry points the reference programs (mesa_ref.c, frag_ref.c) look up
 * through OSMesaGetProcAddress, and the enums they use. */
#ifndef GL_PROCS_H
#define GL_PROCS_H
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>

typedef GLuint (*CreateShader)(GLenum);
typedef void (*ShaderSource)(GLuint, GLsizei, const char *const *, const GLint *);
typedef void (*CompileShader)(GLuint);
typedef void (*GetShaderiv)(GLuint, GLenum, GLint *);
typedef void (*GetInfoLog)(GLuint, GLsizei, GLsizei *, char *);
typedef void (*DeleteObject)(GLuint);
typedef GLuint (*CreateProgram)(void);
typedef void (*AttachShader)(GLuint, GLuint);
typedef void (*LinkProgram)(GLuint);

#define GL_FRAGMENT_SHADER_ 0x8B30
#define GL_VERTEX_SHADER_ 0x8B31
#define GL_COMPILE_STATUS_ 0x8B81
#define GL_LINK_STATUS_ 0x8B82
#define GL_INFO_LOG_LENGTH_ 0x8B84

/* The entry point `name`; exits with status 2 when Mesa lacks it. */
static void *proc(const char *name) {
    void *p = (void *)OSMesaGetProcAddress(name);
    if (!p) {
        fprintf(stderr, "no %s\n", name);
        exit(2);
    }
    return p;
}
#endif
