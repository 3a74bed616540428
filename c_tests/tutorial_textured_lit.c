/*
 * tutorial_textured_lit.c - textures and lighting together, with the attribute stack.
 *
 * A checkerboard texture is generated in code and mipmapped by the driver
 * (GL_GENERATE_MIPMAP). The floor and a crate are textured with GL_MODULATE so the
 * lighting shows through; a plain lit "gem" (an octahedron) sits on the crate.
 * Every object saves and restores the state it changes with glPushAttrib /
 * glPopAttrib, the way tutorials teach it.
 */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "common.h"

#define WIDTH 320
#define HEIGHT 320
#define CHECK_SIZE 64

static GLubyte checker[CHECK_SIZE][CHECK_SIZE][4];
static GLuint floor_tex, crate_tex;

static void make_checker(void)
{
    int i, j;
    for (i = 0; i < CHECK_SIZE; i++) {
        for (j = 0; j < CHECK_SIZE; j++) {
            int c = (((i & 0x8) == 0) ^ ((j & 0x8) == 0)) * 255;
            checker[i][j][0] = (GLubyte)c;
            checker[i][j][1] = (GLubyte)c;
            checker[i][j][2] = (GLubyte)(c / 2 + 64);
            checker[i][j][3] = 255;
        }
    }
}

static GLuint make_texture(int crate)
{
    GLuint tex;
    static GLubyte img[CHECK_SIZE][CHECK_SIZE][4];
    int i, j;

    memcpy(img, checker, sizeof(img));
    if (crate) {
        /* wooden planks: brown stripes with dark borders */
        for (i = 0; i < CHECK_SIZE; i++) {
            for (j = 0; j < CHECK_SIZE; j++) {
                int border = i < 4 || i >= CHECK_SIZE - 4 || j < 4 || j >= CHECK_SIZE - 4;
                int plank = (i / 10) & 1;
                img[i][j][0] = (GLubyte)(border ? 70 : (plank ? 170 : 150));
                img[i][j][1] = (GLubyte)(border ? 40 : (plank ? 110 : 95));
                img[i][j][2] = (GLubyte)(border ? 20 : 50);
            }
        }
    }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, CHECK_SIZE, CHECK_SIZE, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, img);
    return tex;
}

static void draw_floor(void)
{
    GLfloat grey[] = { 0.8f, 0.8f, 0.8f, 1.0f };

    glPushAttrib(GL_ENABLE_BIT | GL_TEXTURE_BIT | GL_LIGHTING_BIT);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, floor_tex);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
    glBegin(GL_QUADS);
    glNormal3f(0.0f, 1.0f, 0.0f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-8.0f, 0.0f, 8.0f);
    glTexCoord2f(6.0f, 0.0f);
    glVertex3f(8.0f, 0.0f, 8.0f);
    glTexCoord2f(6.0f, 6.0f);
    glVertex3f(8.0f, 0.0f, -8.0f);
    glTexCoord2f(0.0f, 6.0f);
    glVertex3f(-8.0f, 0.0f, -8.0f);
    glEnd();
    glPopAttrib();
}

static void draw_crate(void)
{
    static const GLfloat n[6][3] = { { 0, 0, 1 }, { 0, 0, -1 }, { 0, 1, 0 },
                                     { 0, -1, 0 }, { 1, 0, 0 }, { -1, 0, 0 } };
    static const GLfloat tc[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
    int f, k;

    glPushAttrib(GL_ENABLE_BIT | GL_TEXTURE_BIT | GL_CURRENT_BIT);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_COLOR_MATERIAL);
    glBindTexture(GL_TEXTURE_2D, crate_tex);
    glColor3f(1.0f, 1.0f, 1.0f);
    glPushMatrix();
    glTranslatef(0.0f, 1.0f, 0.0f);
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
    glBegin(GL_QUADS);
    for (f = 0; f < 6; f++) {
        /* two axes spanning the face */
        GLfloat a[3], b[3];
        a[0] = n[f][1] != 0.0f ? 1.0f : -n[f][2];
        a[1] = 0.0f;
        a[2] = n[f][1] != 0.0f ? 0.0f : n[f][0];
        b[0] = n[f][1] * a[2] - n[f][2] * a[1];
        b[1] = n[f][2] * a[0] - n[f][0] * a[2];
        b[2] = n[f][0] * a[1] - n[f][1] * a[0];
        glNormal3fv(n[f]);
        for (k = 0; k < 4; k++) {
            float s = tc[k][0] * 2.0f - 1.0f, t = tc[k][1] * 2.0f - 1.0f;
            glTexCoord2fv(tc[k]);
            glVertex3f(n[f][0] + s * a[0] + t * b[0], n[f][1] + s * a[1] + t * b[1],
                       n[f][2] + s * a[2] + t * b[2]);
        }
    }
    glEnd();
    glPopMatrix();
    glPopAttrib();
}

static void draw_gem(void)
{
    GLfloat ruby[] = { 0.8f, 0.1f, 0.2f, 1.0f };
    GLfloat white[] = { 1.0f, 1.0f, 1.0f, 1.0f };
    static const GLfloat p[6][3] = { { 1, 0, 0 }, { 0, 0, 1 }, { -1, 0, 0 },
                                     { 0, 0, -1 }, { 0, 1.4f, 0 }, { 0, -1.4f, 0 } };
    int i;

    glPushAttrib(GL_LIGHTING_BIT);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, ruby);
    glMaterialfv(GL_FRONT, GL_SPECULAR, white);
    glMaterialf(GL_FRONT, GL_SHININESS, 80.0f);
    glPushMatrix();
    glTranslatef(0.0f, 2.9f, 0.0f);
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
    glScalef(0.6f, 0.6f, 0.6f);
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 8; i++) {
        const GLfloat *a = p[i % 4], *b = p[(i + 1) % 4], *c = p[i < 4 ? 4 : 5];
        GLfloat u[3], v[3], nrm[3];
        int k;
        for (k = 0; k < 3; k++) {
            u[k] = b[k] - a[k];
            v[k] = c[k] - a[k];
        }
        nrm[0] = u[1] * v[2] - u[2] * v[1];
        nrm[1] = u[2] * v[0] - u[0] * v[2];
        nrm[2] = u[0] * v[1] - u[1] * v[0];
        if (i >= 4) {
            nrm[0] = -nrm[0];
            nrm[1] = -nrm[1];
            nrm[2] = -nrm[2];
            glNormal3fv(nrm);
            glVertex3fv(a);
            glVertex3fv(c);
            glVertex3fv(b);
        } else {
            glNormal3fv(nrm);
            glVertex3fv(a);
            glVertex3fv(b);
            glVertex3fv(c);
        }
    }
    glEnd();
    glPopMatrix();
    glPopAttrib();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    GLfloat light_pos[] = { 3.0f, 6.0f, 4.0f, 1.0f };
    GLfloat light_amb[] = { 0.25f, 0.25f, 0.25f, 1.0f };
    OSMesaContext ctx;
    void *buffer;

    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    buffer = malloc(WIDTH * HEIGHT * 4);
    if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {
        printf("OSMesa setup failed!\n");
        return 1;
    }

    make_checker();
    floor_tex = make_texture(0);
    crate_tex = make_texture(1);

    glClearColor(0.3f, 0.4f, 0.6f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glEnable(GL_CULL_FACE);
    glLightfv(GL_LIGHT0, GL_AMBIENT, light_amb);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.5, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -2.0f, -7.0f);
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-20.0f, 0.0f, 1.0f, 0.0f);
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    draw_floor();
    draw_crate();
    draw_gem();
    glFinish();
    sgl_image(out, "scene", WIDTH, HEIGHT, 4, "RGBA", WIDTH * 4, 1, buffer);

    /* the attribute stack left everything as it was */
    sgl_text(out, "state", "tex2d %d colormat %d light %d err 0x%x\n",
             glIsEnabled(GL_TEXTURE_2D), glIsEnabled(GL_COLOR_MATERIAL),
             glIsEnabled(GL_LIGHTING), glGetError());

    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buffer);
    return 0;
}
