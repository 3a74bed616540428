/*
 * Tutorial 2: a textured quad with a procedural texture.
 *
 * A checkerboard with a coloured gradient is computed in memory, uploaded with
 * gluBuild2DMipmaps and mapped onto a floor that recedes into the distance and a
 * quad that turns, driven by a timer. Keys: 'm' switches between mipmapped and plain
 * linear filtering, Esc quits.
 */
#include <GL/glut.h>
#include <stdlib.h>

#define TEX_SIZE 64

static GLubyte image[TEX_SIZE][TEX_SIZE][3];
static GLuint texture;
static float angle = 0.0f;
static int mipmaps = 1;

static void make_texture(void)
{
    int i, j;
    for (i = 0; i < TEX_SIZE; i++) {
        for (j = 0; j < TEX_SIZE; j++) {
            int check = ((i & 8) == 0) ^ ((j & 8) == 0);
            image[i][j][0] = (GLubyte)(check ? 255 : 4 * i);
            image[i][j][1] = (GLubyte)(check ? 255 : 4 * j);
            image[i][j][2] = (GLubyte)(check ? 255 : 128);
        }
    }
}

static void set_filter(void)
{
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                    mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
}

static void init(void)
{
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glEnable(GL_DEPTH_TEST);

    make_texture();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, TEX_SIZE, TEX_SIZE, GL_RGB,
                      GL_UNSIGNED_BYTE, image);
    set_filter();
    glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
}

static void reshape(int w, int h)
{
    glViewport(0, 0, (GLsizei)w, (GLsizei)h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60.0, (GLfloat)w / (GLfloat)h, 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    gluLookAt(0.0, 1.5, 4.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);

    /* The floor: one quad, the texture repeated eight times. */
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f); glVertex3f(-10.0f, -1.0f, 2.0f);
    glTexCoord2f(8.0f, 0.0f); glVertex3f(10.0f, -1.0f, 2.0f);
    glTexCoord2f(8.0f, 8.0f); glVertex3f(10.0f, -1.0f, -30.0f);
    glTexCoord2f(0.0f, 8.0f); glVertex3f(-10.0f, -1.0f, -30.0f);
    glEnd();

    /* The turning quad, tinted. */
    glPushMatrix();
    glRotatef(angle, 0.0f, 1.0f, 0.0f);
    glColor3f(1.0f, 0.8f, 0.6f);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f); glVertex3f(-1.0f, -0.8f, 0.0f);
    glTexCoord2f(1.0f, 0.0f); glVertex3f(1.0f, -0.8f, 0.0f);
    glTexCoord2f(1.0f, 1.0f); glVertex3f(1.0f, 1.2f, 0.0f);
    glTexCoord2f(0.0f, 1.0f); glVertex3f(-1.0f, 1.2f, 0.0f);
    glEnd();
    glPopMatrix();

    glutSwapBuffers();
}

static void timer(int value)
{
    angle += 7.5f;
    if (angle >= 360.0f)
        angle -= 360.0f;
    glutPostRedisplay();
    glutTimerFunc(40, timer, value);
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    if (key == 27)
        exit(0);
    if (key == 'm') {
        mipmaps = !mipmaps;
        set_filter();
        glutPostRedisplay();
    }
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB | GLUT_DEPTH);
    glutInitWindowSize(320, 240);
    glutCreateWindow("Procedural texture");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutTimerFunc(40, timer, 0);
    glutMainLoop();
    return 0;
}
