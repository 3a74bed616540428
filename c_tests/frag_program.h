/* frag_program.h - what the fragment-program scenes (frag_*.c) share: a
 * program of one fragment shader (no vertex shader: the fixed-function vertex
 * stage feeds gl_Color, gl_TexCoord[] and gl_FragCoord), linked or the scene
 * fails with the log on stderr; an FW x FH (default 128x128) RGBA context with a 24-bit depth
 * buffer; perspective and orthographic helpers; and the image and depth
 * output. Include after the GL, glext and OSMesa headers. */
#ifndef SGL_FRAG_PROGRAM_H
#define SGL_FRAG_PROGRAM_H

#include "common.h"

#ifndef FW
#define FW 128
#define FH 128
#endif

/* Compiles and links `fs` as the only shader of a program. */
static inline GLuint frag_program(const char *fs)
{
    GLuint s = glCreateShader(GL_FRAGMENT_SHADER), p = glCreateProgram();
    GLint ok = 0;
    char log[2048];
    glShaderSource(s, 1, &fs, NULL);
    glCompileShader(s);
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    glGetShaderInfoLog(s, sizeof log, NULL, log);
    if (ok) {
        glAttachShader(p, s);
        glLinkProgram(p);
        glGetProgramiv(p, GL_LINK_STATUS, &ok);
        glGetProgramInfoLog(p, sizeof log, NULL, log);
    }
    if (!ok) {
        fprintf(stderr, "compile or link: %s\n", log);
        exit(2);
    }
    return p;
}

/* A context drawing into a fresh FW x FH RGBA buffer with depth. */
static inline OSMesaContext frag_context(unsigned char **buf)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    SGL_CHECK(ctx != NULL);
    *buf = malloc(FW * FH * 4);
    SGL_CHECK(*buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, *buf, GL_UNSIGNED_BYTE, FW, FH));
    return ctx;
}

/* A perspective view of the box [-1,1]^2 at depth -3 .. -1 (w varies). */
static inline void frag_perspective(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -2.0f);
}

/* The colour image and the depth buffer as read back. */
static inline void frag_output(FILE *out, const char *name, const unsigned char *buf)
{
    static GLuint depth[FW * FH];
    char dn[64];
    glFinish();
    sgl_image(out, name, FW, FH, 4, "RGBA", FW * 4, 1, buf);
    glReadPixels(0, 0, FW, FH, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    snprintf(dn, sizeof dn, "%s_depth", name);
    sgl_data(out, dn, sizeof depth, depth);
}

/* The output, then the end of the scene: closes the file, frees the context. */
static inline int frag_end(FILE *out, const char *name, unsigned char *buf, OSMesaContext ctx)
{
    frag_output(out, name, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}

/* Sets sampler uniform `name` of `p` to unit `u` (and leaves `p` current). */
static inline void frag_set_unit(GLuint p, const char *name, int u)
{
    glUseProgram(p);
    glUniform1i(glGetUniformLocation(p, name), u);
}

/* An RGBA image of w x h with a seeded pattern (checks and noise). */
static inline void frag_pattern(unsigned char *img, int w, int h, int salt)
{
    int x, y;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            unsigned char *p = img + 4 * (y * w + x);
            int check = ((x / 4) ^ (y / 4) ^ salt) & 1;
            p[0] = (unsigned char)(check ? 230 : 40 + 3 * x);
            p[1] = (unsigned char)((x * 255) / (w > 1 ? w - 1 : 1));
            p[2] = (unsigned char)((y * 255) / (h > 1 ? h - 1 : 1));
            p[3] = (unsigned char)(128 + (int)(sgl_randf() * 127.0f));
        }
}

/* Binds `tex` as a 64x64 2D texture of frag_pattern levels (salted by level)
 * down to 1x1, LINEAR_MIPMAP_LINEAR; `img` holds at least 64x64 RGBA. */
static inline void frag_mipmapped_texture(GLuint tex, unsigned char *img)
{
    int level, size;
    glBindTexture(GL_TEXTURE_2D, tex);
    for (level = 0, size = 64; size >= 1; level++, size /= 2) {
        frag_pattern(img, size, size, level);
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

/* Binds `tex` as a 16x16 LINEAR cube map of frag_pattern faces (salted by
 * face; `img` holds at least 16x16 RGBA). */
static inline void frag_cube_texture(GLuint tex, unsigned char *img)
{
    int face;
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    for (face = 0; face < 6; face++) {
        frag_pattern(img, 16, 16, face);
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RGBA, 16, 16, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, img);
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

/* Binds `tex` as a size x size 2D texture of frag_pattern(salt), stored as
 * `internal`, with the given minification and magnification filters. */
static inline void frag_pattern_texture(GLuint tex, unsigned char *img, int size, int salt,
                                        GLenum internal, GLenum min, GLenum mag)
{
    glBindTexture(GL_TEXTURE_2D, tex);
    frag_pattern(img, size, size, salt);
    glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internal, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)min);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)mag);
}

/* Binds `tex` as a 32x32 LINEAR DEPTH_COMPONENT24 2D texture (a saddle of
 * depths around 0.5) compared with GL_LEQUAL. */
static inline void frag_depth_texture(GLuint tex)
{
    static float depth[32 * 32];
    int x, y;
    glBindTexture(GL_TEXTURE_2D, tex);
    for (y = 0; y < 32; y++)
        for (x = 0; x < 32; x++)
            depth[y * 32 + x] = 0.5f + 0.4f * (float)((x - 16) * (y - 12)) / 256.0f;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 32, 32, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 depth);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

/* Binds a new complete FW x FH framebuffer object: a `color_format` colour
 * renderbuffer and a `depth_format` one at `attachment` (the scene fails when
 * it is incomplete). Needs GL_GLEXT_PROTOTYPES. */
static inline GLuint frag_fbo_of(GLenum color_format, GLenum depth_format, GLenum attachment)
{
    GLuint fbo, rb[2];
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(2, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, color_format, FW, FH);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, depth_format, FW, FH);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, attachment, GL_RENDERBUFFER, rb[1]);
    SGL_CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
    return fbo;
}

/* frag_fbo_of with an RGBA8 colour renderbuffer. */
static inline GLuint frag_fbo(GLenum depth_format, GLenum attachment)
{
    return frag_fbo_of(GL_RGBA8, depth_format, attachment);
}

/* n seeded random triangles in [-1.2,1.2]^2 x [-1,1] (defined below). */
static inline void frag_random_tris(int n);

/* Draws with `draw(progs, n)` into the window and outputs it as "window",
 * then into a new frag_fbo with 24-bit depth (rows not flipped), read back as
 * "fbo"; rebinds the window and outputs the GL error as "error". `rb` holds
 * FW x FH RGBA. */
static inline void frag_window_and_fbo(FILE *out, const unsigned char *buf, unsigned char *rb,
                                       void (*draw)(const GLuint *, int), const GLuint *progs,
                                       int n)
{
    draw(progs, n);
    frag_output(out, "window", buf);
    frag_fbo(GL_DEPTH_COMPONENT24, GL_DEPTH_ATTACHMENT);
    draw(progs, n);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, rb);
    sgl_image(out, "fbo", FW, FH, 4, "RGBA", FW * 4, 1, rb);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    sgl_text(out, "error", "0x%x", glGetError());
}

/* Starts a frame: clears colour (0.1, 0.2, 0.3, 0.4) and depth, sets
 * frag_perspective() and the depth test with `depth_func`. */
static inline void frag_begin_frame(GLenum depth_func)
{
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth_func);
}

/* The main of a scene of `n` programs (at most 16): opens the output, makes the
 * context, lets `make` create the programs (it may also write blocks to `out`), draws
 * with frag_window_and_fbo and ends the scene. */
static inline int frag_scene_main(int argc, char **argv, int n,
                                  void (*make)(GLuint *progs, FILE *out),
                                  void (*draw)(const GLuint *, int))
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    static unsigned char rb[FW * FH * 4];
    GLuint progs[16];
    SGL_CHECK(n <= 16);
    make(progs, out);
    frag_window_and_fbo(out, buf, rb, draw, progs, n);
    return frag_end(out, "end", buf, ctx);
}

/* Clears colour and depth, sets frag_perspective() and the depth test
 * (GL_LESS), and draws `tris` seeded random triangles with each of the `n`
 * programs in turn (the last stays current). */
static inline void frag_each_program(const GLuint *progs, int n, int tris)
{
    int i;
    frag_begin_frame(GL_LESS);
    for (i = 0; i < n; i++) {
        glUseProgram(progs[i]);
        frag_random_tris(tris);
    }
}

/* A triangle with per-vertex colours and texture coordinates (sets 0 and 1). */
static inline void frag_tri(const float v[3][3], const float c[3][4], const float t[3][4])
{
    int k;
    glBegin(GL_TRIANGLES);
    for (k = 0; k < 3; k++) {
        glColor4fv(c[k]);
        glMultiTexCoord4fv(GL_TEXTURE0, t[k]);
        glMultiTexCoord4f(GL_TEXTURE1, t[k][1], t[k][0], t[k][3], 1.0f);
        glVertex3fv(v[k]);
    }
    glEnd();
}

/* n seeded random triangles in [-1.2,1.2]^2 x [-1,1] with colours and coordinates. */
static inline void frag_random_tris(int n)
{
    int i, k, j;
    for (i = 0; i < n; i++) {
        float v[3][3], c[3][4], t[3][4];
        for (k = 0; k < 3; k++) {
            v[k][0] = sgl_randf() * 2.4f - 1.2f;
            v[k][1] = sgl_randf() * 2.4f - 1.2f;
            v[k][2] = sgl_randf() * 2.0f - 1.0f;
            for (j = 0; j < 4; j++) {
                c[k][j] = sgl_randf();
                t[k][j] = sgl_randf() * 4.0f - 2.0f;
            }
        }
        frag_tri(v, c, t);
    }
}

#endif
