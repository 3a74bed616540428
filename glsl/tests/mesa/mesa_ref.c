/* The reference GLSL compiler for softgl-glsl's tests: Mesa's own, through OSMesa.
 *
 * Usage: mesa_ref core|compat MAJOR MINOR
 * Creates an OSMesa context of that profile and version (a compatibility context of
 * version 2.1 or 3.0 for GLSL 1.10 to 1.30, a core one of 3.2 or 3.3 for 1.50 and 3.30),
 * then reads records from stdin until end of file:
 *     <stage> <byte count>\n<source bytes>
 * where stage is `vert`, `frag` or `link` (`link` has no source: it links the shaders
 * compiled since the previous `link` into one program). For each record it writes
 *     <status> <byte count>\n<info log bytes>\n
 * where status is 1 when the compile (or link) succeeded and 0 when it failed.
 * Exit status 2 when the context cannot be made (the log says why). */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "gl_procs.h"


static void reply(int ok, const char *log, int n) {
    printf("%d %d\n", ok, n);
    fwrite(log, 1, (size_t)n, stdout);
    printf("\n");
    fflush(stdout);
}

int main(int argc, char **argv) {
    if (argc != 4) {
        fprintf(stderr, "usage: mesa_ref core|compat MAJOR MINOR\n");
        return 2;
    }
    int core = strcmp(argv[1], "core") == 0;
    int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                     OSMESA_PROFILE, core ? OSMESA_CORE_PROFILE : OSMESA_COMPAT_PROFILE,
                     OSMESA_CONTEXT_MAJOR_VERSION, atoi(argv[2]),
                     OSMESA_CONTEXT_MINOR_VERSION, atoi(argv[3]), 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, NULL);
    static unsigned char buf[4 * 4 * 4];
    if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 4, 4)) {
        fprintf(stderr, "mesa_ref: no %s %s.%s context\n", argv[1], argv[2], argv[3]);
        return 2;
    }
    CreateShader create = (CreateShader)proc("glCreateShader");
    ShaderSource source = (ShaderSource)proc("glShaderSource");
    CompileShader compile = (CompileShader)proc("glCompileShader");
    GetShaderiv shaderiv = (GetShaderiv)proc("glGetShaderiv");
    GetInfoLog shader_log = (GetInfoLog)proc("glGetShaderInfoLog");
    DeleteObject delete_shader = (DeleteObject)proc("glDeleteShader");
    CreateProgram create_program = (CreateProgram)proc("glCreateProgram");
    AttachShader attach = (AttachShader)proc("glAttachShader");
    LinkProgram link = (LinkProgram)proc("glLinkProgram");
    GetShaderiv programiv = (GetShaderiv)proc("glGetProgramiv");
    GetInfoLog program_log = (GetInfoLog)proc("glGetProgramInfoLog");
    DeleteObject delete_program = (DeleteObject)proc("glDeleteProgram");

    GLuint pending[64];
    int npending = 0;
    char stage[16];
    long len;
    while (scanf("%15s %ld", stage, &len) == 2) {
        if (getchar() != '\n' || len < 0) {
            fprintf(stderr, "mesa_ref: bad record\n");
            return 2;
        }
        char *src = malloc((size_t)len + 1);
        if (fread(src, 1, (size_t)len, stdin) != (size_t)len) {
            fprintf(stderr, "mesa_ref: short record\n");
            return 2;
        }
        src[len] = 0;
        GLint ok = 0, n = 0;
        if (strcmp(stage, "link") == 0) {
            GLuint p = create_program();
            for (int i = 0; i < npending; i++) attach(p, pending[i]);
            link(p);
            programiv(p, GL_LINK_STATUS_, &ok);
            programiv(p, GL_INFO_LOG_LENGTH_, &n);
            char *log = calloc((size_t)n + 1, 1);
            GLsizei got = 0;
            if (n > 0) program_log(p, n, &got, log);
            reply(ok != 0, log, got);
            free(log);
            delete_program(p);
            for (int i = 0; i < npending; i++) delete_shader(pending[i]);
            npending = 0;
        } else {
            GLenum type = strcmp(stage, "vert") == 0 ? GL_VERTEX_SHADER_ : GL_FRAGMENT_SHADER_;
            GLuint s = create(type);
            const char *srcs[1] = {src};
            GLint lens[1] = {(GLint)len};
            source(s, 1, srcs, lens);
            compile(s);
            shaderiv(s, GL_COMPILE_STATUS_, &ok);
            shaderiv(s, GL_INFO_LOG_LENGTH_, &n);
            char *log = calloc((size_t)n + 1, 1);
            GLsizei got = 0;
            if (n > 0) shader_log(s, n, &got, log);
            reply(ok != 0, log, got);
            free(log);
            if (npending < 64) pending[npending++] = s;
            else delete_shader(s);
        }
        free(src);
    }
    OSMesaDestroyContext(ctx);
    return 0;
}
