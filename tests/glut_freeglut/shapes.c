/*
 * Every GLUT shape drawn lit (a few in fog, two through a display list), one scene
 * at a time, each scene's RGBA pixels appended to the file named by argv[1].
 * tests/glut_freeglut.rs builds this once against the system freeglut (GLX on
 * Mesa's llvmpipe, under Xvfb) and once against softglut on softgl, and compares.
 */
#include <GL/freeglut.h>
#include <stdio.h>
#include <stdlib.h>

#define SIZE 160
#define SCENES 30

static const char *out_path;
static GLuint list;

static void shape(int i)
{
    double at[3] = {0.1, -0.2, 0.05};
    switch (i) {
    case 0: glutSolidSphere(1.2, 20, 16); break;
    case 1: glutWireSphere(1.2, 11, 7); break;
    case 2: glutSolidCone(1.0, 2.0, 18, 9); break;
    case 3: glutWireCone(1.0, 2.0, 12, 4); break;
    case 4: glutSolidCylinder(0.8, 1.5, 16, 5); break;
    case 5: glutWireCylinder(0.8, 1.5, 10, 3); break;
    case 6: glutSolidTorus(0.3, 1.0, 12, 24); break;
    case 7: glutWireTorus(0.3, 1.0, 8, 16); break;
    case 8: glutSolidCube(1.5); break;
    case 9: glutWireCube(1.2); break;
    case 10: glutSolidDodecahedron(); break;
    case 11: glutWireDodecahedron(); break;
    case 12: glutSolidIcosahedron(); break;
    case 13: glutWireIcosahedron(); break;
    case 14: glutSolidOctahedron(); break;
    case 15: glutSolidTetrahedron(); break;
    case 16: glutWireTetrahedron(); break;
    case 17: glutSolidRhombicDodecahedron(); break;
    case 18: glutWireRhombicDodecahedron(); break;
    case 19: glutSolidTeapot(1.0); break;
    case 20: glutWireTeapot(1.0); break;
    /* After size 1.0 freeglut moves the vertices but keeps the first normals. */
    case 21: glutSolidTeapot(0.7); break;
    case 22: glutSolidTeacup(2.0); break;
    case 23: glutWireTeacup(2.0); break;
    case 24: glutSolidTeaspoon(3.0); break;
    case 25: glutSolidSierpinskiSponge(3, at, 1.4); break;
    case 26: glutWireSierpinskiSponge(2, at, 1.4); break;
    case 27: case 28: /* fog */
        glTranslatef(-0.8f, 0, 0); glutSolidSphere(0.8, 16, 12);
        glTranslatef(1.6f, 0, -1.5f); glutSolidCone(0.6, 1.5, 14, 6);
        break;
    case 29: glCallList(list); break;
    }
}

static void display(void)
{
    static unsigned char px[SIZE * SIZE * 4];
    float light[4] = {2, 3, 4, 0}, spec[4] = {1, 1, 1, 1};
    FILE *f = fopen(out_path, "wb");
    int i;
    if (!f) { perror(out_path); exit(1); }
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glutSolidTeapot(0.8);
    glTranslatef(0, 0.9f, 0);
    glutSolidCylinder(0.2, 0.5, 9, 2);
    glEndList();
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 30);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 3);
    glFogf(GL_FOG_END, 8);
    for (i = 0; i < SCENES; i++) {
        glClearColor(0.1f, 0.1f, 0.1f, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        if (i >= 27 && i <= 28) glEnable(GL_FOG); else glDisable(GL_FOG);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-0.6, 0.6, -0.6, 0.6, 2, 20);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glLightfv(GL_LIGHT0, GL_POSITION, light);
        glTranslatef(0, 0, i == 28 ? -6.0f : -5.0f);
        glRotatef(20.0f + 7 * (i % 3), 1, 0, 0);
        glRotatef(30.0f + 11 * i, 0, 1, 0);
        shape(i);
        glFinish();
        glReadPixels(0, 0, SIZE, SIZE, GL_RGBA, GL_UNSIGNED_BYTE, px);
        fwrite(px, 1, sizeof px, f);
    }
    fclose(f);
    exit(glGetError() == GL_NO_ERROR ? 0 : 2);
}

int main(int argc, char **argv)
{
    if (argc < 2) return 1;
    out_path = argv[1];
    glutInit(&argc, argv);
    /* With GLUT_STENCIL freeglut's GLX visual has softglut's 24-bit depth and 8-bit
     * stencil; GLUT_DEPTH alone picks a 32-bit depth buffer, under which an edge drawn
     * twice (the wire solids') resolves its depth ties differently at a few pixels. */
    glutInitDisplayMode(GLUT_RGBA | GLUT_DEPTH | GLUT_STENCIL | GLUT_SINGLE);
    glutInitWindowSize(SIZE, SIZE);
    glutCreateWindow("shapes");
    glutDisplayFunc(display);
    glutMainLoop();
    return 0;
}
