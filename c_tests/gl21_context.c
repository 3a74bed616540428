/* gl21_context: a GL 2.1 compatibility context as a GL 2.x program finds it.
 * OSMesaCreateContextAttribs with {compatibility, 2.1} gives a context; its
 * GL_VERSION is at least 2.1 and GL_SHADING_LANGUAGE_VERSION at least 1.20
 * (the numbers are printed as "at least", since Mesa answers 4.5/4.50); the
 * GL 2.0 extensions are advertised; every GL 2.0 limit query answers without an
 * error and at least the GL 2.0 minimum; the derivative hint is set, queried,
 * refused with a bad mode and restored by glPopAttrib; GL_SHADER_COMPILER is
 * true. Then a #version 120 program (a mat2x3 uniform, a const float array with
 * an array constructor, a vertex attribute at a bound location) draws a
 * triangle fan beside a fixed-function quad, and the image is compared. */
#define GL_GLEXT_PROTOTYPES
#include <math.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "errcheck.h"
#include "vert_program.h"

static const char *VS = "#version 120\n"
                        "uniform mat2x3 m;\n"
                        "attribute vec2 pos;\n"
                        "varying vec3 c;\n"
                        "void main() {\n"
                        "  c = m * (pos * 0.5 + 0.5);\n"
                        "  gl_Position = vec4(pos * 0.8, 0.0, 1.0);\n"
                        "}\n";

static const char *FS = "#version 120\n"
                        "varying vec3 c;\n"
                        "const float k[3] = float[3](0.25, 0.5, 1.0);\n"
                        "void main() {\n"
                        "  gl_FragColor = vec4(c * vec3(k[0], k[1], k[2]) + vec3(k.length()) * 0.1, 1.0);\n"
                        "}\n";

/* A limit query: its error and whether it reaches `least`. */
static void limit(const char *name, GLenum pname, GLint least)
{
    GLint v = -7;
    glGetIntegerv(pname, &v);
    sgl_text(out, "limit", "%-38s >= %5d: %d err 0x%04x\n", name, least, v >= least,
             glGetError());
}
#define LIMIT(e, least) limit(#e, e, least)

static void has_ext(const char *exts, const char *name)
{
    const char *p = exts;
    size_t n = strlen(name);
    int found = 0;
    while ((p = strstr(p, name)) != NULL) {
        if ((p == exts || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            found = 1;
        p += n;
    }
    sgl_text(out, "ext", "%s %d\n", name, found);
}

int main(int argc, char **argv)
{
    static const int attribs[] = {OSMESA_FORMAT,          OSMESA_RGBA,
                                  OSMESA_DEPTH_BITS,      24,
                                  OSMESA_PROFILE,         OSMESA_COMPAT_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION, 2,
                                  OSMESA_CONTEXT_MINOR_VERSION, 1,
                                  0};
    static const char *names[] = {"pos", NULL};
    static const GLfloat mat[6] = {1.0f, 0.2f, 0.0f, 0.0f, 0.6f, 1.0f};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);
    unsigned char *buf;
    const char *version, *glsl, *exts;
    int major = 0, minor = 0, i;
    GLint hint = -7;
    GLboolean compiler = 7;
    GLuint p;
    SGL_CHECK(ctx != NULL);
    out = sgl_open(argc, argv);
    buf = malloc(FW * FH * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, FW, FH));

    version = (const char *)glGetString(GL_VERSION);
    glsl = (const char *)glGetString(GL_SHADING_LANGUAGE_VERSION);
    exts = (const char *)glGetString(GL_EXTENSIONS);
    SGL_CHECK(version != NULL && glsl != NULL && exts != NULL);
    SGL_CHECK(sscanf(version, "%d.%d", &major, &minor) == 2);
    sgl_text(out, "version", "GL at least 2.1: %d\n", major * 10 + minor >= 21);
    SGL_CHECK(sscanf(glsl, "%d.%d", &major, &minor) == 2);
    sgl_text(out, "version", "GLSL at least 1.20: %d\n", major * 100 + minor >= 120);
    sgl_text(out, "version", "err 0x%04x\n", glGetError());
    has_ext(exts, "GL_ARB_shader_objects");
    has_ext(exts, "GL_ARB_vertex_shader");
    has_ext(exts, "GL_ARB_fragment_shader");
    has_ext(exts, "GL_ARB_shading_language_100");
    has_ext(exts, "GL_ARB_draw_buffers");
    has_ext(exts, "GL_ARB_texture_non_power_of_two");
    has_ext(exts, "GL_ARB_point_sprite");
    has_ext(exts, "GL_ARB_pixel_buffer_object");
    has_ext(exts, "GL_EXT_texture_sRGB");

    LIMIT(GL_MAX_VERTEX_ATTRIBS, 16);
    LIMIT(GL_MAX_TEXTURE_IMAGE_UNITS, 2);
    LIMIT(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, 2);
    LIMIT(GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS, 0);
    LIMIT(GL_MAX_TEXTURE_COORDS, 2);
    LIMIT(GL_MAX_VARYING_FLOATS, 32);
    LIMIT(GL_MAX_VERTEX_UNIFORM_COMPONENTS, 512);
    LIMIT(GL_MAX_FRAGMENT_UNIFORM_COMPONENTS, 64);
    LIMIT(GL_MAX_DRAW_BUFFERS, 1);

    glGetIntegerv(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, &hint);
    sgl_text(out, "hint", "initial 0x%04x err 0x%04x\n", hint, glGetError());
    glPushAttrib(GL_HINT_BIT);
    E(glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_NICEST));
    E(glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_RGBA));
    glGetIntegerv(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, &hint);
    sgl_text(out, "hint", "set 0x%04x err 0x%04x\n", hint, glGetError());
    glPopAttrib();
    glGetIntegerv(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, &hint);
    sgl_text(out, "hint", "popped 0x%04x err 0x%04x\n", hint, glGetError());
    glGetBooleanv(GL_SHADER_COMPILER, &compiler);
    sgl_text(out, "compiler", "GL_SHADER_COMPILER %d err 0x%04x\n", compiler, glGetError());

    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(0.9f, 0.4f, 0.1f);
    glRectf(-0.95f, -0.95f, -0.3f, 0.95f);
    p = vert_program(VS, FS, names);
    glUseProgram(p);
    glUniformMatrix2x3fv(glGetUniformLocation(p, "m"), 1, GL_FALSE, mat);
    glBegin(GL_TRIANGLE_FAN);
    glVertexAttrib2f(0, 0.2f, 0.0f);
    for (i = 0; i <= 12; i++) {
        float a = (float)i * 3.14159265f / 6.0f;
        glVertexAttrib2f(0, 0.2f + 0.7f * cosf(a), 0.7f * sinf(a));
    }
    glEnd();
    glUseProgram(0);
    sgl_text(out, "draw", "err 0x%04x\n", glGetError());
    glFinish();
    sgl_image(out, "image", FW, FH, 4, "RGBA", FW * 4, 1, buf);
    return sgl_end_scene(ctx, buf);
}
