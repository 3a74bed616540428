/*
 * Tutorial 3: fog and depth.
 *
 * Rows of GLUT shapes recede down a corridor; the camera glides forward with the
 * clock. Keys: 'f' cycles the fog mode (GL_EXP, GL_EXP2, GL_LINEAR), '+' / '-'
 * change the density, Esc quits.
 */
#include <GL/glut.h>
#include <stdlib.h>

static GLint fog_mode = GL_EXP2;
static float density = 0.12f;
static float camera_z = 6.0f;

static void init(void)
{
    GLfloat fog_color[4] = { 0.5f, 0.55f, 0.6f, 1.0f };
    GLfloat light_pos[] = { 1.0f, 2.0f, 3.0f, 0.0f };

    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);

    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, fog_mode);
    glFogfv(GL_FOG_COLOR, fog_color);
    glFogf(GL_FOG_DENSITY, density);
    glFogf(GL_FOG_START, 2.0f);
    glFogf(GL_FOG_END, 20.0f);
    glHint(GL_FOG_HINT, GL_DONT_CARE);
    glClearColor(0.5f, 0.55f, 0.6f, 1.0f);
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (GLdouble)w / (GLdouble)h, 0.5, 60.0);
    glMatrixMode(GL_MODELVIEW);
}

static void shape(int kind)
{
    switch (kind % 4) {
    case 0: glutSolidSphere(0.6, 20, 14); break;
    case 1: glutSolidCube(1.0); break;
    case 2: glutSolidTorus(0.2, 0.5, 12, 24); break;
    default:
        glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
        glutSolidCone(0.5, 1.2, 16, 4);
        break;
    }
}

static void display(void)
{
    int i;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 1.0, camera_z, 0.0, 0.0, camera_z - 10.0, 0.0, 1.0, 0.0);

    for (i = 0; i < 12; i++) {
        float z = -3.0f * (float)i;
        glPushMatrix();
        glTranslatef(-1.6f, 0.0f, z);
        glColor3f(0.9f, 0.3f + 0.05f * (float)i, 0.2f);
        shape(i);
        glPopMatrix();

        glPushMatrix();
        glTranslatef(1.6f, 0.0f, z - 1.5f);
        glColor3f(0.2f, 0.4f, 0.9f - 0.05f * (float)i);
        shape(i + 2);
        glPopMatrix();
    }

    /* The floor. */
    glColor3f(0.3f, 0.6f, 0.3f);
    glNormal3f(0.0f, 1.0f, 0.0f);
    glBegin(GL_QUADS);
    glVertex3f(-4.0f, -0.8f, 8.0f);
    glVertex3f(4.0f, -0.8f, 8.0f);
    glVertex3f(4.0f, -0.8f, -40.0f);
    glVertex3f(-4.0f, -0.8f, -40.0f);
    glEnd();

    glutSwapBuffers();
}

static void idle(void)
{
    camera_z = 6.0f - 0.002f * (float)glutGet(GLUT_ELAPSED_TIME);
    glutPostRedisplay();
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 'f':
        fog_mode = fog_mode == GL_EXP ? GL_EXP2 : fog_mode == GL_EXP2 ? GL_LINEAR : GL_EXP;
        glFogi(GL_FOG_MODE, fog_mode);
        break;
    case '+':
        density *= 1.5f;
        glFogf(GL_FOG_DENSITY, density);
        break;
    case '-':
        density /= 1.5f;
        glFogf(GL_FOG_DENSITY, density);
        break;
    case 27:
        exit(0);
    }
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutCreateWindow("Fog");
    init();
    glutReshapeFunc(reshape);
    glutDisplayFunc(display);
    glutKeyboardFunc(keyboard);
    glutIdleFunc(idle);
    glutMainLoop();
    return 0;
}
