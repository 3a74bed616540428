/*
 * tutorial_fog_terrain.c - a fogged height-field terrain with a wireframe overlay.
 *
 * The terrain is a grid of heights from a few sines and cosines, drawn as one
 * triangle strip per row with a colour by height and lighting from computed
 * normals. Linear fog fades the far hills into the sky colour. The wireframe is
 * drawn on top with glPolygonMode(GL_LINE); the filled pass is pushed back with
 * glPolygonOffset so the lines do not stitch. A second picture uses GL_EXP2 fog.
 */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include "common.h"

#define WIDTH 400
#define HEIGHT 300
#define GRID 48

static float height[GRID + 1][GRID + 1];
static float normal[GRID + 1][GRID + 1][3];

static float terrain_height(float x, float z)
{
    return 0.6f * sinf(x * 0.35f) * cosf(z * 0.3f) + 0.3f * sinf(x * 0.9f + z * 0.7f) +
           0.15f * cosf(z * 1.7f);
}

static void build_terrain(void)
{
    int i, j;
    for (i = 0; i <= GRID; i++)
        for (j = 0; j <= GRID; j++)
            height[i][j] = terrain_height((float)j - GRID / 2, (float)i - GRID / 2);
    for (i = 0; i <= GRID; i++) {
        for (j = 0; j <= GRID; j++) {
            float hl = height[i][j > 0 ? j - 1 : j], hr = height[i][j < GRID ? j + 1 : j];
            float hd = height[i > 0 ? i - 1 : i][j], hu = height[i < GRID ? i + 1 : i][j];
            float nx = hl - hr, ny = 2.0f, nz = hd - hu;
            float len = sqrtf(nx * nx + ny * ny + nz * nz);
            normal[i][j][0] = nx / len;
            normal[i][j][1] = ny / len;
            normal[i][j][2] = nz / len;
        }
    }
}

static void terrain_color(float h)
{
    if (h < -0.3f)
        glColor3f(0.2f, 0.4f, 0.8f);
    else if (h < 0.3f)
        glColor3f(0.3f + 0.5f * (h + 0.3f), 0.7f, 0.25f);
    else
        glColor3f(0.6f + 0.4f * (h - 0.3f), 0.55f, 0.4f);
}

static void draw_terrain(int colored)
{
    int i, j;
    for (i = 0; i < GRID; i++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (j = 0; j <= GRID; j++) {
            if (colored)
                terrain_color(height[i][j]);
            glNormal3fv(normal[i][j]);
            glVertex3f((float)j - GRID / 2, height[i][j], (float)i - GRID / 2);
            if (colored)
                terrain_color(height[i + 1][j]);
            glNormal3fv(normal[i + 1][j]);
            glVertex3f((float)j - GRID / 2, height[i + 1][j], (float)i + 1 - GRID / 2);
        }
        glEnd();
    }
}

static void setup_view(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 80.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(18.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, -3.0f, -8.0f);
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
}

static void render(GLenum fog_mode)
{
    GLfloat sky[] = { 0.7f, 0.75f, 0.85f, 1.0f };
    GLfloat sun[] = { 0.4f, 1.0f, 0.3f, 0.0f };

    glClearColor(sky[0], sky[1], sky[2], sky[3]);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    setup_view();
    glLightfv(GL_LIGHT0, GL_POSITION, sun);

    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, fog_mode);
    glFogfv(GL_FOG_COLOR, sky);
    glFogf(GL_FOG_START, 5.0f);
    glFogf(GL_FOG_END, 40.0f);
    glFogf(GL_FOG_DENSITY, 0.05f);
    glHint(GL_FOG_HINT, GL_NICEST);

    /* filled terrain, pushed back a little */
    glEnable(GL_LIGHTING);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    draw_terrain(1);
    glDisable(GL_POLYGON_OFFSET_FILL);

    /* wireframe overlay */
    glDisable(GL_LIGHTING);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(0.1f, 0.15f, 0.1f);
    draw_terrain(0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_FOG);
    glFinish();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *pixels = malloc(WIDTH * HEIGHT * 4);

    if (!ctx || !pixels || !OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {
        fprintf(stderr, "could not set up OSMesa\n");
        return 1;
    }
    build_terrain();
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);

    render(GL_LINEAR);
    sgl_image(out, "linear_fog", WIDTH, HEIGHT, 4, "RGBA", WIDTH * 4, 1, pixels);
    render(GL_EXP2);
    sgl_image(out, "exp2_fog", WIDTH, HEIGHT, 4, "RGBA", WIDTH * 4, 1, pixels);

    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(pixels);
    return 0;
}
