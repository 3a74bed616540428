/*
 * Tutorial 4: blending, with a transparent teapot.
 *
 * Opaque objects are drawn first with depth writes on; then the teapot is drawn with
 * alpha 0.45, blending on and depth writes off, so the objects behind it show
 * through. Keys: 'b' toggles blending, 'a' / 'A' lower / raise the teapot's alpha,
 * Esc quits. The scene turns with a timer while the window is visible.
 */
#include <GL/glut.h>
#include <stdlib.h>

static float angle = 0.0f, alpha = 0.45f;
static int blending = 1, visible = 0;

static void init(void)
{
    GLfloat light_pos[] = { -2.0f, 3.0f, 4.0f, 0.0f };
    GLfloat spec[] = { 0.8f, 0.8f, 0.8f, 1.0f };

    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 60.0f);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / (double)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
}

static void material(float r, float g, float b, float a)
{
    GLfloat diffuse[4];
    diffuse[0] = r;
    diffuse[1] = g;
    diffuse[2] = b;
    diffuse[3] = a;
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diffuse);
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 1.5, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glRotatef(angle, 0.0f, 1.0f, 0.0f);

    /* Opaque: a torus and a cube behind the teapot. */
    glPushMatrix();
    glTranslatef(-0.8f, 0.0f, -1.5f);
    glRotatef(60.0f, 1.0f, 0.0f, 0.0f);
    material(0.9f, 0.6f, 0.1f, 1.0f);
    glutSolidTorus(0.25, 0.9, 16, 32);
    glPopMatrix();

    glPushMatrix();
    glTranslatef(1.0f, -0.2f, -1.8f);
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
    material(0.2f, 0.7f, 0.3f, 1.0f);
    glutSolidCube(1.1);
    glPopMatrix();

    /* Transparent: the teapot, last, without writing depth. */
    if (blending) {
        glEnable(GL_BLEND);
        glDepthMask(GL_FALSE);
    }
    material(0.3f, 0.5f, 1.0f, alpha);
    glutSolidTeapot(1.0);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);

    glutSwapBuffers();
}

static void timer(int value)
{
    if (visible)
        angle += 6.0f;
    glutPostRedisplay();
    glutTimerFunc(50, timer, value);
}

static void visibility(int state)
{
    visible = state == GLUT_VISIBLE;
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 'b': blending = !blending; break;
    case 'a': if (alpha > 0.1f) alpha -= 0.1f; break;
    case 'A': if (alpha < 1.0f) alpha += 0.1f; break;
    case 27: exit(0);
    }
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGBA | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutCreateWindow("Transparent teapot");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutVisibilityFunc(visibility);
    glutTimerFunc(50, timer, 0);
    glutMainLoop();
    return 0;
}
