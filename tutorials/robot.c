/*
 * Tutorial 5: a robot arm built with the matrix stack.
 *
 * Each part is placed relative to its parent: push the matrix, move to the joint,
 * rotate, draw, and keep going down the hierarchy; pop to return to the parent.
 * Keys: 's' / 'S' turn the shoulder, 'e' / 'E' bend the elbow, 'f' / 'F' open /
 * close the fingers, 'r' turns the base, Esc quits.
 */
#include <GL/glut.h>
#include <stdlib.h>

static int shoulder = 20, elbow = 40, fingers = 20, base = 30;
static GLUquadric *quadric;

static void init(void)
{
    GLfloat light_pos[] = { 3.0f, 5.0f, 4.0f, 0.0f };
    glClearColor(0.9f, 0.9f, 0.85f, 1.0f);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    quadric = gluNewQuadric();
    gluQuadricNormals(quadric, GLU_SMOOTH);
}

static void box(float length, float width)
{
    /* A part of the given length along +x from the joint. */
    glPushMatrix();
    glTranslatef(length / 2.0f, 0.0f, 0.0f);
    glScalef(length, width, width);
    glutSolidCube(1.0);
    glPopMatrix();
}

static void joint(void)
{
    glColor3f(0.3f, 0.3f, 0.35f);
    gluSphere(quadric, 0.3, 16, 12);
}

static void finger(float side)
{
    glPushMatrix();
    glTranslatef(0.0f, 0.0f, side * 0.15f);
    glRotatef(side * (float)fingers, 0.0f, 1.0f, 0.0f);
    glColor3f(0.8f, 0.2f, 0.2f);
    box(0.6f, 0.1f);
    glPopMatrix();
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 2.0, 8.0, 0.5, 0.5, 0.0, 0.0, 1.0, 0.0);

    /* The base: a cylinder standing on the floor, capped by a disk. */
    glPushMatrix();
    glRotatef((GLfloat)base, 0.0f, 1.0f, 0.0f);
    glPushMatrix();
    glTranslatef(0.0f, -1.5f, 0.0f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glColor3f(0.2f, 0.4f, 0.7f);
    gluCylinder(quadric, 0.8, 0.5, 1.2, 24, 2);
    glTranslatef(0.0f, 0.0f, 1.2f);
    gluDisk(quadric, 0.0, 0.5, 24, 1);
    glPopMatrix();

    /* Upper arm. */
    glTranslatef(0.0f, -0.3f, 0.0f);
    joint();
    glRotatef((GLfloat)shoulder, 0.0f, 0.0f, 1.0f);
    glColor3f(0.9f, 0.6f, 0.1f);
    box(2.0f, 0.4f);

    /* Forearm. */
    glTranslatef(2.0f, 0.0f, 0.0f);
    joint();
    glRotatef((GLfloat)elbow, 0.0f, 0.0f, 1.0f);
    glColor3f(0.9f, 0.8f, 0.2f);
    box(1.6f, 0.3f);

    /* Hand and two fingers. */
    glTranslatef(1.6f, 0.0f, 0.0f);
    finger(1.0f);
    finger(-1.0f);
    glPopMatrix();

    glutSwapBuffers();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (GLfloat)w / (GLfloat)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 's': shoulder = (shoulder + 5) % 360; break;
    case 'S': shoulder = (shoulder - 5) % 360; break;
    case 'e': elbow = (elbow + 5) % 360; break;
    case 'E': elbow = (elbow - 5) % 360; break;
    case 'f': if (fingers < 45) fingers += 5; break;
    case 'F': if (fingers > 0) fingers -= 5; break;
    case 'r': base = (base + 15) % 360; break;
    case 27:
        gluDeleteQuadric(quadric);
        exit(0);
    }
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutInitWindowPosition(100, 100);
    glutCreateWindow(argv[0]);
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
