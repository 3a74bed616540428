/*
 * Tutorial 10: the accumulation buffer (GLUT_ACCUM). A square and a triangle are
 * drawn several times along their motion and averaged with glAccum into one motion
 * blurred frame; 'j' changes the number of passes (8 or 3), 'r' toggles a final
 * GL_RETURN scaled by 1.25 against 1, Esc quits.
 */
#include <GL/glut.h>
#include <stdlib.h>

static int passes = 8, bright = 0;
static float t = 0.0f;

static void scene(float dt)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glPushMatrix();
    glTranslatef(-0.6f + 0.25f * (t + dt), 0.2f, 0.0f);
    glRotatef(40.0f * (t + dt), 0.0f, 0.0f, 1.0f);
    glColor3f(1.0f, 0.7f, 0.2f);
    glRectf(-0.2f, -0.2f, 0.2f, 0.2f);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.4f, -0.3f + 0.2f * (t + dt), 0.0f);
    glColor3f(0.3f, 0.6f, 1.0f);
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.25f, -0.2f);
    glVertex2f(0.25f, -0.2f);
    glVertex2f(0.0f, 0.25f);
    glEnd();
    glPopMatrix();
}

static void display(void)
{
    int i;
    glClear(GL_ACCUM_BUFFER_BIT);
    for (i = 0; i < passes; i++) {
        scene(0.6f * (float)i / (float)passes);
        glAccum(GL_ACCUM, 1.0f / (float)passes);
    }
    glAccum(GL_RETURN, bright ? 1.25f : 1.0f);
    glutSwapBuffers();
    t += 0.5f;
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    if (key == 'j')
        passes = passes == 8 ? 3 : 8;
    else if (key == 'r')
        bright = !bright;
    else if (key == 27)
        exit(0);
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_ACCUM);
    glutInitWindowSize(320, 240);
    glutCreateWindow("accum");
    glClearColor(0.1f, 0.1f, 0.15f, 0.0f);
    glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
    glutDisplayFunc(display);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
