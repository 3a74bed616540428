/*
 * tutorial_lit_cube.c - a lit, spinning cube rendered off-screen with OSMesa.
 *
 * The classic first lighting program: the cube's geometry goes into a display
 * list once, then every frame sets up the camera, rotates the model and calls the
 * list. One white directional light plus a dim coloured point light, a shiny
 * material, glColorMaterial so each face keeps its own colour, and GL_NORMALIZE
 * because the cube is scaled. Four frames of the spin are saved.
 */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include "common.h"

#define WIDTH 320
#define HEIGHT 240

static GLuint cube_list;

/* Build the cube once: six quads, each with its own normal and colour. */
static void make_cube(void)
{
    static const GLfloat n[6][3] = {
        { 0.0f, 0.0f, 1.0f }, { 0.0f, 0.0f, -1.0f }, { 0.0f, 1.0f, 0.0f },
        { 0.0f, -1.0f, 0.0f }, { 1.0f, 0.0f, 0.0f }, { -1.0f, 0.0f, 0.0f }
    };
    static const GLfloat col[6][3] = {
        { 0.9f, 0.2f, 0.2f }, { 0.2f, 0.9f, 0.2f }, { 0.2f, 0.3f, 0.9f },
        { 0.9f, 0.9f, 0.2f }, { 0.9f, 0.3f, 0.9f }, { 0.2f, 0.9f, 0.9f }
    };
    static const GLint faces[6][4] = {
        { 0, 1, 2, 3 }, { 5, 4, 7, 6 }, { 3, 2, 6, 7 },
        { 4, 5, 1, 0 }, { 1, 5, 6, 2 }, { 4, 0, 3, 7 }
    };
    GLfloat v[8][3];
    int i, j;

    v[0][0] = v[3][0] = v[4][0] = v[7][0] = -1.0f;
    v[1][0] = v[2][0] = v[5][0] = v[6][0] = 1.0f;
    v[0][1] = v[1][1] = v[4][1] = v[5][1] = -1.0f;
    v[2][1] = v[3][1] = v[6][1] = v[7][1] = 1.0f;
    v[0][2] = v[1][2] = v[2][2] = v[3][2] = 1.0f;
    v[4][2] = v[5][2] = v[6][2] = v[7][2] = -1.0f;

    cube_list = glGenLists(1);
    glNewList(cube_list, GL_COMPILE);
    glBegin(GL_QUADS);
    for (i = 0; i < 6; i++) {
        glColor3fv(col[i]);
        glNormal3fv(n[i]);
        for (j = 0; j < 4; j++)
            glVertex3fv(v[faces[i][j]]);
    }
    glEnd();
    glEndList();
}

static void init(void)
{
    GLfloat light0_pos[] = { 1.0f, 2.0f, 3.0f, 0.0f };
    GLfloat light1_pos[] = { -3.0f, -1.0f, 2.0f, 1.0f };
    GLfloat light1_col[] = { 0.3f, 0.3f, 0.6f, 1.0f };
    GLfloat white[] = { 1.0f, 1.0f, 1.0f, 1.0f };
    GLfloat ambient[] = { 0.15f, 0.15f, 0.15f, 1.0f };

    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);

    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glLightfv(GL_LIGHT0, GL_POSITION, light0_pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT1, GL_POSITION, light1_pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, light1_col);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.1f);

    glMaterialfv(GL_FRONT, GL_SPECULAR, white);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    glEnable(GL_CULL_FACE);

    make_cube();
}

static void reshape(int w, int h)
{
    double aspect = (double)w / (double)h;
    double near_plane = 1.0, far_plane = 20.0;
    double top = near_plane * tan(45.0 * 3.14159265358979 / 360.0);

    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-top * aspect, top * aspect, -top, top, near_plane, far_plane);
    glMatrixMode(GL_MODELVIEW);
}

static void display(float angle)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -6.0f);
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(angle, 0.0f, 1.0f, 0.0f);
    glRotatef(angle * 0.5f, 0.0f, 0.0f, 1.0f);
    glScalef(1.2f, 0.8f, 1.0f);
    glCallList(cube_list);
    glFinish();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx;
    unsigned char *buffer;
    int frame;
    char name[32];

    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!ctx) {
        fprintf(stderr, "OSMesaCreateContext failed\n");
        return 1;
    }
    buffer = (unsigned char *)malloc(WIDTH * HEIGHT * 4);
    if (!OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT)) {
        fprintf(stderr, "OSMesaMakeCurrent failed\n");
        return 1;
    }

    init();
    reshape(WIDTH, HEIGHT);
    for (frame = 0; frame < 4; frame++) {
        display(30.0f * (float)frame + 10.0f);
        sprintf(name, "frame%d", frame);
        sgl_image(out, name, WIDTH, HEIGHT, 4, "RGBA", WIDTH * 4, 1, buffer);
    }

    glDeleteLists(cube_list, 1);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buffer);
    return 0;
}
