/* vert_program.h - what the vertex-program scenes (vert_*.c) share: a program
 * of a vertex shader and, unless NULL, a fragment shader (attribute locations
 * bound before the link from a NULL-terminated name list), linked or the scene
 * fails with the log on stderr; plus the context, projection and output
 * helpers of frag_program.h. Include after the GL, glext and OSMesa headers. */
#ifndef SGL_VERT_PROGRAM_H
#define SGL_VERT_PROGRAM_H

#include "frag_program.h"

/* Compiles `src` as a shader of `kind` and attaches it to `p`. */
static inline void vert_attach(GLuint p, GLenum kind, const char *src)
{
    GLuint s = glCreateShader(kind);
    GLint ok = 0;
    char log[2048];
    glShaderSource(s, 1, &src, NULL);
    glCompileShader(s);
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "compile: %s\n", log);
        exit(2);
    }
    glAttachShader(p, s);
}

/* Starts a frame of the vertex-input scenes: clears colour (0.1, 0.2, 0.3, 0.4) and
 * depth, projects w x h pixel units orthographically (identity modelview) and tests
 * depth with GL_LESS. */
static inline void vert_begin_ortho(double w, double h)
{
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, w, 0.0, h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
}

/* Links `p`; prints the log and exits on failure. */
static inline void vert_link(GLuint p)
{
    GLint ok = 0;
    char log[2048];
    glLinkProgram(p);
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        glGetProgramInfoLog(p, sizeof log, NULL, log);
        fprintf(stderr, "link: %s\n", log);
        exit(2);
    }
}

/* A program of `vs` and `fs` (NULL: fixed-function fragments); `attribs[k]`
 * bound to location k (NULL-terminated, or NULL for none). */
static inline GLuint vert_program(const char *vs, const char *fs, const char **attribs)
{
    GLuint p = glCreateProgram();
    int k;
    vert_attach(p, GL_VERTEX_SHADER, vs);
    if (fs)
        vert_attach(p, GL_FRAGMENT_SHADER, fs);
    for (k = 0; attribs && attribs[k]; k++)
        glBindAttribLocation(p, (GLuint)k, attribs[k]);
    vert_link(p);
    return p;
}

/* The body of a vertex-input scene's main once its programs exist: runs `setup` and
 * logs its error, draws the window and the framebuffer object with `draw`, runs
 * `queries`, and draws the window once more (image "again", after the queries'
 * errors). */
static inline void vert_scene_body(FILE *out, unsigned char *buf, unsigned char *rb,
                                   void (*setup)(void), void (*draw)(const GLuint *, int),
                                   void (*queries)(void))
{
    setup();
    sgl_text(out, "setup", "err 0x%04x\n", glGetError());
    frag_window_and_fbo(out, buf, rb, draw, NULL, 0);
    queries();
    draw(NULL, 0);
    frag_output(out, "again", buf);
}

/* A new buffer object bound to GL_ARRAY_BUFFER holding `bytes` of `v`: vertices of
 * `stride` bytes, three position floats then three colour floats, as the enabled
 * vertex and colour arrays. */
static inline GLuint vert_color_vbo(const void *v, GLsizeiptr bytes, GLsizei stride)
{
    GLuint vbo;
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, bytes, v, GL_STATIC_DRAW);
    glVertexPointer(3, GL_FLOAT, stride, (void *)0);
    glColorPointer(3, GL_FLOAT, stride, (void *)(3 * sizeof(GLfloat)));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    return vbo;
}

/* n seeded random triangles (as frag_random_tris) that also carry normals and
 * secondary colours. */
static inline void vert_random_tris(int n)
{
    int i, k, j;
    glBegin(GL_TRIANGLES);
    for (i = 0; i < n; i++) {
        for (k = 0; k < 3; k++) {
            float c[4], t[4];
            for (j = 0; j < 4; j++) {
                c[j] = sgl_randf();
                t[j] = sgl_randf() * 4.0f - 2.0f;
            }
            glColor4fv(c);
            glSecondaryColor3f(c[2], c[0], c[1]);
            glNormal3f(t[0], t[1], t[2] + 0.5f);
            glMultiTexCoord4fv(GL_TEXTURE0, t);
            glMultiTexCoord4f(GL_TEXTURE1, t[1], t[0], t[3], 1.0f);
            glVertex3f(sgl_randf() * 2.4f - 1.2f, sgl_randf() * 2.4f - 1.2f,
                       sgl_randf() * 2.0f - 1.0f);
        }
    }
    glEnd();
}

#endif
