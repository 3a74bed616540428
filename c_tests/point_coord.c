/* point_coord: gl_PointCoord (GLSL 1.10+) and a vertex shader's gl_PointSize
 * (GL_VERTEX_PROGRAM_POINT_SIZE).  A fragment shader colours points by
 * gl_PointCoord: sprites with the origin upper-left and lower-left, in the
 * window and in a framebuffer object (rows not flipped), and ordinary points
 * (GL_POINT_SPRITE off).  A vertex
 * shader writes gl_PointSize from an attribute (sizes 0.4 .. 300, so below one
 * pixel and above the largest point), with GL_VERTEX_PROGRAM_POINT_SIZE on (the
 * shader's size) and off (glPointSize), and the enable's query; sizes that
 * are NaN, infinite, negative, zero or tiny. */
#define GL_GLEXT_PROTOTYPES
#include "prims_common.h"
#include <GL/glext.h>
#include "vert_program.h"

static const char *FS =
    "#version 120\n"
    "void main() {\n"
    "  vec2 p = gl_PointCoord;\n"
    "  float ring = step(0.25, abs(length(p - 0.5) - 0.3));\n"
    "  gl_FragColor = vec4(p, gl_Color.b * ring, 1.0);\n"
    "}\n";

static const char *VS =
    "#version 120\n"
    "attribute float psize;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_PointSize = psize;\n"
    "  gl_FrontColor = gl_Color;\n"
    "}\n";

/* A vertex shader whose point size is a uniform (NaN, infinities, huge, negative). */
static const char *VS_UNIFORM =
    "#version 120\n"
    "uniform float s;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_PointSize = s;\n"
    "  gl_FrontColor = gl_Color;\n"
    "}\n";

/* Points of sizes 1 .. 31 at centres with varied fractions. */
static void fs_points(void)
{
    static const float fx[4] = {0.5f, 0.0f, 0.3f, 0.75f};
    int i;
    for (i = 0; i < 24; i++) {
        float size = 1.0f + 1.3f * (float)i;
        glPointSize(size);
        glBegin(GL_POINTS);
        prims_color(i);
        glVertex2f(12.0f + (float)((i % 6) * 40) + fx[i % 4],
                   14.0f + (float)((i / 6) * 58) + fx[(i + 1) % 4]);
        glEnd();
    }
}

/* One glDrawArrays of points (the first, of size 300, under the rest) whose sizes come from the `psize` attribute array
 * (location 1). */
static void vs_points(void)
{
    static const float sizes[16] = {300.0f, 1.0f,  1.6f,  2.5f,  3.0f, 5.5f, 8.0f, 12.25f,
                                    17.0f,  23.5f, 31.0f, 40.0f, 0.75f, 6.0f, 0.4f, 2.0f};
    static float pos[16 * 2], col[16 * 3];
    int i;
    for (i = 0; i < 16; i++) {
        float x = 16.0f + (float)((i % 5) * 52) + 0.25f * (float)(i % 3);
        float y = 20.0f + (float)((i / 5) * 60) + 0.3f * (float)(i % 4);
        pos[2 * i] = i == 0 ? 128.0f : x;
        pos[2 * i + 1] = i == 0 ? 128.5f : y;
        col[3 * i] = (float)((i * 53) % 256) / 255.0f;
        col[3 * i + 1] = (float)((i * 97 + 80) % 256) / 255.0f;
        col[3 * i + 2] = (float)((i * 151 + 40) % 256) / 255.0f;
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableVertexAttribArray(1);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glColorPointer(3, GL_FLOAT, 0, col);
    glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, 0, sizes);
    glDrawArrays(GL_POINTS, 0, 16);
    glDisableVertexAttribArray(1);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
}

static void read_fbo(FILE *out, const char *name)
{
    static unsigned char px[PW * PH * 4];
    glReadPixels(0, 0, PW, PH, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_image(out, name, PW, PH, 4, "RGBA", PW * 4, 1, px);
}

int main(int argc, char **argv)
{
    static const char *attribs[] = {"unused0", "psize", NULL};
    FILE *out = sgl_open(argc, argv);
    GLuint fb, rb, fprog, vprog, uprog;
    float zero = 0.0f;
    const float hostile[6] = {zero / zero, -1.0f / zero, -5.0f, 0.0f, 1e-30f, 1.0f / zero};
    int i;
    GLint on = -1;

    prims_begin();
    fprog = frag_program(FS);
    vprog = vert_program(VS, FS, attribs);

    /* sprites in the window, both origins */
    glUseProgram(fprog);
    glEnable(GL_POINT_SPRITE);
    fs_points();
    prims_end(out, "window_upper");
    glClear(GL_COLOR_BUFFER_BIT);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    fs_points();
    prims_end(out, "window_lower");

    /* ordinary points (no sprite) still see gl_PointCoord */
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_POINT_SPRITE);
    fs_points();
    prims_end(out, "no_sprite");

    /* a framebuffer object */
    glGenFramebuffers(1, &fb);
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, PW, PH);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    SGL_CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
    glEnable(GL_POINT_SPRITE);
    glClear(GL_COLOR_BUFFER_BIT);
    fs_points();
    read_fbo(out, "fbo_lower");
    glClear(GL_COLOR_BUFFER_BIT);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
    fs_points();
    read_fbo(out, "fbo_upper");
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_POINT_SPRITE);
    fs_points();
    read_fbo(out, "fbo_no_sprite");

    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    /* the vertex shader's size, with the enable off (glPointSize 7) and on */
    glUseProgram(vprog);
    glGetIntegerv(GL_VERTEX_PROGRAM_POINT_SIZE, &on);
    sgl_text(out, "default", "enable %d %d err 0x%x\n", on,
             glIsEnabled(GL_VERTEX_PROGRAM_POINT_SIZE), glGetError());
    glClear(GL_COLOR_BUFFER_BIT);
    glPointSize(7.0f);
    vs_points();
    prims_end(out, "vs_size_off");
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_VERTEX_PROGRAM_POINT_SIZE);
    glGetIntegerv(GL_VERTEX_PROGRAM_POINT_SIZE, &on);
    sgl_text(out, "enabled", "enable %d %d err 0x%x\n", on,
             glIsEnabled(GL_VERTEX_PROGRAM_POINT_SIZE), glGetError());
    vs_points();
    prims_end(out, "vs_size_sprites");
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_POINT_SPRITE);
    vs_points();
    prims_end(out, "vs_size_points");

    /* sizes that are not numbers or not positive draw one pixel; infinity the largest */
    uprog = vert_program(VS_UNIFORM, FS, NULL);
    glUseProgram(uprog);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_POINT_SPRITE);
    for (i = 0; i < 6; i++) {
        glUniform1f(glGetUniformLocation(uprog, "s"), hostile[i]);
        glBegin(GL_POINTS);
        prims_color(i);
        glVertex2f(20.0f + 40.0f * (float)i, 30.5f);
        glVertex2f(20.0f + 40.0f * (float)i, 1e7f);
        glEnd();
    }
    prims_end(out, "vs_size_hostile");
    glUseProgram(0);

    prims_close(out);
    return 0;
}
