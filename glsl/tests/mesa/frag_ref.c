/* The reference pixels for softgl's shader lowering: Mesa's llvmpipe through OSMesa.
 *
 * Usage: frag_ref WIDTH HEIGHT
 * Makes a compatibility context (2.1 or later) drawing into a GL_FLOAT RGBA buffer of
 * WIDTH x HEIGHT, then reads jobs from stdin until end of file. A job is records:
 *     vert <byte count>\n<source>       the vertex shader
 *     frag <byte count>\n<source>       the fragment shader
 *     uni <name> <kind> <n> <hex bits>...\n   a uniform: kind f (floats: glUniform{n}fv),
 *                                        i (ints: glUniform{n}iv) or m (a matrix of n
 *                                        columns: glUniformMatrix{n}fv)
 *     tex <16 hex float bits>\n          gl_MultiTexCoord0 of the four corners
 *     draw\n                             link, set the uniforms, clear to the sentinel
 *                                        (0.125, 0.25, 0.375, 0.5), draw the full-window
 *                                        quad (-1,-1) (1,-1) (1,1) (-1,1) and reply
 * The reply is `ok <bytes>\n` and WIDTH * HEIGHT * 4 floats (rows bottom-up, RGBA), or
 * `err <bytes>\n<log>`. Exit status 2 when the context cannot be made. */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "gl_procs.h"

typedef void (*UseProgram)(GLuint);
typedef GLint (*GetUniformLocation)(GLuint, const char *);
typedef void (*UniformFv)(GLint, GLsizei, const GLfloat *);
typedef void (*UniformIv)(GLint, GLsizei, const GLint *);
typedef void (*UniformMat)(GLint, GLsizei, GLboolean, const GLfloat *);
typedef void (*MultiTexCoord4f)(GLenum, GLfloat, GLfloat, GLfloat, GLfloat);
#define GL_TEXTURE0_ 0x84C0

static char *read_source(long len) {
    char *src = malloc((size_t)len + 1);
    if (fread(src, 1, (size_t)len, stdin) != (size_t)len) {
        fprintf(stderr, "frag_ref: short record\n");
        exit(2);
    }
    src[len] = 0;
    return src;
}

static float from_bits(unsigned u) {
    float f;
    memcpy(&f, &u, 4);
    return f;
}

struct uniform {
    char name[64];
    char kind;
    int n;
    unsigned bits[16];
};

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: frag_ref WIDTH HEIGHT\n");
        return 2;
    }
    int w = atoi(argv[1]), h = atoi(argv[2]);
    int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0,
                     OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                     OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 0, 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);
    float *buf = calloc((size_t)w * h * 4, sizeof(float));
    if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_FLOAT, w, h)) {
        fprintf(stderr, "frag_ref: no float context\n");
        return 2;
    }
    CreateShader create = (CreateShader)proc("glCreateShader");
    ShaderSource source = (ShaderSource)proc("glShaderSource");
    CompileShader compile = (CompileShader)proc("glCompileShader");
    GetShaderiv shaderiv = (GetShaderiv)proc("glGetShaderiv");
    GetInfoLog shader_log = (GetInfoLog)proc("glGetShaderInfoLog");
    CreateProgram create_program = (CreateProgram)proc("glCreateProgram");
    AttachShader attach = (AttachShader)proc("glAttachShader");
    LinkProgram link = (LinkProgram)proc("glLinkProgram");
    GetShaderiv programiv = (GetShaderiv)proc("glGetProgramiv");
    GetInfoLog program_log = (GetInfoLog)proc("glGetProgramInfoLog");
    UseProgram use = (UseProgram)proc("glUseProgram");
    DeleteObject delete_shader = (DeleteObject)proc("glDeleteShader");
    DeleteObject delete_program = (DeleteObject)proc("glDeleteProgram");
    GetUniformLocation location = (GetUniformLocation)proc("glGetUniformLocation");
    UniformFv ufv[5] = {0, (UniformFv)proc("glUniform1fv"), (UniformFv)proc("glUniform2fv"),
                        (UniformFv)proc("glUniform3fv"), (UniformFv)proc("glUniform4fv")};
    UniformIv uiv[5] = {0, (UniformIv)proc("glUniform1iv"), (UniformIv)proc("glUniform2iv"),
                        (UniformIv)proc("glUniform3iv"), (UniformIv)proc("glUniform4iv")};
    UniformMat umat[5] = {0, 0, (UniformMat)proc("glUniformMatrix2fv"),
                          (UniformMat)proc("glUniformMatrix3fv"),
                          (UniformMat)proc("glUniformMatrix4fv")};
    MultiTexCoord4f mtc = (MultiTexCoord4f)proc("glMultiTexCoord4f");

    char *vs = NULL, *fs = NULL;
    struct uniform unis[32];
    int nunis = 0;
    unsigned tex[16] = {0};
    char tag[16];
    while (scanf("%15s", tag) == 1) {
        if (!strcmp(tag, "vert") || !strcmp(tag, "frag")) {
            long len;
            if (scanf("%ld", &len) != 1 || getchar() != '\n') return 2;
            char *s = read_source(len);
            if (tag[0] == 'v') { free(vs); vs = s; } else { free(fs); fs = s; }
        } else if (!strcmp(tag, "uni")) {
            struct uniform *u = &unis[nunis < 32 ? nunis++ : 31];
            if (scanf("%63s %c %d", u->name, &u->kind, &u->n) != 3) return 2;
            int count = u->kind == 'm' ? u->n * u->n : u->n;
            for (int i = 0; i < count && i < 16; i++)
                if (scanf("%x", &u->bits[i]) != 1) return 2;
        } else if (!strcmp(tag, "tex")) {
            for (int i = 0; i < 16; i++)
                if (scanf("%x", &tex[i]) != 1) return 2;
        } else if (!strcmp(tag, "draw")) {
            GLuint sh[2];
            const char *srcs[2] = {vs ? vs : "", fs ? fs : ""};
            GLenum types[2] = {GL_VERTEX_SHADER_, GL_FRAGMENT_SHADER_};
            GLuint prog = create_program();
            char log[4096] = "";
            GLsizei got = 0;
            int ok = 1;
            for (int i = 0; i < 2; i++) {
                GLint st = 0;
                sh[i] = create(types[i]);
                source(sh[i], 1, &srcs[i], NULL);
                compile(sh[i]);
                shaderiv(sh[i], GL_COMPILE_STATUS_, &st);
                if (!st && ok) {
                    shader_log(sh[i], sizeof log, &got, log);
                    ok = 0;
                }
                attach(prog, sh[i]);
            }
            if (ok) {
                GLint st = 0;
                link(prog);
                programiv(prog, GL_LINK_STATUS_, &st);
                if (!st) {
                    program_log(prog, sizeof log, &got, log);
                    ok = 0;
                }
            }
            if (!ok) {
                printf("err %d\n", (int)got);
                fwrite(log, 1, (size_t)got, stdout);
            } else {
                use(prog);
                for (int i = 0; i < nunis; i++) {
                    struct uniform *u = &unis[i];
                    GLint loc = location(prog, u->name);
                    float f[16];
                    GLint iv[16];
                    for (int k = 0; k < 16; k++) {
                        f[k] = from_bits(u->bits[k]);
                        iv[k] = (GLint)u->bits[k];
                    }
                    if (u->kind == 'f') ufv[u->n](loc, 1, f);
                    else if (u->kind == 'i') uiv[u->n](loc, 1, iv);
                    else umat[u->n](loc, 1, GL_FALSE, f);
                }
                glViewport(0, 0, w, h);
                glClearColor(0.125f, 0.25f, 0.375f, 0.5f);
                glClear(GL_COLOR_BUFFER_BIT);
                static const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
                glBegin(GL_QUADS);
                for (int v = 0; v < 4; v++) {
                    mtc(GL_TEXTURE0_, from_bits(tex[4 * v]), from_bits(tex[4 * v + 1]),
                        from_bits(tex[4 * v + 2]), from_bits(tex[4 * v + 3]));
                    glVertex2f(corner[v][0], corner[v][1]);
                }
                glEnd();
                glFinish();
                size_t bytes = (size_t)w * h * 4 * sizeof(float);
                printf("ok %zu\n", bytes);
                fwrite(buf, 1, bytes, stdout);
                use(0);
            }
            fflush(stdout);
            for (int i = 0; i < 2; i++) delete_shader(sh[i]);
            delete_program(prog);
            nunis = 0;
        } else {
            fprintf(stderr, "frag_ref: bad record %s\n", tag);
            return 2;
        }
    }
    OSMesaDestroyContext(ctx);
    return 0;
}
