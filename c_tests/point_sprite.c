/* point_sprite: GL_POINT_SPRITE (GL 2.0, ARB_point_sprite).  Textured sprites of
 * sizes 1 .. 40 at fractional centres with GL_COORD_REPLACE on unit 0, with the
 * coordinate origin GL_UPPER_LEFT and GL_LOWER_LEFT, in the window and in a
 * framebuffer object (whose rows are not flipped); a mipmapped texture (the
 * sprite's size picks the level); unit 1 replaced while unit 0 keeps its vertex
 * coordinate; perspective points (w != 1) with distance attenuation; sprites
 * with GL_POINT_SMOOTH also on (the sprite wins); GL_POINT polygons; a 4-sample
 * object; a fragment shader reading gl_TexCoord[0]; COORD_REPLACE with the
 * sprite enable off (ordinary points); and the queries, GL_POINT_BIT and errors. */
#define GL_GLEXT_PROTOTYPES
#include "prims_common.h"
#include <GL/glext.h>

/* A 16x16 mipmapped texture: a different pattern and tint per level, so that the
 * level a sprite picks and where its coordinates run both show. */
static void mip_texture(void)
{
    static unsigned char px[16 * 16 * 4];
    int level, size, x, y;
    for (level = 0, size = 16; size >= 1; level++, size /= 2) {
        for (y = 0; y < size; y++)
            for (x = 0; x < size; x++) {
                unsigned char *p = px + (y * size + x) * 4;
                p[0] = (unsigned char)(x * 255 / (size > 1 ? size - 1 : 1));
                p[1] = (unsigned char)(y * 255 / (size > 1 ? size - 1 : 1));
                p[2] = (unsigned char)(((x ^ y) & 1) ? 255 - 40 * level : 40 * level);
                p[3] = 255;
            }
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, size, size, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, px);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

/* Sprites of sizes 1 .. 40 in rows, at centres with varied fractions (some on pixel
 * centres and corners, where the fill rule decides). */
static void sizes(void)
{
    static const float fx[4] = {0.5f, 0.0f, 0.3f, 0.75f};
    int i;
    glBegin(GL_POINTS);
    for (i = 0; i < 40; i++) {
        float size = 1.0f + (float)i;
        float x = 8.0f + (float)((i % 8) * 31) + fx[i % 4];
        float y = 10.0f + (float)((i / 8) * 48) + fx[(i + 1) % 4];
        if (i > 0) {
            glEnd();
            glPointSize(size);
            glBegin(GL_POINTS);
        } else {
            glPointSize(size);
        }
        prims_color(i);
        glVertex2f(x + size * 0.3f, y);
    }
    glEnd();
    /* sprites thinner than a pixel are one pixel wide */
    for (i = 0; i < 12; i++) {
        glPointSize(0.15f + 0.07f * (float)i);
        glBegin(GL_POINTS);
        prims_color(40 + i);
        glVertex2f(6.0f + 20.0f * (float)i + fx[i % 4], 250.0f - fx[(i + 2) % 4]);
        glEnd();
    }
}

/* A perspective row of points at eye distances 1.5 .. 20 (w varies). */
static void perspective_row(float ndc_y)
{
    int i;
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    glBegin(GL_POINTS);
    for (i = 0; i < 10; i++) {
        float d = 1.5f + 2.1f * (float)i;
        float x = -0.85f + 0.19f * (float)i;
        prims_color(3 * i);
        glVertex3f(x * d, ndc_y * d, -d);
    }
    glEnd();
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
}

static const char *FS =
    "#version 110\n"
    "uniform sampler2D t;\n"
    "void main() {\n"
    "  vec4 c = texture2D(t, gl_TexCoord[0].st);\n"
    "  gl_FragColor = vec4(c.rg * 0.5 + gl_TexCoord[0].st * 0.5, c.b * gl_Color.g,\n"
    "                      1.0);\n"
    "}\n";

static GLuint shader_program(void)
{
    GLuint s = glCreateShader(GL_FRAGMENT_SHADER), p = glCreateProgram();
    GLint ok = 0;
    glShaderSource(s, 1, &FS, NULL);
    glCompileShader(s);
    glAttachShader(p, s);
    glLinkProgram(p);
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    SGL_CHECK(ok);
    return p;
}

/* Reads the bound framebuffer object (PW x PH) as an image. */
static void read_fbo(FILE *out, const char *name)
{
    static unsigned char px[PW * PH * 4];
    glReadPixels(0, 0, PW, PH, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_image(out, name, PW, PH, 4, "RGBA", PW * 4, 1, px);
}

static void state(FILE *out, const char *name)
{
    GLint sprite = -1, origin = -1, rep0 = -1, rep1 = -1;
    glGetIntegerv(GL_POINT_SPRITE, &sprite);
    glGetIntegerv(GL_POINT_SPRITE_COORD_ORIGIN, &origin);
    glActiveTexture(GL_TEXTURE0);
    glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &rep0);
    glActiveTexture(GL_TEXTURE1);
    glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &rep1);
    glActiveTexture(GL_TEXTURE0);
    sgl_text(out, name, "sprite %d enabled %d origin 0x%x replace %d %d err 0x%x\n", sprite,
             glIsEnabled(GL_POINT_SPRITE), origin, rep0, rep1, glGetError());
}

int main(int argc, char **argv)
{
    static const GLfloat atten[3] = {0.0f, 0.3f, 0.0f};
    static const GLfloat none[3] = {1.0f, 0.0f, 0.0f};
    FILE *out = sgl_open(argc, argv);
    GLuint tex[2], fb[2], rb[3], prog;
    GLint errs[8];
    GLfloat f = -1.0f;
    int i;

    prims_begin();
    state(out, "defaults");
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    mip_texture();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);

    /* COORD_REPLACE alone changes nothing: ordinary points with the vertex coordinate */
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    glTexCoord2f(0.3f, 0.7f);
    sizes();
    prims_end(out, "replace_without_sprite");

    /* sprites, upper-left origin (the default) and lower-left */
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_POINT_SPRITE);
    state(out, "enabled");
    sizes();
    prims_end(out, "window_upper");
    glClear(GL_COLOR_BUFFER_BIT);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    sizes();
    prims_end(out, "window_lower");

    /* unit 1 replaced (a NEAREST copy of the texture), unit 0 keeps its coordinate */
    glClear(GL_COLOR_BUFFER_BIT);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    mip_texture();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    state(out, "unit1");
    glMultiTexCoord2f(GL_TEXTURE0, 0.9f, 0.1f);
    glColor3f(0.4f, 0.4f, 0.4f);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
    sizes();
    prims_end(out, "unit1_replaced");
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);

    /* perspective points with distance attenuation, both origins; smooth is ignored */
    glClear(GL_COLOR_BUFFER_BIT);
    glPointSize(24.0f);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, atten);
    perspective_row(0.6f);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    perspective_row(0.1f);
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    perspective_row(-0.5f);
    glDisable(GL_BLEND);
    glDisable(GL_POINT_SMOOTH);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
    prims_end(out, "perspective");

    /* GL_POINT polygons draw their vertices as sprites */
    glClear(GL_COLOR_BUFFER_BIT);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(13.0f);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2f(30.3f, 40.6f);
    glVertex2f(200.5f, 60.0f);
    glVertex2f(120.25f, 210.75f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    prims_end(out, "polygon_points");

    /* a framebuffer object: rows not flipped, so the origins swap roles */
    glGenFramebuffers(2, fb);
    glGenRenderbuffers(3, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, PW, PH);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    SGL_CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
    glClear(GL_COLOR_BUFFER_BIT);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
    sizes();
    read_fbo(out, "fbo_upper");
    glClear(GL_COLOR_BUFFER_BIT);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    sizes();
    read_fbo(out, "fbo_lower");

    /* a 4-sample object, resolved into the single-sample one */
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, PW, PH);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[2]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, PW, PH);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[1]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              rb[2]);
    SGL_CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    sizes();
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
    glPointSize(24.0f);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, atten);
    perspective_row(-0.8f);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(0, 0, PW, PH, 0, 0, PW, PH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    read_fbo(out, "msaa");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    /* a fragment shader reads the replaced gl_TexCoord[0] */
    glClear(GL_COLOR_BUFFER_BIT);
    prog = shader_program();
    glUseProgram(prog);
    glUniform1i(glGetUniformLocation(prog, "t"), 0);
    sizes();
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    glPointSize(24.0f);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, atten);
    perspective_row(-0.8f);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
    glUseProgram(0);
    prims_end(out, "shader");

    /* GL_POINT_BIT saves the enable, the origin and the replace bits */
    glPushAttrib(GL_POINT_BIT);
    glDisable(GL_POINT_SPRITE);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
    state(out, "pushed");
    glPopAttrib();
    state(out, "popped");
    glGetTexEnvfv(GL_POINT_SPRITE, GL_COORD_REPLACE, &f);

    /* the errors: a bad pname, a bad value, a bad origin, a bad target query */
    glTexEnvi(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, GL_TRUE);
    errs[0] = (GLint)glGetError();
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, 7);
    errs[1] = (GLint)glGetError();
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_FRONT);
    errs[2] = (GLint)glGetError();
    glPointParameterf(GL_POINT_SPRITE_COORD_ORIGIN, 3.0f);
    errs[3] = (GLint)glGetError();
    glGetTexEnviv(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, &i);
    errs[4] = (GLint)glGetError();
    glTexEnvf(GL_POINT_SPRITE, GL_COORD_REPLACE, 0.0f);
    errs[5] = (GLint)glGetError();
    state(out, "after_errors");
    sgl_text(out, "errors", "%x %x %x %x %x %x replace_f %g\n", errs[0], errs[1], errs[2],
             errs[3], errs[4], errs[5], f);

    prims_close(out);
    return 0;
}
