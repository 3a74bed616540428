/*
 * Tutorial 1: a spinning, lit cube.
 *
 * Keys: arrow keys tilt and turn the cube, '+' / '-' move it closer / farther,
 * 'l' toggles lighting, 's' stops / restarts the spin, Esc quits.
 */
#include <GL/glut.h>
#include <stdlib.h>

static float xrot = 20.0f, yrot = 30.0f, distance = 5.0f;
static int lighting = 1, spinning = 1, last_time = 0;

static void init(void)
{
    GLfloat light_pos[] = { 2.0f, 3.0f, 4.0f, 0.0f };
    GLfloat white[] = { 1.0f, 1.0f, 1.0f, 1.0f };

    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glShadeModel(GL_SMOOTH);

    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glMaterialfv(GL_FRONT, GL_SPECULAR, white);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
}

static void reshape(int w, int h)
{
    if (h == 0)
        h = 1;
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 1.0, 100.0);
    glMatrixMode(GL_MODELVIEW);
}

static void face(float nx, float ny, float nz, float r, float g, float b)
{
    /* A unit face perpendicular to the normal, wound counter-clockwise. */
    float ux = ny, uy = nz, uz = nx;            /* one axis in the face */
    float vx = ny * uz - nz * uy, vy = nz * ux - nx * uz, vz = nx * uy - ny * ux;
    glColor3f(r, g, b);
    glNormal3f(nx, ny, nz);
    glVertex3f(nx - ux - vx, ny - uy - vy, nz - uz - vz);
    glVertex3f(nx + ux - vx, ny + uy - vy, nz + uz - vz);
    glVertex3f(nx + ux + vx, ny + uy + vy, nz + uz + vz);
    glVertex3f(nx - ux + vx, ny - uy + vy, nz - uz + vz);
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -distance);
    glRotatef(xrot, 1.0f, 0.0f, 0.0f);
    glRotatef(yrot, 0.0f, 1.0f, 0.0f);

    glBegin(GL_QUADS);
    face(1, 0, 0, 0.9f, 0.2f, 0.2f);
    face(-1, 0, 0, 0.2f, 0.9f, 0.2f);
    face(0, 1, 0, 0.2f, 0.2f, 0.9f);
    face(0, -1, 0, 0.9f, 0.9f, 0.2f);
    face(0, 0, 1, 0.9f, 0.2f, 0.9f);
    face(0, 0, -1, 0.2f, 0.9f, 0.9f);
    glEnd();

    glutSwapBuffers();
}

static void idle(void)
{
    int now = glutGet(GLUT_ELAPSED_TIME);
    if (spinning)
        yrot += (now - last_time) * 0.09f;   /* 90 degrees per second */
    last_time = now;
    glutPostRedisplay();
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 27:
        exit(0);
    case '+':
        distance -= 0.5f;
        break;
    case '-':
        distance += 0.5f;
        break;
    case 'l':
        lighting = !lighting;
        if (lighting)
            glEnable(GL_LIGHTING);
        else
            glDisable(GL_LIGHTING);
        break;
    case 's':
        spinning = !spinning;
        break;
    }
    glutPostRedisplay();
}

static void special(int key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case GLUT_KEY_UP:    xrot -= 10.0f; break;
    case GLUT_KEY_DOWN:  xrot += 10.0f; break;
    case GLUT_KEY_LEFT:  yrot -= 10.0f; break;
    case GLUT_KEY_RIGHT: yrot += 10.0f; break;
    }
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutInitWindowPosition(100, 100);
    glutCreateWindow("Spinning cube");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutIdleFunc(idle);
    glutKeyboardFunc(keyboard);
    glutSpecialFunc(special);
    glutMainLoop();
    return 0;
}
